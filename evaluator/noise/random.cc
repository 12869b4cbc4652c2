#include "evaluator/noise/random.h"

#include <cmath>
#include <numbers>

namespace slamsweep::evaluator::inline noise {
namespace {

// SplitMix64 finaliser (Steele, Lea, Flood 2014): a bijection on 64-bit words with full
// avalanche, the usual way to turn counters into independent-looking seeds.
std::uint64_t Mix64(std::uint64_t value) {
  value = (value ^ (value >> 30)) * 0xbf58476d1ce4e5b9ULL;
  value = (value ^ (value >> 27)) * 0x94d049bb133111ebULL;
  return value ^ (value >> 31);
}

constexpr std::uint64_t kGoldenGamma = 0x9e3779b97f4a7c15ULL;

}  // namespace

std::uint64_t DeriveSeed(std::uint64_t base_seed, std::uint64_t iteration) {
  // base + gamma * (iteration + 1) is distinct for distinct iterations (gamma is odd), and
  // Mix64 is a bijection, so distinct iterations can never share a seed.
  return Mix64(base_seed + kGoldenGamma * (iteration + 1));
}

double UniformUnit(RandomEngine& engine) { return static_cast<double>(engine() >> 11) * 0x1.0p-53; }

double UniformBetween(RandomEngine& engine, double low, double high) {
  return low + (high - low) * UniformUnit(engine);
}

std::uint64_t UniformIndex(RandomEngine& engine, std::uint64_t count) {
  if (count <= 1) return 0;
  // Draws below 2^64 mod count would make the low residues more likely; skip them.
  const std::uint64_t threshold = (0 - count) % count;
  while (true) {
    const std::uint64_t draw = engine();
    if (draw >= threshold) return draw % count;
  }
}

UniformIndexSampler::UniformIndexSampler(std::uint64_t count)
    : count_(count),
      threshold_(count > 1 ? (0 - count) % count : 0),
      // ceil(2^128 / count); unused for count <= 1.
      multiplier_(count > 1 ? ~static_cast<Uint128>(0) / count + 1 : 0) {}

double StandardNormal(RandomEngine& engine) {
  // 1 - U is in (0, 1], so the logarithm is always finite.
  const double radius_source = 1.0 - UniformUnit(engine);
  const double angle_source = UniformUnit(engine);
  return std::sqrt(-2.0 * std::log(radius_source)) * std::cos(2.0 * std::numbers::pi * angle_source);
}

}  // namespace slamsweep::evaluator::inline noise
