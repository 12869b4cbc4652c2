#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "evaluator/core/statistics.h"
#include "evaluator/trajectory_metrics/alignment.h"
#include "evaluator/trajectory_metrics/association.h"
#include "evaluator/trajectory_metrics/pose_relation.h"

namespace slamsweep::evaluator::inline trajectory_metrics {

/// One APE or RPE result: the statistics of one error vector, the unit they are in and the
/// full specification they were computed under (numbers from different specifications must
/// never be compared).
struct MetricResult {
  std::string metric;  ///< "ape" or "rpe"
  std::string unit;    ///< "m" or "deg"
  /// Every option: pose_relation, alignment, n_to_align, t_max_diff_s, t_offset_s and, for RPE,
  /// delta, delta_unit, all_pairs, delta_tolerance and pairs_from.
  nlohmann::json specification;
  ErrorStatistics statistics;
  /// One error per compared pair (APE: per associated pose; RPE: per index pair), in order.
  std::vector<double> errors;
  /// Associated pose pairs (timestamp matches), for APE and RPE alike. evo's own
  /// "pairs_associated" differs for RPE: it counts the poses evo keeps for plotting, which is
  /// the number of RPE index pairs + 1 (statistics.n + 1).
  std::size_t pairs = 0;
  std::size_t reference_unpaired = 0;
  std::size_t estimate_unpaired = 0;
  /// The transform applied to the estimate; absent for alignment "none".
  std::optional<Alignment> alignment;

  /// rmse mean median std min max sse n at the top level, plus metric, unit, specification,
  /// pairs, reference_unpaired, estimate_unpaired and (when aligned) alignment. No errors vector.
  nlohmann::json ToJson() const;
};

/// Completes a result whose `errors` (and `alignment`) are filled: metric name, unit of the pose
/// relation, specification, statistics of the errors, and the association counts. APE and RPE
/// share it so both report the same fields the same way.
void FinishMetricResult(std::string metric, PoseRelation pose_relation, nlohmann::json specification,
                        const AssociatedIndices& pairs, MetricResult& result);

}  // namespace slamsweep::evaluator::inline trajectory_metrics
