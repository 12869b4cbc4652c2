#pragma once

#include <map>
#include <string>

#include <lama/pose2d.h>
#include <lama/sdm/frequency_occupancy_map.h>
#include <lama/types.h>

#include "evaluator/core/laser_scan.h"
#include "evaluator/core/occupancy_grid.h"
#include "evaluator/core/pose.h"
#include "evaluator/sequence/robot_log.h"
#include "slam/common/driver_io.h"
#include "slam/common/parameters.h"

// What the LaMa drivers (slam/lama: Slam2D, slam/lama_pf: PFSlam2D) share, the way iris_lama_ros's nodes do it.
namespace slamsweep::slam::lama_driver {

/// The nodes' scan conversion: `mrange` (0 or beyond the scan's maximum range: the scan's maximum range) and
/// `beam_step` (every n-th beam).
struct ScanOptions {
  double mrange = 20.0;
  int beam_step = 1;
};

/// The scan as the nodes give it to LaMa: every beam_step-th beam with a finite range strictly between the
/// scan's minimum range and the maximum range above, as a point in the sensor frame, with the sensor's mount on
/// the robot as the cloud's origin and orientation.
lama::PointCloudXYZ::Ptr LamaCloud(const evaluator::LaserScan& scan, const ScanOptions& options);

/// LaMa's occupancy map as the nodes publish it: the cells of its allocated patches, each free (p = 0),
/// occupied (p = 1) or else unknown, on LaMa's cells; an empty map gives one unknown cell.
evaluator::OccupancyGrid LamaMap(const lama::FrequencyOccupancyMap& map);

/// The end of a LaMa run: the trajectory from the poses at the updates (odometry between them) replaces the one
/// written scan by scan, and the map is the last stage and the final map.
void WriteLamaResult(const evaluator::RobotLog& robot, const std::map<double, evaluator::Pose>& key_poses,
                     const lama::FrequencyOccupancyMap& map, DriverOutputs& outputs);

lama::Pose2D LamaPose(const evaluator::Pose& pose);
evaluator::Pose ToPose(const lama::Pose2D& pose);

/// InputError naming the first shared option out of its range.
void CheckSharedOptions(double resolution, double l2_max, const std::string& strategy,
                        const std::string& compression_algorithm, int patch_size, const ScanOptions& scan);

/// Reads the options both nodes read under the same names (with the offline launch files' values as defaults:
/// d_thresh 0.5, a_thresh 0.5, mrange 20) into LaMa's options (Slam2D::Options or PFSlam2D::Options). The
/// compression algorithm's default differs between the nodes and is given.
template <typename Options>
void ReadSharedOptions(Parameters& parameters, Options& options, ScanOptions& scan,
                       const std::string& compression_algorithm) {
  options.trans_thresh = parameters.Real("d_thresh", 0.5);
  options.rot_thresh = parameters.Real("a_thresh", 0.5);
  options.l2_max = parameters.Real("l2_max", 0.5);
  options.truncated_ray = parameters.Real("truncate", 0.0);
  options.truncated_range = parameters.Real("truncate_range", 0.0);
  options.resolution = parameters.Real("resolution", 0.05);
  options.strategy = parameters.Text("strategy", "gn");
  options.use_compression = parameters.Flag("use_compression", false);
  options.calgorithm = parameters.Text("compression_algorithm", compression_algorithm);
  options.patch_size = static_cast<std::uint32_t>(parameters.Integer("patch_size", 32));
  options.cache_size = static_cast<std::uint32_t>(parameters.Integer("cache_size", 100));
  scan.mrange = parameters.Real("mrange", 20.0);
  scan.beam_step = parameters.Integer("beam_step", 1);
  CheckSharedOptions(options.resolution, options.l2_max, options.strategy, options.calgorithm,
                     static_cast<int>(options.patch_size), scan);
}

}  // namespace slamsweep::slam::lama_driver
