#pragma once

#include <cstdint>
#include <vector>

#include "evaluator/core/input_error.h"
#include "orchestrator/config/sweep_config.h"
#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline matrix {

/// Every run of a sweep, in a deterministic order: for each algorithm (as written), each combination
/// of its parameter lists (cartesian product, first parameter varying slowest), each sequence, each
/// noise setting and each iteration — minus the cells an `exclude` matches — then the `include` cells
/// in the order written (an include without noise adds every noise setting; its parameters replace
/// those of every combination). A cell that appears twice is kept once. Run ids per MakeRunId, seeds
/// per SeedForRun. Throws InputError when the product exceeds 1,000,000 runs, and on a run id collision
/// (two different runs, one id).
std::vector<RunSpec> ExpandMatrix(const SweepConfig& config);

/// A sweep with more runs than its reader accepts (the service's runs-per-sweep limit; HTTP 413).
class MatrixTooLargeError : public evaluator::InputError {
 public:
  using evaluator::InputError::InputError;
};

/// ExpandMatrix for a reader that accepts at most `max_runs` runs: throws MatrixTooLargeError, without
/// building the runs, when the product before exclusions exceeds 16 x max_runs (a hostile "iterations:
/// 1000000" costs nothing), and after building them when more than `max_runs` remain.
std::vector<RunSpec> ExpandMatrix(const SweepConfig& config, std::uint64_t max_runs);

/// The seed of a run under `policy` (see sweep_config.h); `spec` must hold everything but seed and id.
std::uint64_t SeedForRun(const RunSpec& spec, std::uint64_t base_seed, SeedPolicy policy);

/// True when `filter` matches the cell of `spec` (every given field equal; parameters compared by value).
bool Matches(const CellFilter& filter, const RunSpec& spec);

}  // namespace slamsweep::orchestrator::inline matrix
