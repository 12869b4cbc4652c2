#include "orchestrator/adapters/run_inputs.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <opencv2/core.hpp>

#include "evaluator/core/input_error.h"
#include "orchestrator/adapters/odometry_adapter.h"
#include "orchestrator/adapters/stage_image.h"
#include "orchestrator/run/run_record.h"
#include "tests/orchestrator/worker/run_spec_fixture.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

namespace ev = slamsweep::evaluator;

ev::Pose At(double x) {
  ev::Pose pose;
  pose.position = Eigen::Vector3d(x, 0, 0);
  return pose;
}

ev::Sequence FiveScans() {
  ev::Sequence sequence;
  sequence.name = "five";
  ev::Trajectory reference;
  for (int i = 0; i < 5; ++i) {
    ev::LaserScan scan;
    scan.stamp_s = i;
    scan.ranges_m = {1.0f, 1.0f};
    scan.angle_increment_rad = 0.1;
    scan.range_max_m = 10;
    sequence.scans.push_back(scan);
    sequence.odometry.Add(i, At(i));
    reference.Add(i + 0.5, At(i));
  }
  sequence.reference = reference;
  sequence.relations = ev::Relations{{0, 1, At(1)}, {1, 2.5, At(1.5)}, {3, 4, At(1)}};
  return sequence;
}

TEST(CutSequenceTest, KeepsTheFirstScansAndTheTruthUpToTheLastOne) {
  const ev::Sequence cut = CutSequence(FiveScans(), 3);
  ASSERT_EQ(cut.scans.size(), 3u);
  EXPECT_EQ(cut.odometry.size(), 3u);
  EXPECT_EQ(cut.odometry.stamps_s().back(), 2.0);
  // Reference stamps 0.5 and 1.5 lie before the last kept scan (2 s); 2.5 does not.
  ASSERT_TRUE(cut.reference);
  EXPECT_EQ(cut.reference->stamps_s(), (std::vector<double>{0.5, 1.5}));
  // Only the relation that ends by 2 s survives.
  ASSERT_TRUE(cut.relations);
  ASSERT_EQ(cut.relations->size(), 1u);
  EXPECT_EQ(cut.relations->front().t2_s, 1.0);
}

TEST(CutSequenceTest, LeavesAShorterSequenceAloneAndRefusesZero) {
  EXPECT_EQ(CutSequence(FiveScans(), 10).scans.size(), 5u);
  EXPECT_THROW(CutSequence(FiveScans(), 0), ev::InputError);
}

TEST(ApplyRunNoiseTest, CleanNoiseChangesNothingAndNoisyOdometryIsReproducible) {
  ev::Sequence clean = FiveScans();
  const nlohmann::json record = ApplyRunNoise(clean, NoiseSpec{}, 3);
  EXPECT_EQ(clean.odometry.poses()[4].position.x(), 4.0);
  EXPECT_TRUE(record["odometry"].is_null());

  NoiseSpec noise;
  noise.name = "noisy";
  noise.odometry = ev::OdometryNoise{0.01, 0.01, 0.01, 0.01, 0.0, 0.0};
  ev::Sequence a = FiveScans();
  ev::Sequence b = FiveScans();
  ApplyRunNoise(a, noise, 3);
  const nlohmann::json noisy = ApplyRunNoise(b, noise, 3);
  EXPECT_EQ(a.odometry.poses()[4].position, b.odometry.poses()[4].position);
  EXPECT_NE(a.odometry.poses()[4].position.x(), 4.0);
  // The reference's stamps differ from the scans': noise is drawn around the odometry.
  EXPECT_EQ(noisy["odometry_around"], "odometry");
  EXPECT_EQ(noisy["odometry_seed"], ev::DeriveSeed(3, 0));
}

TEST(PrepareRunInputsTest, TheProgramGetsTheOdometryNeverTheReference) {
  // The simulated floor: odometry drawn with its own noise around the exact truth. What the program
  // is handed must be that odometry: were it the reference, every program would score perfectly.
  const RunSpec spec = testing::SimulatedRun("odometry", 60);
  const RunInputs inputs = PrepareRunInputs(spec);
  ASSERT_TRUE(inputs.truth.reference);
  ASSERT_EQ(inputs.robot.odometry.size(), inputs.truth.reference->size());
  double largest_m = 0.0;
  for (std::size_t i = 0; i < inputs.robot.odometry.size(); ++i) {
    largest_m = std::max(
        largest_m, (inputs.robot.odometry.poses()[i].position - inputs.truth.reference->poses()[i].position).norm());
  }
  EXPECT_GT(largest_m, 0.01);
  EXPECT_FALSE(inputs.odometry_is_reference);
  // result.json's sequence record: how many scans over how long, from which the report takes the densest log.
  ASSERT_EQ(inputs.robot.scans.size(), 60u);
  EXPECT_EQ(inputs.sequence_record.at("scans"), 60);
  const double span_s = inputs.robot.scans.back().stamp_s - inputs.robot.scans.front().stamp_s;
  EXPECT_DOUBLE_EQ(inputs.sequence_record.at("span_s").get<double>(), span_s);
  const std::optional<double> rate = ScanRateOfResult(nlohmann::json{{"sequence", inputs.sequence_record}});
  ASSERT_TRUE(rate);
  EXPECT_DOUBLE_EQ(*rate, 59.0 / span_s);
  EXPECT_FALSE(ScanRateOfResult(nlohmann::json{{"sequence", {{"scans", 1}, {"span_s", 0.0}}}}));
  EXPECT_FALSE(ScanRateOfResult(nlohmann::json::object()));
}

TEST(OdometryAdapterTest, TheTrajectoryIsTheOdometryAndTheMapIsRenderedFromIt) {
  const slamsweep::testing::TempDir dir;
  const RunPaths paths{dir.path()};
  const RunSpec spec = testing::SimulatedRun("odometry", 40);
  const RunInputs inputs = PrepareRunInputs(spec);
  const OdometryAdapter adapter;
  EXPECT_TRUE(adapter.Prepare(spec, inputs.robot, paths).argv.empty());
  const CollectedOutputs outputs = adapter.Collect(spec, inputs.robot, paths);
  ASSERT_TRUE(outputs.trajectory);
  EXPECT_EQ(outputs.trajectory->stamps_s(), inputs.robot.odometry.stamps_s());
  EXPECT_EQ(outputs.trajectory->poses().back().position, inputs.robot.odometry.poses().back().position);
  EXPECT_TRUE(outputs.map_rendered_from_trajectory);
  EXPECT_DOUBLE_EQ(outputs.map.resolution_m, spec.evaluation.map_resolution_m);
  ASSERT_EQ(outputs.stages.size(), spec.evaluation.stages);
  // The last stage is the final map; an earlier stage has seen fewer scans, so fewer known cells.
  const auto known = [](const cv::Mat& image) {
    return image.total() - static_cast<std::size_t>(cv::countNonZero(image == kStageUnknown));
  };
  EXPECT_LT(known(outputs.stages.front()), known(outputs.stages.back()));
  EXPECT_EQ(outputs.stages.back().rows, outputs.map.height);

  RunSpec with_parameters = spec;
  with_parameters.algorithm.parameters = {{"x", 1}};
  EXPECT_THROW(adapter.Prepare(with_parameters, inputs.robot, paths), ev::InputError);
}

}  // namespace
}  // namespace slamsweep::orchestrator
