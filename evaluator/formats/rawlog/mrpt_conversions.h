#pragma once

// Conversions between slamsweep's value types and MRPT's observation classes. Used by the rawlog
// reader and writer only; the rest of slamsweep never sees an MRPT type.

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <string>

#include "evaluator/core/laser_scan.h"
#include "evaluator/core/pose.h"

namespace slamsweep::evaluator::inline formats::inline rawlog::internal {

mrpt::poses::CPose3D ToMrptPose3D(const Pose& pose);
Pose FromMrptPose3D(const mrpt::poses::CPose3D& pose);
/// x, y and yaw of a planar pose.
mrpt::poses::CPose2D ToMrptPose2D(const Pose& pose);
Pose FromMrptPose2D(const mrpt::poses::CPose2D& pose);

/// MRPT spreads the beams of a 2D scan symmetrically about the sensor's x axis: beam i at
/// -aperture/2 + i * aperture/(n-1) (rightToLeft), or the mirror image. A slamsweep fan may start
/// anywhere (CARMEN's 180-beam fan ends at +89 deg), so the fan's centre direction is folded into
/// the sensor pose: the beam directions on the robot are the same, only the sensor frame turns.
/// Invalid ranges are the beams that LaserScan::IsHit rejects. Needs at least 2 beams.
/// The scan's stamp becomes the observation's timestamp (mrpt::Clock::fromDouble).
mrpt::obs::CObservation2DRangeScan::Ptr ToMrptScan(const LaserScan& scan, const std::string& sensor_label,
                                                   float range_std_m);

/// The inverse: the sensor pose keeps MRPT's symmetric frame (angle_min = -aperture/2, or +aperture/2
/// for a clockwise scan). A range marked invalid that would read as a hit becomes range_max_m, the
/// "no return" convention of LaserScan (other invalid ranges keep their value); range_min_m is 0 (MRPT states none);
/// stamp_s = mrpt::Clock::toDouble(timestamp). Needs at least 2 beams.
LaserScan FromMrptScan(const mrpt::obs::CObservation2DRangeScan& scan);

}  // namespace slamsweep::evaluator::inline formats::inline rawlog::internal
