#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline matrix {

/// Share `index` (1-based) of `count` shares: `--shard 2/4`.
struct Shard {
  std::size_t index = 1;
  std::size_t count = 1;
};

/// Parses "I/N" with 1 <= I <= N; anything else is an InputError naming `option` and the expected form.
Shard ParseShard(std::string_view text, std::string_view option = "--shard");

/// The runs of `shard`, in their original order. A run belongs to share Fnv1a64(run_id) % count + 1,
/// so every run lands in exactly one share, and adding runs to a sweep never moves existing runs
/// between shares (their finished results stay where they are).
std::vector<RunSpec> SelectShard(std::vector<RunSpec> runs, std::size_t index, std::size_t count);
inline std::vector<RunSpec> SelectShard(std::vector<RunSpec> runs, const Shard& shard) {
  return SelectShard(std::move(runs), shard.index, shard.count);
}

}  // namespace slamsweep::orchestrator::inline matrix
