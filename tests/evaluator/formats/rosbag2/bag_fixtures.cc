#include "tests/evaluator/formats/rosbag2/bag_fixtures.h"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>

#include "evaluator/core/pose.h"
#include "evaluator/formats/bag/bag_conversions.h"
#include "evaluator/sequence_io/robot_log_file.h"
#include "evaluator/sequence_io/sequence_file.h"

namespace slamsweep::testing {
namespace {

constexpr std::size_t kScans = 150;

std::string ReadAll(const std::filesystem::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

std::string RunCommand(const std::string& command, const std::filesystem::path& log) {
  if (std::system((command + " > '" + log.string() + "' 2>&1").c_str()) == 0) return "";
  return "`" + command + "` failed:\n" + ReadAll(log);
}

const std::filesystem::path& FixtureDir() {
  static const TempDir dir;
  return dir.path();
}

const CarmenFixture& RawCarmenLog() {
  static const CarmenFixture fixture = [] {
    CarmenFixture made;
    const std::string relative = "datasets/intel/intel-corrected.log.gz";
    if (made.why = MissingSharedFile(relative); !made.why.empty()) return made;
    evaluator::SequenceReadOptions options;
    options.carmen.odometry = evaluator::OdometryMode::kRecorded;
    const evaluator::Sequence intel = evaluator::ReadSequence(SharedRoot() / relative, options);
    // Stamps on whole nanoseconds, as a bag holds them: the reader's repairs of the log's non-increasing
    // stamps leave a few a ulp beside another reading's, which a ROS time cannot tell apart.
    const auto ns = [](double stamp_s) { return evaluator::ToRosTime(stamp_s, "fixture").Nanoseconds(); };
    const auto seconds = [](std::int64_t stamp_ns) {
      return evaluator::RosTimeSeconds(stamp_ns / 1000000000, static_cast<std::uint32_t>(stamp_ns % 1000000000));
    };
    evaluator::RobotLog log;
    log.name = "intel-start";
    std::map<std::int64_t, evaluator::Pose> readings;
    for (std::size_t i = 0; i < kScans; ++i) {
      evaluator::LaserScan scan = intel.scans[i];
      scan.stamp_s = seconds(ns(scan.stamp_s));
      log.scans.push_back(scan);
      log.odometry.Add(scan.stamp_s, intel.odometry.poses()[i]);
      readings[ns(scan.stamp_s)] = intel.odometry.poses()[i];
    }
    for (std::size_t i = 0; i < intel.odometry_readings.size(); ++i) {
      if (intel.odometry_readings.stamps_s()[i] > intel.scans[kScans - 1].stamp_s) break;
      readings.try_emplace(ns(intel.odometry_readings.stamps_s()[i]), intel.odometry_readings.poses()[i]);
    }
    for (const auto& [stamp_ns, pose] : readings) log.odometry_readings.Add(seconds(stamp_ns), pose);
    made.log = FixtureDir() / "intel-start.log";
    evaluator::WriteRobotLog(log, made.log, evaluator::SequenceWriteFormat::kCarmen);
    return made;
  }();
  return fixture;
}

const BagTools& NpmBagTools() {
  static const BagTools tools = [] {
    BagTools found;
    const std::filesystem::path log = FixtureDir() / "install-bag-tools.log";
    if (std::system(("node --version > '" + log.string() + "' 2>&1").c_str()) != 0) {
      found.why = "Node.js is not installed (the ROS 2 bag tests' independent side; scripts/install-bag-tools.sh)";
      return found;
    }
    const std::string command = std::string("'") + SLAMSWEEP_INSTALL_BAG_TOOLS + "' --check";
    if (!RunCommand(command, log).empty()) {
      found.why = "the npm bag tools are not installed (run scripts/install-bag-tools.sh; scripts/test.sh does)";
      return found;
    }
    std::string prefix = ReadAll(log);
    while (!prefix.empty() && (prefix.back() == '\n' || prefix.back() == '\r')) prefix.pop_back();
    found.prefix = prefix;
    return found;
  }();
  return tools;
}

std::string RunBagTool(const std::string& arguments) {
  static int calls = 0;
  const std::filesystem::path out = FixtureDir() / ("bag_tool_" + std::to_string(++calls) + ".out");
  const std::string command = "NODE_PATH='" + (NpmBagTools().prefix / "node_modules").string() + "' node '" +
                              SLAMSWEEP_BAG_TOOL + "' " + arguments + " 2> '" + out.string() + ".err'";
  if (std::system((command + " > '" + out.string() + "'").c_str()) != 0) {
    throw std::runtime_error("`" + command + "` failed:\n" + ReadAll(out.string() + ".err"));
  }
  return ReadAll(out);
}

nlohmann::json NpmDump(const std::filesystem::path& bag, const std::string& topics) {
  return nlohmann::json::parse(RunBagTool("dump '" + bag.string() + "' " + topics));
}

void ExpectSameRobotData(const evaluator::Sequence& expected, const evaluator::Sequence& actual) {
  ASSERT_EQ(actual.scans.size(), expected.scans.size());
  for (std::size_t i = 0; i < expected.scans.size(); ++i) {
    const evaluator::LaserScan& a = actual.scans[i];
    const evaluator::LaserScan& e = expected.scans[i];
    ASSERT_EQ(a.stamp_s, e.stamp_s) << "scan " << i;
    ASSERT_EQ(a.ranges_m, e.ranges_m) << "scan " << i;
    // A LaserScan message holds float32 angles and limits. The log's SICK fan, stored as float32 in the bag, reads back
    // as the log's fan (ToLaserScan).
    ASSERT_EQ(a.angle_min_rad, e.angle_min_rad) << "scan " << i;
    ASSERT_EQ(a.angle_increment_rad, e.angle_increment_rad) << "scan " << i;
    ASSERT_EQ(static_cast<float>(a.range_max_m), static_cast<float>(e.range_max_m)) << "scan " << i;
    ASSERT_EQ(static_cast<float>(a.range_min_m), static_cast<float>(e.range_min_m)) << "scan " << i;
    ASSERT_LT((a.sensor_pose_on_robot.Inverse() * e.sensor_pose_on_robot).position.norm(), 1e-12) << "scan " << i;
  }
  const auto expect_same = [](const evaluator::Trajectory& e, const evaluator::Trajectory& a, const char* what) {
    ASSERT_EQ(a.size(), e.size()) << what;
    for (std::size_t i = 0; i < e.size(); ++i) {
      ASSERT_EQ(a.stamps_s()[i], e.stamps_s()[i]) << what << " " << i;
      ASSERT_EQ(a.poses()[i].position.x(), e.poses()[i].position.x()) << what << " " << i;
      ASSERT_EQ(a.poses()[i].position.y(), e.poses()[i].position.y()) << what << " " << i;
      ASSERT_NEAR(evaluator::NormalizeAngleRad(a.poses()[i].Yaw() - e.poses()[i].Yaw()), 0.0, 1e-12)
          << what << " " << i;
    }
  };
  expect_same(expected.odometry, actual.odometry, "odometry");
  expect_same(expected.odometry_readings, actual.odometry_readings, "odometry reading");
}

}  // namespace slamsweep::testing
