#include "orchestrator/worker/run_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator {
namespace {

namespace ev = slamsweep::evaluator;

ev::Pose At(double x, double y = 0.0) {
  ev::Pose pose;
  pose.position = Eigen::Vector3d(x, y, 0);
  return pose;
}

/// The robot drives along x at 1 m/s: pose at t is (t, 0).
ev::Trajectory Line(double y_offset = 0.0) {
  ev::Trajectory line;
  for (int i = 0; i <= 10; ++i) line.Add(i, At(i, y_offset));
  return line;
}

std::optional<double> Find(const RunMetrics& metrics, const std::string& name, const std::string& statistic) {
  for (const FlatMetric& metric : metrics.metrics) {
    if (metric.metric == name && metric.statistic == statistic) return metric.value;
  }
  return std::nullopt;
}

TEST(RunMetricsTest, RelationsAreScoredByHand) {
  const ev::Trajectory estimate = Line();
  // Expected motions: 1 m along x (the estimate agrees: error 0) and 1.5 m (the estimate moved
  // 1 m: error 0.5 m). Mean of |e| = 0.25 m, population std = 0.25 m.
  const ev::Relations relations = {{0, 1, At(1)}, {2, 3, At(1.5)}};
  MetricInputs inputs;
  inputs.estimate = &estimate;
  inputs.relations = &relations;
  const RunMetrics metrics = ComputeRunMetrics({}, inputs);
  EXPECT_NEAR(*Find(metrics, "relations_trans", "mean"), 0.25, 1e-12);
  EXPECT_NEAR(*Find(metrics, "relations_trans", "std"), 0.25, 1e-12);
  EXPECT_EQ(*Find(metrics, "relations_trans", "n"), 2.0);
  EXPECT_NEAR(*Find(metrics, "relations_rot", "mean"), 0.0, 1e-12);
  EXPECT_TRUE(metrics.details.contains("relations"));
  EXPECT_FALSE(Find(metrics, "ape_trans", "rmse")) << "no reference, no APE";
}

TEST(RunMetricsTest, ApeAndRpeCarryTheirUnitsAndSpecification) {
  const ev::Trajectory reference = Line();
  const ev::Trajectory estimate = Line(0.2);
  EvaluationOptions evaluation;
  evaluation.align = "none";
  evaluation.rpe_delta_m = 2.0;
  MetricInputs inputs;
  inputs.estimate = &estimate;
  inputs.reference = &reference;
  const RunMetrics metrics = ComputeRunMetrics(evaluation, inputs);
  EXPECT_NEAR(*Find(metrics, "ape_trans", "rmse"), 0.2, 1e-12);
  EXPECT_EQ(*Find(metrics, "ape_trans", "n"), 11.0);
  EXPECT_NEAR(*Find(metrics, "rpe_trans", "max"), 0.0, 1e-12);
  for (const FlatMetric& metric : metrics.metrics) {
    if (metric.statistic == "n") {
      EXPECT_EQ(metric.unit, "count");
    } else {
      EXPECT_EQ(metric.unit, metric.metric.ends_with("_rot") ? "deg" : "m") << metric.metric;
    }
  }
  EXPECT_EQ(metrics.details["rpe_trans"]["specification"]["delta"], 2.0);
  EXPECT_EQ(metrics.details["rpe_trans"]["specification"]["delta_unit"], "m");
  EXPECT_TRUE(metrics.warnings.empty());
}

TEST(RunMetricsTest, AMetricThatCannotBeComputedIsAWarningAndTheOthersStillCount) {
  const ev::Trajectory reference = Line();
  const ev::Trajectory estimate = Line().Shifted(100.0);  // no stamp within 0.01 s
  const ev::OccupancyGrid unknown(10, 10, 0.05);          // not one known cell
  ev::OccupancyGrid room(10, 10, 0.05, {}, 0.0f);
  room.at(5, 5) = 1.0f;
  MetricInputs inputs;
  inputs.estimate = &estimate;
  inputs.reference = &reference;
  inputs.map = &unknown;
  RunMetrics metrics = ComputeRunMetrics({}, inputs);
  EXPECT_TRUE(metrics.metrics.empty());
  ASSERT_EQ(metrics.warnings.size(), 5u);  // ape x2, rpe x2, paper map
  EXPECT_TRUE(metrics.warnings.front().starts_with("ape_trans: ")) << metrics.warnings.front();
  EXPECT_TRUE(metrics.warnings.back().starts_with("paper_map: ")) << metrics.warnings.back();

  inputs.map = &room;
  metrics = ComputeRunMetrics({}, inputs);
  EXPECT_NEAR(*Find(metrics, "occupied_to_all", "value"), 0.01, 1e-12);
  EXPECT_EQ(*Find(metrics, "unknown_to_all", "value"), 0.0);
}

TEST(RunMetricsTest, AnUnknownAlignmentIsAnInputError) {
  EvaluationOptions evaluation;
  evaluation.align = "se4";
  EXPECT_THROW(ComputeRunMetrics(evaluation, {}), ev::InputError);
}

}  // namespace
}  // namespace slamsweep::orchestrator
