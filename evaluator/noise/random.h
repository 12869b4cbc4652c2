#pragma once

#include <cstdint>
#include <random>

namespace slamsweep::evaluator::inline noise {

/// Random numbers that are the same on every machine for the same seed.
///
/// std::mt19937_64 is specified bit for bit by the standard, but the std distributions
/// (uniform_real_distribution, normal_distribution, ...) are implementation-defined, so a
/// sweep recorded with libstdc++ could not be replayed with libc++. Every sampler below is a
/// fixed transform of the engine's raw output instead.
using RandomEngine = std::mt19937_64;

/// The seed of iteration `iteration` of a sweep whose base seed is `base_seed`.
/// Distinct iterations of one base seed always get distinct seeds (the mixing step is a
/// bijection), and neighbouring iterations get unrelated streams, which consecutive raw seeds
/// would not guarantee for a Mersenne Twister.
std::uint64_t DeriveSeed(std::uint64_t base_seed, std::uint64_t iteration);

/// Uniform in [0, 1): the top 53 bits of one engine draw, so every value is exact.
double UniformUnit(RandomEngine& engine);

/// Uniform in [low, high).
double UniformBetween(RandomEngine& engine, double low, double high);

/// Uniform integer in [0, count), unbiased (modulo with rejection); `count` must be > 0.
std::uint64_t UniformIndex(RandomEngine& engine, std::uint64_t count);

// GCC's 128-bit integer (the remainder below); __extension__ keeps -Wpedantic quiet about it.
__extension__ typedef unsigned __int128 Uint128;

/// UniformIndex for one count drawn many times (the bootstrap's inner loop): the same values from the same
/// engine state, with the rejection threshold computed once and the remainder by multiplication (Lemire's
/// exact "fastmod") instead of two 64-bit divisions per draw.
class UniformIndexSampler {
 public:
  explicit UniformIndexSampler(std::uint64_t count);
  /// value % count by the sampler's multiplication (tests).
  static std::uint64_t RemainderForTesting(std::uint64_t count, std::uint64_t value) {
    return UniformIndexSampler(count).Remainder(value);
  }
  std::uint64_t operator()(RandomEngine& engine) const {
    if (count_ <= 1) return 0;
    while (true) {
      const std::uint64_t draw = engine();
      if (draw >= threshold_) return Remainder(draw);
    }
  }

 private:
  std::uint64_t Remainder(std::uint64_t value) const {
    const Uint128 low = multiplier_ * value;
    const Uint128 top = static_cast<Uint128>(static_cast<std::uint64_t>(low >> 64)) * count_;
    const Uint128 bottom = (static_cast<Uint128>(static_cast<std::uint64_t>(low)) * count_) >> 64;
    return static_cast<std::uint64_t>((top + bottom) >> 64);
  }
  std::uint64_t count_;
  std::uint64_t threshold_;
  Uint128 multiplier_;
};

/// Standard normal sample (mean 0, variance 1) by the Box-Muller transform. Always consumes
/// exactly two engine draws, so the stream position does not depend on the values drawn.
/// Bit-identical wherever std::log/std::sqrt/std::cos are (glibc on any x86-64 or arm64).
double StandardNormal(RandomEngine& engine);

}  // namespace slamsweep::evaluator::inline noise
