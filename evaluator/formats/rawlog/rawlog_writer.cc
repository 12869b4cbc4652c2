#include "evaluator/formats/rawlog/rawlog_writer.h"

#include <fmt/format.h>
#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <exception>
#include <system_error>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/rawlog/mrpt_conversions.h"

namespace slamsweep::evaluator::inline formats::inline rawlog {
namespace {

using internal::ToMrptPose2D;
using internal::ToMrptScan;

/// Tolerance on z, roll and pitch of the odometry: a rawlog action is a planar increment.
constexpr double kPlanarTolerance = 1e-6;

void CheckWritable(const RobotLog& sequence) {
  ValidateRobotLog(sequence);
  for (std::size_t i = 0; i < sequence.scans.size(); ++i) {
    if (sequence.scans[i].BeamCount() < 2) {
      throw InputError(fmt::format("sequence '{}': scan {} has {} beam(s); an MRPT 2D scan needs at least 2",
                                   sequence.name, i, sequence.scans[i].BeamCount()));
    }
  }
  if (!sequence.odometry.IsPlanar(kPlanarTolerance)) {
    throw InputError(
        fmt::format("sequence '{}': odometry leaves the plane (z, roll or pitch above {}); a rawlog "
                    "holds planar odometry increments",
                    sequence.name, kPlanarTolerance));
  }
}

mrpt::obs::CActionCollection OdometryAction(const Pose& increment, double stamp_s) {
  mrpt::obs::CActionRobotMovement2D movement;
  movement.estimationMethod = mrpt::obs::CActionRobotMovement2D::emOdometry;
  movement.computeFromOdometry(ToMrptPose2D(increment), mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
  movement.timestamp = mrpt::Clock::fromDouble(stamp_s);
  mrpt::obs::CActionCollection actions;
  actions.insert(movement);
  return actions;
}

void WriteObjects(const RobotLog& sequence, mrpt::serialization::CArchive& archive, const RawlogWriteOptions& options,
                  RawlogSummary& summary) {
  const auto range_std_m = static_cast<float>(options.range_std_m);
  const std::vector<Pose>& odometry = sequence.odometry.poses();
  for (std::size_t i = 0; i < sequence.scans.size(); ++i) {
    const LaserScan& scan = sequence.scans[i];
    const auto observation = ToMrptScan(scan, options.scan_label, range_std_m);
    if (options.form == RawlogForm::kActionsSensoryFrames) {
      const Pose increment = i == 0 ? odometry[0] : Relative(odometry[i - 1], odometry[i]);
      archive << OdometryAction(increment, scan.stamp_s);
      mrpt::obs::CSensoryFrame frame;
      frame.insert(observation);
      archive << frame;
      ++summary.actions;
      ++summary.sensory_frames;
    } else {
      mrpt::obs::CObservationOdometry odometry_observation;
      odometry_observation.sensorLabel = options.odometry_label;
      odometry_observation.timestamp = observation->timestamp;
      odometry_observation.odometry = ToMrptPose2D(odometry[i]);
      archive << odometry_observation;
      archive << *observation;
      summary.observations += 2;
    }
    ++summary.scans;
  }
}

}  // namespace

void CheckRawlogWriteOptions(const RawlogWriteOptions& options) {
  if (options.compression_level < 0 || options.compression_level > 9) {
    throw InputError(fmt::format("compression_level: expected 0 (none) to 9, got {}", options.compression_level));
  }
  if (!(options.range_std_m > 0.0) || !std::isfinite(options.range_std_m)) {
    throw InputError(
        fmt::format("range_std_m: expected a finite standard deviation > 0 m, got {}", options.range_std_m));
  }
  if (options.scan_label.empty()) throw InputError("scan_label: expected a sensor label, got an empty string");
  if (options.form == RawlogForm::kObservations && options.odometry_label.empty()) {
    throw InputError("odometry_label: expected a sensor label, got an empty string");
  }
}

RawlogSummary WriteRawlog(const RobotLog& sequence, const std::filesystem::path& path,
                          const RawlogWriteOptions& options) {
  CheckRawlogWriteOptions(options);
  CheckWritable(sequence);
  RawlogSummary summary;
  if (!sequence.scans.empty()) {
    summary.first_stamp_s = sequence.scans.front().stamp_s;
    summary.last_stamp_s = sequence.scans.back().stamp_s;
  }
  try {
    mrpt::io::CFileGZOutputStream stream;
    std::string error;
    if (!stream.open(path.string(), options.compression_level, error)) {
      throw InputError(Located(path, 0, "cannot create the rawlog: " + error));
    }
    auto archive = mrpt::serialization::archiveFrom(stream);
    WriteObjects(sequence, archive, options, summary);
    stream.close();
  } catch (const std::exception& failure) {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
    if (dynamic_cast<const InputError*>(&failure) != nullptr) throw;
    throw InputError(Located(path, 0, std::string("writing the rawlog failed: ") + failure.what()));
  }
  return summary;
}

}  // namespace slamsweep::evaluator::inline formats::inline rawlog
