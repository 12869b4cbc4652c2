#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/core/relation.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/formats/trajectory/segment_errors_csv.h"
#include "evaluator/trajectory_metrics/coverage.h"
#include "orchestrator/run/flat_metric.h"
#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline worker {

/// The share of the relations inside the log that a run's estimate covers (both stamps in its span).
struct RelationsCoverage {
  std::size_t covered = 0;
  std::size_t inside_log = 0;
  double Fraction() const {
    return inside_log == 0 ? 0.0 : static_cast<double>(covered) / static_cast<double>(inside_log);
  }
  /// {"basis": "relations", "fraction", "covered", "inside_log"}
  nlohmann::json ToJson() const;
};

/// Every metric of a run with its full specification.
struct RunMetrics {
  std::vector<FlatMetric> metrics;
  /// metric name -> the evaluator's result JSON (MetricResult / RelationsResult / PaperMetrics).
  nlohmann::json details = nlohmann::json::object();
  /// One sentence per metric that could not be computed ("ape_trans: no matching timestamps ...").
  std::vector<std::string> warnings;
  /// Every segment of the segment RPE, for the run folder's rpe_segments.csv; absent when it was
  /// not computed.
  std::optional<std::vector<evaluator::SegmentErrorRecord>> segment_errors;
  /// The reference trajectory itself scored against the relations, exactly as the run's estimate is
  /// (same relations, same odometry between poses): the floor no program's relations error can be
  /// expected to go below when the reference is a SLAM result. Empty without reference or relations.
  std::vector<FlatMetric> reference_floor;
  nlohmann::json reference_floor_details;
  /// How much of the reference's time span the estimate covers; absent without both.
  std::optional<evaluator::TrajectoryCoverage> coverage;
  /// Where relations are the only reference (no reference trajectory): how many of the relations inside
  /// the log the estimate covers. The coverage gate then counts relations, not time.
  std::optional<RelationsCoverage> relations_coverage;
};

/// What the metrics are computed from: the run's estimate and the truth it is compared with.
struct MetricInputs {
  const evaluator::OccupancyGrid* map = nullptr;
  /// The map as written to the run folder (map_saver's trinary classes). The map-versus-reference
  /// scores are computed on it, so whoever reads the run's map file counts the same cells; the paper
  /// metrics need the program's grey levels and use `map`. null: `map` is used for both.
  const evaluator::OccupancyGrid* written_map = nullptr;
  const evaluator::Trajectory* estimate = nullptr;   ///< null: trajectory metrics are skipped
  const evaluator::Trajectory* reference = nullptr;  ///< null: APE and RPE are skipped
  const evaluator::Relations* relations = nullptr;   ///< null: the relations metric is skipped
  /// Relations of the sequence's file outside the (cut) log: counted, never scored, never "not covered".
  std::size_t relations_outside_log = 0;
  /// The odometry the program was given (its readings where denser than its scans): the relations
  /// metric moves the estimate by it between the estimate's poses. null: linear interpolation.
  const evaluator::Trajectory* odometry = nullptr;
  /// The reference map at the evaluation's cell size (orchestrator/reference_map); null: the
  /// map-versus-reference scores are skipped. The run's map is resampled to its cell size when
  /// they differ, and placed on it by the ATE's alignment, or by ICP from identity without one.
  const evaluator::OccupancyGrid* reference_map = nullptr;
  /// Where the reference map came from (ReferenceMap::ToJson), kept in the map_compare details.
  nlohmann::json reference_map_record;
};

/// Computes what the inputs allow: ape_trans/ape_rot (evaluation.align, t_max_diff_s),
/// rpe_trans/rpe_rot (delta evaluation.rpe_delta_m metres, consecutive pairs, no alignment: a
/// rigid alignment does not change relative errors), the segment RPE at evaluation.rpe_segments_m
/// (SegmentRpeMetricName; its lengths, and how they were chosen, in details["segment_rpe"]),
/// relations_trans/rot (Kuemmerle et al.: mean, std, n = used and skipped relations; also for the
/// reference itself as `reference_floor`), and
/// always the paper map metrics, on the map resampled to evaluation.map_resolution_m
/// (ResampleKeepingProbabilities; details["paper_map"] records resolution_m, the scale scored, and
/// map_resolution_m, the program's own). A metric that cannot be computed becomes a warning, never an
/// exception: the others still count. An invalid evaluation option (unknown alignment) is an
/// InputError naming it.
RunMetrics ComputeRunMetrics(const EvaluationOptions& evaluation, const MetricInputs& inputs);

/// The flat metric of the segment RPE at one length: "segment_trans_10m" (translation error, m),
/// "segment_drift_10m" (translation error in % of the length), "segment_rot_10m" (deg/m); a
/// fractional length is written with p for the point ("segment_drift_2p5m"). `kind` is trans, drift or rot.
std::string SegmentRpeMetricName(std::string_view kind, double length_m);

/// Throws RunFailure (incomplete_trajectory) when the trajectory spans less of the reference's time
/// span than evaluation.min_coverage, or, where relations are the only reference, covers a smaller
/// share of the relations inside the log: its errors would be measured on the part it chose to keep.
void RequireCoverage(const EvaluationOptions& evaluation, const RunMetrics& metrics);

}  // namespace slamsweep::orchestrator::inline worker
