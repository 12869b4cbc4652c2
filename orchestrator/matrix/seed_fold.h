#pragma once

#include <cstdint>

namespace slamsweep::orchestrator::inline matrix {

/// A run's 64-bit seed for a program that takes a 32-bit one (the `{seed32}` placeholder): the two
/// halves XORed, so every bit of the seed counts. A result is reproduced from its recorded seed
/// through this fold, so it must never change (orchestrator/DESIGN.md, "Seeds").
constexpr std::uint32_t Seed32(std::uint64_t seed) { return static_cast<std::uint32_t>(seed ^ (seed >> 32)); }

/// For a program that reads its seed as a non-negative int and treats a negative one as "seed from
/// the clock" (MRPT's RANDOM_SEED): Seed32 without its top bit.
constexpr std::int32_t Seed31(std::uint64_t seed) { return static_cast<std::int32_t>(Seed32(seed) & 0x7fffffffU); }

}  // namespace slamsweep::orchestrator::inline matrix
