#pragma once

#include <string>

#include "orchestrator/matrix/run_spec.h"

namespace slamsweep::orchestrator {

/// Range checks shared by the sweep config and run.json: InputError naming `path`.field and what is
/// expected ("evaluation.rpe_delta_m: expected a finite distance > 0 m"), without a file location
/// (the caller adds it).
void ValidateEvaluationOptions(const EvaluationOptions& evaluation, const std::string& path);
void ValidateThreshold(const Threshold& threshold, const std::string& path);

}  // namespace slamsweep::orchestrator
