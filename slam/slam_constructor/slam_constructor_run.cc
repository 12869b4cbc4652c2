// The only file of a driver that includes slam-constructor: its headers define functions outside
// classes without `inline`, so one translation unit per program may include them.
#include "slam/slam_constructor/slam_constructor_run.h"

#include <cmath>
#include <iostream>

#include <utils/init_slam.h>
#include <utils/properties_providers.h>

#include "evaluator/core/input_error.h"
#include "evaluator/core/installation.h"

namespace slamsweep::slam::slam_constructor {
namespace {

const std::string kSeedProperty = "slam/scmtch/MC/seed";
const std::string kSkipNoReturnsProperty = "ros/skip_exceeding_lsr_vals";

/// slam-constructor keeps cells in an unbounded grid addressed from its origin; a cell never
/// touched by a scan is unknown.
evaluator::OccupancyGrid ToOccupancyGrid(const GridMap& map) {
  const DiscretePoint2D origin = map.origin();
  const int width = map.width();
  const int height = map.height();
  const double scale = map.scale();
  // External cell c covers [scale * c, scale * (c + 1)): the first internal cell is -origin.
  evaluator::OccupancyGrid grid(width, height, scale, {-origin.x * scale, -origin.y * scale, 0.0});
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const GridCell& cell = map[DiscretePoint2D{x - origin.x, y - origin.y}];
      if (cell.is_unknown()) continue;
      grid.at(height - 1 - y, x) = static_cast<float>(double(cell));
    }
  }
  return grid;
}

RobotPose Planar(const evaluator::Pose& pose) { return RobotPose(pose.position.x(), pose.position.y(), pose.Yaw()); }

/// The scan as slam-constructor's ROS observer builds it: polar points in the laser frame, a
/// no-return at max range as a free (not occupied) point, or dropped when the properties say
/// ros/skip_exceeding_lsr_vals=true. A laser mounted off the robot's origin gives Cartesian points
/// in the robot frame instead.
LaserScan2D ToScan(const evaluator::LaserScan& scan, bool skip_no_returns) {
  LaserScan2D out;
  out.points().reserve(scan.BeamCount());
  const evaluator::Pose& mount = scan.sensor_pose_on_robot;
  const bool centred = std::hypot(mount.position.x(), mount.position.y()) < 1e-9;
  const double mount_yaw = mount.Yaw();
  for (std::size_t b = 0; b < scan.BeamCount(); ++b) {
    double range = scan.ranges_m[b];
    if (range < scan.range_min_m) continue;
    const bool hit = scan.IsHit(scan.ranges_m[b]);
    if (!hit && skip_no_returns) continue;
    if (!hit) range = scan.range_max_m;
    const double angle = mount_yaw + scan.BeamAngleRad(b);
    if (centred) {
      out.points().push_back(ScanPoint2D::make_polar(range, angle, hit));
    } else {
      const Point2D point{mount.position.x() + range * std::cos(angle), mount.position.y() + range * std::sin(angle)};
      out.points().push_back(ScanPoint2D::make_cartesian(point, hit));
    }
  }
  return out;
}

class SlamConstructorAlgorithm : public Algorithm {
 public:
  explicit SlamConstructorAlgorithm(FilePropertiesProvider properties) : properties_(std::move(properties)) {}

  void Run(const evaluator::RobotLog& robot, DriverOutputs& outputs) override {
    auto world = init_1h_slam(properties_);
    const bool skip_no_returns = properties_.get_bool(kSkipNoReturnsProperty, true);
    for (std::size_t i = 0; i < robot.scans.size(); ++i) {
      TransformedLaserScan observation;
      observation.scan = ToScan(robot.scans[i], skip_no_returns);
      observation.quality = 1.0;
      if (i > 0) {
        // The odometry increment in the robot frame, turned into the world frame at the current
        // estimate's heading: slam-constructor adds pose deltas component-wise in the world frame.
        const RobotPose previous = Planar(robot.odometry.poses()[i - 1]);
        const RobotPose current = Planar(robot.odometry.poses()[i]);
        const double c = std::cos(previous.theta), s = std::sin(previous.theta);
        const double dx = current.x - previous.x, dy = current.y - previous.y;
        const double forward = c * dx + s * dy, left = -s * dx + c * dy;
        const double heading = world->pose().theta;
        observation.pose_delta = RobotPoseDelta(std::cos(heading) * forward - std::sin(heading) * left,
                                                std::sin(heading) * forward + std::cos(heading) * left,
                                                std::remainder(current.theta - previous.theta, 2 * M_PI));
      }
      world->handle_sensor_data(observation);
      const RobotPose& pose = world->pose();
      outputs.AddPose(i, robot.scans[i].stamp_s, evaluator::Pose::Planar(pose.x, pose.y, pose.theta));
      if (outputs.StageDue(i) && i + 1 < robot.scans.size()) outputs.WriteStage(i, ToOccupancyGrid(world->map()));
    }
    const evaluator::OccupancyGrid map = ToOccupancyGrid(world->map());
    outputs.WriteStage(robot.scans.size() - 1, map);
    outputs.WriteFinal(map);
  }

 private:
  FilePropertiesProvider properties_;
};

}  // namespace

std::filesystem::path ConfigFile(std::string_view relative, const std::filesystem::path& built_root) {
  if (const auto installed = evaluator::FindInstalledData("slam-constructor/config/" + std::string(relative)))
    return *installed;
  return built_root / "config" / relative;
}

std::unique_ptr<Algorithm> ConfigureFromProperties(const std::filesystem::path& properties_file, Parameters& parameters,
                                                   const DriverArgs& args) {
  if (!std::filesystem::is_regular_file(properties_file)) {
    throw evaluator::InputError(properties_file.string() +
                                " missing: reinstall with scripts/install-slam.sh slam-constructor");
  }
  FilePropertiesProvider properties;
  properties.append_file_content(properties_file.string());
  // A beam without a return reaches the ROS observer at the laser's range_max and, unless
  // ros/skip_exceeding_lsr_vals is set, is inserted as free space out to that range. The Radish
  // and Freiburg logs declare 80 m, so every no-return became an 80 m free ray through the walls
  // (tinySLAM on intel, clean odometry: 8,975 corners and 1.02 m ATE; skipped: 216 corners and
  // 0.16 m). The driver therefore skips them unless the parameter says otherwise, for vinySLAM
  // too, whose properties file does not name the key.
  properties.set_property(kSkipNoReturnsProperty, "true");
  for (const std::string& key : properties.available_properties()) {
    if (key == kSeedProperty) continue;
    properties.set_property(key, parameters.Text(key, properties.get_str(key, "")));
  }
  if (parameters.Has(kSeedProperty)) {
    throw evaluator::InputError("parameter " + kSeedProperty +
                                ": the scan matcher's seed comes from --seed (the run's seed)");
  }
  // std::mt19937 takes 32 bits: the fold keeps the high half of the run's 64-bit seed.
  const std::uint64_t seed = args.seed.value_or(0);
  properties.set_property(kSeedProperty,
                          std::to_string(static_cast<std::int32_t>((seed ^ (seed >> 32)) & 0x7fffffffU)));
  return std::make_unique<SlamConstructorAlgorithm>(std::move(properties));
}

}  // namespace slamsweep::slam::slam_constructor
