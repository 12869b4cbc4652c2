#include "evaluator/formats/rawlog/mrpt_conversions.h"

#include <mrpt/core/Clock.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/CVectorFixed.h>

#include <cmath>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline formats::inline rawlog::internal {
namespace {

void RequireTwoBeams(std::size_t beams) {
  if (beams < 2) {
    throw InputError("a 2D scan with " + std::to_string(beams) +
                     " beams: MRPT spreads beams over the aperture in n - 1 steps and needs at least 2");
  }
}

}  // namespace

mrpt::poses::CPose3D ToMrptPose3D(const Pose& pose) {
  const Eigen::Matrix3d rotation = pose.orientation.normalized().toRotationMatrix();
  mrpt::math::CMatrixDouble33 mrpt_rotation;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) mrpt_rotation(r, c) = rotation(r, c);
  }
  mrpt::math::CVectorFixedDouble<3> translation;
  for (int i = 0; i < 3; ++i) translation[i] = pose.position[i];
  return mrpt::poses::CPose3D(mrpt_rotation, translation);
}

Pose FromMrptPose3D(const mrpt::poses::CPose3D& pose) {
  Eigen::Matrix3d rotation;
  const mrpt::math::CMatrixDouble33& mrpt_rotation = pose.getRotationMatrix();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) rotation(r, c) = mrpt_rotation(r, c);
  }
  Pose out;
  out.position = Eigen::Vector3d(pose.x(), pose.y(), pose.z());
  out.orientation = Eigen::Quaterniond(rotation).normalized();
  return out;
}

mrpt::poses::CPose2D ToMrptPose2D(const Pose& pose) {
  return mrpt::poses::CPose2D(pose.position.x(), pose.position.y(), pose.Yaw());
}

Pose FromMrptPose2D(const mrpt::poses::CPose2D& pose) { return Pose::Planar(pose.x(), pose.y(), pose.phi()); }

mrpt::obs::CObservation2DRangeScan::Ptr ToMrptScan(const LaserScan& scan, const std::string& sensor_label,
                                                   float range_std_m) {
  const std::size_t beams = scan.BeamCount();
  RequireTwoBeams(beams);
  const double span_rad = scan.angle_increment_rad * static_cast<double>(beams - 1);
  const double centre_rad = scan.angle_min_rad + span_rad / 2.0;

  auto observation = mrpt::obs::CObservation2DRangeScan::Create();
  observation->sensorLabel = sensor_label;
  observation->timestamp = mrpt::Clock::fromDouble(scan.stamp_s);
  observation->aperture = static_cast<float>(std::abs(span_rad));
  observation->rightToLeft = scan.angle_increment_rad > 0.0;
  observation->maxRange = static_cast<float>(scan.range_max_m);
  observation->stdError = range_std_m;
  observation->sensorPose = ToMrptPose3D(scan.sensor_pose_on_robot * Pose::Planar(0.0, 0.0, centre_rad));
  observation->resizeScan(beams);
  for (std::size_t i = 0; i < beams; ++i) {
    observation->setScanRange(i, scan.ranges_m[i]);
    observation->setScanRangeValidity(i, scan.IsHit(scan.ranges_m[i]));
  }
  return observation;
}

LaserScan FromMrptScan(const mrpt::obs::CObservation2DRangeScan& observation) {
  const std::size_t beams = observation.getScanSize();
  RequireTwoBeams(beams);
  LaserScan scan;
  scan.stamp_s = mrpt::Clock::toDouble(observation.timestamp);
  const double aperture_rad = observation.aperture;
  const double step_rad = aperture_rad / static_cast<double>(beams - 1);
  scan.angle_min_rad = observation.rightToLeft ? -aperture_rad / 2.0 : aperture_rad / 2.0;
  scan.angle_increment_rad = observation.rightToLeft ? step_rad : -step_rad;
  scan.range_min_m = 0.0;
  scan.range_max_m = observation.maxRange;
  scan.sensor_pose_on_robot = FromMrptPose3D(observation.sensorPose);
  scan.ranges_m.resize(beams);
  for (std::size_t i = 0; i < beams; ++i) {
    const float range_m = observation.getScanRange(i);
    // An invalid beam keeps its stored value when that already reads as "no return" (CARMEN's
    // 81.91 m code), so a write/read round trip returns what was written.
    const bool reads_as_hit = scan.IsHit(range_m);
    scan.ranges_m[i] =
        observation.getScanRangeValidity(i) || !reads_as_hit ? range_m : static_cast<float>(scan.range_max_m);
  }
  return scan;
}

}  // namespace slamsweep::evaluator::inline formats::inline rawlog::internal
