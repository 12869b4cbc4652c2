#include "slam/common/driver_io.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/map_server_format.h"
#include "evaluator/formats/trajectory/trajectory_file.h"
#include "evaluator/sequence_io/robot_log_file.h"
#include "tests/support/shared_data.h"

namespace slamsweep::slam {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

fs::path FreshDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("slam_driver_io_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<std::size_t> StagesOf(std::size_t scans, int stages) {
  const fs::path dir = FreshDir("stages");
  DriverOutputs outputs(dir, scans, stages);
  std::vector<std::size_t> due;
  for (std::size_t i = 0; i < scans; ++i) {
    if (outputs.StageDue(i)) due.push_back(i);
  }
  return due;
}

TEST(DriverOutputsTest, SpreadsStagesEvenlyEndingAtTheLastScan) {
  EXPECT_EQ(StagesOf(10, 5), (std::vector<std::size_t>{1, 3, 5, 7, 9}));
  EXPECT_EQ(StagesOf(10, 3), (std::vector<std::size_t>{3, 6, 9}));
  EXPECT_EQ(StagesOf(3, 10), (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(StagesOf(7, 1), (std::vector<std::size_t>{6}));
  EXPECT_TRUE(StagesOf(7, 0).empty());
}

TEST(DriverOutputsTest, WritesTrajectoryMapAndStagesThatReadBack) {
  const fs::path dir = FreshDir("write");
  DriverOutputs outputs(dir / "out", 2, 1);
  outputs.AddPose(0, 10.0, evaluator::Pose::Planar(1.0, 2.0, 0.5));
  evaluator::OccupancyGrid map(4, 3, 0.1, {-1.0, -2.0, 0.0});
  map.at(0, 0) = 1.0f;
  map.at(1, 1) = 0.0f;
  map.at(2, 3) = 0.5f;
  outputs.AddPose(1, 10.5, evaluator::Pose::Planar(1.5, 2.0, 0.25));
  ASSERT_TRUE(outputs.StageDue(1));
  outputs.WriteStage(1, map);
  outputs.WriteFinal(map);

  const evaluator::Trajectory trajectory = evaluator::ReadTrajectory(dir / "out" / "trajectory.tum");
  ASSERT_EQ(trajectory.size(), 2u);
  EXPECT_DOUBLE_EQ(trajectory.stamps_s()[1], 10.5);
  EXPECT_NEAR(trajectory.poses()[1].Yaw(), 0.25, 1e-12);
  const evaluator::OccupancyGrid final_map = evaluator::ReadMapServer(dir / "out" / "map.yaml");
  EXPECT_EQ(final_map.width, 4);
  EXPECT_DOUBLE_EQ(final_map.origin.x_m, -1.0);
  EXPECT_TRUE(evaluator::OccupancyGrid::IsUnknown(final_map.at(0, 1)));
  EXPECT_GT(final_map.at(0, 0), 0.9f);
  EXPECT_LT(final_map.at(1, 1), 0.1f);
  // Scale mode keeps grey levels; map_server reads a level between its thresholds back on its own
  // 0..99 scale, so an uncertain cell stays strictly between free and occupied.
  EXPECT_GT(final_map.at(2, 3), 0.3f);
  EXPECT_LT(final_map.at(2, 3), 0.9f);
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / "stages" / "stage-000001.yaml"));
}

TEST(DriverOutputsTest, RefusesPosesOutOfOrder) {
  DriverOutputs outputs(FreshDir("order"), 3, 0);
  EXPECT_THROW(outputs.AddPose(1, 0.0, evaluator::Pose::Planar(0, 0, 0)), std::logic_error);
}

TEST(ReadDriverInputTest, KeepsScansAndOdometryOnly) {
  evaluator::RobotLog log;
  log.name = "square";
  for (int i = 0; i < 3; ++i) {
    evaluator::LaserScan scan;
    scan.stamp_s = i;
    scan.ranges_m = {1.0f, 2.0f, 3.0f};
    scan.angle_min_rad = -0.5;
    scan.angle_increment_rad = 0.5;
    scan.range_max_m = 10.0;
    log.scans.push_back(scan);
    log.odometry.Add(i, evaluator::Pose::Planar(i, 0.0, 0.0));
  }
  const fs::path dir = FreshDir("input");
  evaluator::WriteRobotLog(log, dir / "square.log", evaluator::SequenceWriteFormat::kCarmen);
  const evaluator::RobotLog read = ReadDriverInput(dir / "square.log");
  ASSERT_EQ(read.scans.size(), 3u);
  EXPECT_EQ(read.scans[1].BeamCount(), 3u);
  EXPECT_NEAR(read.scans[1].angle_increment_rad, 0.5, 1e-6);
  EXPECT_NEAR(read.odometry.poses()[2].position.x(), 2.0, 1e-6);
}

TEST(ReadDriverInputTest, NamesTheFileItCannotRead) {
  const fs::path dir = FreshDir("bad");
  testing::WriteFile(dir / "bad.log", "ROBOTLASER1 this is not a laser\n");
  try {
    ReadDriverInput(dir / "bad.log");
    FAIL() << "no error";
  } catch (const evaluator::InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("bad.log"));
  }
}

}  // namespace
}  // namespace slamsweep::slam
