#pragma once

#include <cstddef>

#include <nlohmann/json.hpp>

#include "evaluator/sequence/sequence.h"
#include "orchestrator/matrix/run_spec.h"

namespace slamsweep::orchestrator {

/// What a run gives its program, and the truth it is scored against: the sequence after cutting
/// (max_scans) and noise. `sequence.reference` and `sequence.relations` stay noise-free.
struct RunInputs {
  evaluator::Sequence sequence;
  /// The noise applied and its seeds, recorded in result.json so the input can be reproduced.
  nlohmann::json noise_record;
};

/// The first `max_scans` scans of `sequence` with their odometry; reference poses and relations
/// later than the last kept scan are dropped too (they describe a part the run never saw).
/// A sequence with fewer scans is returned unchanged; max_scans = 0 is an InputError.
evaluator::Sequence CutSequence(evaluator::Sequence sequence, std::size_t max_scans);

/// Applies the run's noise exactly as `slamsweep data convert` does: odometry noise with
/// DeriveSeed(seed, 0), drawn around the reference when it has a pose at every scan (corrected
/// logs, whose odometry equals their reference), else around the odometry; range noise with
/// DeriveSeed(seed, 1). Returns the record of what was applied.
nlohmann::json ApplyRunNoise(evaluator::Sequence& sequence, const NoiseSpec& noise, std::uint64_t seed);

/// Loads the run's sequence (LoadCatalogSequence: paths in run.json are already resolved), cuts
/// and noises it. Every problem is an InputError naming the sequence or the field.
RunInputs PrepareRunInputs(const RunSpec& spec);

}  // namespace slamsweep::orchestrator
