#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/validity/metric_validity.h"
#include "orchestrator/store/results_store.h"

namespace slamsweep::orchestrator::inline store {

/// A run as the metric validity study reads it: status, odometry flag, every flat metric with a value
/// as "<metric>.<statistic>", and the resources (wall_s, cpu_s, peak_rss_kb) of runs that ran a
/// program (the odometry baseline runs none: its wall time is slamsweep's own rendering). The store's
/// outputs and the report's validity page convert their runs alike, so both hold the same numbers.
evaluator::ValidityRun ToValidityRun(const RunRecord& run);
std::vector<evaluator::ValidityRun> ToValidityRuns(const std::vector<RunRecord>& runs);

/// A study with the digest of the inputs it was drawn from (ValidityInputsDigest, below).
struct DigestedValidityStudy {
  evaluator::ValidityStudy study;
  std::string inputs_sha256;
};

/// The study of `runs` (evaluator::ComputeValidityStudy) and its inputs' digest, from one conversion of the
/// runs: the one computation behind summary.json's "validity" and validity.csv.
DigestedValidityStudy ValidityStudyOf(const std::vector<RunRecord>& runs);

/// SHA-256 (64 hex digits) of everything ValidityStudyOf's result depends on: every run as the study reads
/// it (in run id order, values bit for bit), the study's options, this slamsweep's revision and the digest of
/// the running program. summary.json keeps it beside the study ("validity"."inputs_sha256"), so that a
/// reader with the same runs and the same build may take the study from there instead of drawing its
/// bootstrap again, and any other reader computes it anew.
std::string ValidityInputsDigest(const std::vector<evaluator::ValidityRun>& runs);

/// The study summary.json's `validity` object holds, when its inputs_sha256 is ValidityInputsDigest(runs);
/// otherwise (another build, other runs, no digest) nullopt.
std::optional<evaluator::ValidityStudy> StoredValidityStudyFor(const nlohmann::json& validity,
                                                               const std::vector<evaluator::ValidityRun>& runs);

}  // namespace slamsweep::orchestrator::inline store
