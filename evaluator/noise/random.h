#pragma once

#include <cstdint>
#include <random>

namespace slamsweep::evaluator {

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

/// Standard normal sample (mean 0, variance 1) by the Box-Muller transform. Always consumes
/// exactly two engine draws, so the stream position does not depend on the values drawn.
/// Bit-identical wherever std::log/std::sqrt/std::cos are (glibc on any x86-64 or arm64).
double StandardNormal(RandomEngine& engine);

}  // namespace slamsweep::evaluator
