#pragma once

#include <cstdint>
#include <string_view>

namespace slamsweep::orchestrator::inline run {

/// 64-bit FNV-1a of `bytes`: simple, specified bit for bit, and the same on every machine, which
/// std::hash is not. Names runs, picks shards and signs builds, so it must never change.
std::uint64_t Fnv1a64(std::string_view bytes);

}  // namespace slamsweep::orchestrator::inline run
