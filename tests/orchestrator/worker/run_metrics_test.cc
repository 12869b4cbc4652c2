#include "orchestrator/worker/run_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "evaluator/core/input_error.h"
#include "orchestrator/run/run_failure.h"

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

// Relations outside the log are counted apart from relations inside it that the run did not cover.
TEST(RunMetricsTest, RelationsOutsideTheLogAreNotCountedAsNotCovered) {
  ev::Trajectory estimate;
  for (int i = 0; i <= 5; ++i) estimate.Add(i, At(i));  // stops half-way through the log's 0..10 s
  const ev::Relations relations = {{0, 1, At(1)}, {2, 3, At(1)}, {4, 8, At(4)}, {7, 9, At(2)}};
  MetricInputs inputs;
  inputs.estimate = &estimate;
  inputs.relations = &relations;
  inputs.relations_outside_log = 6;
  const RunMetrics metrics = ComputeRunMetrics({}, inputs);
  EXPECT_EQ(*Find(metrics, "relations_trans", "n"), 2.0);
  EXPECT_EQ(*Find(metrics, "relations_trans", "not_covered"), 2.0);
  EXPECT_EQ(*Find(metrics, "relations_trans", "outside_log"), 6.0);
  EXPECT_FALSE(Find(metrics, "relations_trans", "skipped"));
  EXPECT_EQ(metrics.details.at("relations").at("outside_log"), 6);
  EXPECT_EQ(metrics.details.at("relations").at("not_covered"), 2);
  // Relations are the only reference: the coverage counts them, 2 of the 4 inside the log.
  ASSERT_TRUE(metrics.relations_coverage.has_value());
  EXPECT_EQ(metrics.relations_coverage->covered, 2u);
  EXPECT_EQ(metrics.relations_coverage->inside_log, 4u);
  EXPECT_EQ(metrics.details.at("coverage").at("basis"), "relations");
  EXPECT_DOUBLE_EQ(metrics.details.at("coverage").at("fraction").get<double>(), 0.5);
  EvaluationOptions evaluation;
  evaluation.min_coverage = 0.95;
  try {
    RequireCoverage(evaluation, metrics);
    FAIL() << "expected the coverage gate to fail the run";
  } catch (const RunFailure& failure) {
    EXPECT_EQ(failure.kind(), FailureKind::kIncompleteTrajectory);
    EXPECT_NE(std::string(failure.what()).find("covers 2 of the 4 relations inside the log"), std::string::npos)
        << failure.what();
  }
  evaluation.min_coverage = 0.5;
  EXPECT_NO_THROW(RequireCoverage(evaluation, metrics));
}

// An estimate that covers none of the relations is scored 0 of them, and fails the gate.
TEST(RunMetricsTest, AnEstimateCoveringNoRelationFailsTheRelationsCoverage) {
  ev::Trajectory estimate;
  estimate.Add(0, At(0));
  estimate.Add(1, At(1));
  const ev::Relations relations = {{4, 8, At(4)}};
  MetricInputs inputs;
  inputs.estimate = &estimate;
  inputs.relations = &relations;
  const RunMetrics metrics = ComputeRunMetrics({}, inputs);
  ASSERT_TRUE(metrics.relations_coverage.has_value());
  EXPECT_EQ(metrics.relations_coverage->covered, 0u);
  EXPECT_THROW(RequireCoverage({}, metrics), RunFailure);
}

// With a reference trajectory the gate stays on its time span; relations do not add a second one.
TEST(RunMetricsTest, WithAReferenceTheCoverageIsTheReferencesTimeSpan) {
  const ev::Trajectory reference = Line();
  const ev::Trajectory estimate = Line();
  const ev::Relations relations = {{0, 1, At(1)}};
  MetricInputs inputs;
  inputs.estimate = &estimate;
  inputs.reference = &reference;
  inputs.relations = &relations;
  const RunMetrics metrics = ComputeRunMetrics({}, inputs);
  EXPECT_FALSE(metrics.relations_coverage.has_value());
  ASSERT_TRUE(metrics.coverage.has_value());
  EXPECT_FALSE(metrics.details.at("coverage").contains("basis"));
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
    if (metric.metric.starts_with("segment_")) continue;  // their units: SegmentRpeAtTenToFiftyPercent below
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
  ASSERT_EQ(metrics.warnings.size(), 6u);  // ape x2, rpe x2, segment rpe, paper map
  EXPECT_TRUE(metrics.warnings.front().starts_with("ape_trans: ")) << metrics.warnings.front();
  EXPECT_TRUE(metrics.warnings.back().starts_with("paper_map: ")) << metrics.warnings.back();

  inputs.map = &room;
  metrics = ComputeRunMetrics({}, inputs);
  EXPECT_NEAR(*Find(metrics, "occupied_to_all", "value"), 0.01, 1e-12);
  EXPECT_EQ(*Find(metrics, "unknown_to_all", "value"), 0.0);
}

/// The estimate `scale` times as far along x as the reference, poses 0 .. last.
ev::Trajectory Stretched(double scale, int last = 10) {
  ev::Trajectory line;
  for (int i = 0; i <= last; ++i) line.Add(i, At(scale * i));
  return line;
}

TEST(RunMetricsTest, SegmentRpeAtTenToFiftyPercentOfTheReferencePath) {
  const ev::Trajectory reference = Line();  // 10 m: segments of 1, 2, 3, 4 and 5 m
  const ev::Trajectory estimate = Stretched(1.1);
  MetricInputs inputs;
  inputs.estimate = &estimate;
  inputs.reference = &reference;
  const RunMetrics metrics = ComputeRunMetrics({}, inputs);
  for (const int length : {1, 2, 3, 4, 5}) {
    const std::string suffix = "_" + std::to_string(length) + "m";
    EXPECT_NEAR(*Find(metrics, "segment_drift" + suffix, "mean"), 10.0, 1e-9) << suffix;  // 10 % too long
    EXPECT_NEAR(*Find(metrics, "segment_trans" + suffix, "max"), 0.1 * length, 1e-9);
    EXPECT_NEAR(*Find(metrics, "segment_rot" + suffix, "mean"), 0.0, 1e-12);
    EXPECT_EQ(*Find(metrics, "segment_drift" + suffix, "n"), 11.0 - length);
    EXPECT_FALSE(Find(metrics, "segment_drift" + suffix, "rmse"));
  }
  for (const FlatMetric& metric : metrics.metrics) {
    if (!metric.metric.starts_with("segment_") || metric.statistic == "n") continue;
    EXPECT_EQ(metric.unit, metric.metric.starts_with("segment_drift") ? "%"
                           : metric.metric.starts_with("segment_rot") ? "deg/m"
                                                                      : "m")
        << metric.metric;
  }
  const nlohmann::json& specification = metrics.details.at("segment_rpe").at("specification");
  EXPECT_EQ(specification.at("lengths_m"), nlohmann::json::array({1.0, 2.0, 3.0, 4.0, 5.0}));
  EXPECT_EQ(specification.at("lengths_from"), "reference path");
  EXPECT_EQ(specification.at("reference_path_m"), 10.0);
  EXPECT_EQ(specification.at("pairs_from"), "reference");
  ASSERT_TRUE(metrics.segment_errors);
  EXPECT_EQ(metrics.segment_errors->size(), 10u + 9u + 8u + 7u + 6u);
  EXPECT_TRUE(metrics.warnings.empty());
}

// The lengths come from the whole reference, never from the part an estimate covers: a run that
// stopped early is scored at the same lengths as the others of its group, and lacks the longest.
TEST(RunMetricsTest, SegmentLengthsDoNotDependOnTheEstimate) {
  const ev::Trajectory reference = Line();
  const ev::Trajectory short_estimate = Stretched(1.0, 4);
  MetricInputs inputs;
  inputs.estimate = &short_estimate;
  inputs.reference = &reference;
  const RunMetrics metrics = ComputeRunMetrics({}, inputs);
  EXPECT_EQ(metrics.details.at("segment_rpe").at("specification").at("lengths_m"),
            nlohmann::json::array({1.0, 2.0, 3.0, 4.0, 5.0}));
  EXPECT_TRUE(Find(metrics, "segment_drift_4m", "mean"));
  EXPECT_FALSE(Find(metrics, "segment_drift_5m", "mean"));
  ASSERT_EQ(metrics.warnings.size(), 1u);
  EXPECT_NE(metrics.warnings[0].find("no segment of 5 m"), std::string::npos) << metrics.warnings[0];
}

TEST(RunMetricsTest, ConfiguredSegmentLengthsOrNone) {
  ev::Trajectory reference;  // 0.5 m steps, so that a 2.5 m segment fits exactly
  ev::Trajectory estimate;
  for (int i = 0; i <= 20; ++i) {
    reference.Add(i, At(0.5 * i));
    estimate.Add(i, At(1.02 * 0.5 * i));
  }
  MetricInputs inputs;
  inputs.estimate = &estimate;
  inputs.reference = &reference;
  EvaluationOptions evaluation;
  evaluation.rpe_segments_m = std::vector<double>{2.5};
  RunMetrics metrics = ComputeRunMetrics(evaluation, inputs);
  ASSERT_TRUE(Find(metrics, "segment_drift_2p5m", "median"));
  EXPECT_NEAR(*Find(metrics, "segment_drift_2p5m", "median"), 2.0, 1e-9);
  EXPECT_EQ(metrics.details.at("segment_rpe").at("specification").at("lengths_from"), "evaluation.rpe_segments_m");
  evaluation.rpe_segments_m = std::vector<double>{};
  metrics = ComputeRunMetrics(evaluation, inputs);
  EXPECT_FALSE(metrics.details.contains("segment_rpe"));
  EXPECT_FALSE(metrics.segment_errors);
  EXPECT_EQ(SegmentRpeMetricName("drift", 12.0), "segment_drift_12m");
  EXPECT_EQ(SegmentRpeMetricName("rot", 0.25), "segment_rot_0p25m");
}

TEST(RunMetricsTest, AnUnknownAlignmentIsAnInputError) {
  EvaluationOptions evaluation;
  evaluation.align = "se4";
  EXPECT_THROW(ComputeRunMetrics(evaluation, {}), ev::InputError);
}

}  // namespace
}  // namespace slamsweep::orchestrator
