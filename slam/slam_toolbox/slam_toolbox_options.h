#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include <karto_sdk/Mapper.h>

#include "slam/common/parameters.h"

namespace slamsweep::slam::slam_toolbox_driver {

/// What slam_toolbox's offline node (launch/offline_launch.py: the synchronous node with
/// config/mapper_params_offline.yaml) gives Karto, its Ceres solver and its own scan filter, by the file's names.
/// Every default is the file's value; the file's keys that change nothing in a run (frames, topics, publishing
/// periods, interactive mode, the map saver) are not parameters.
struct SlamToolboxOptions {
  /// Every Mapper parameter of the file, each applied through Mapper's setter as the node does (three of them,
  /// loop_match_maximum_variance_coarse, distance_variance_penalty and angle_variance_penalty, square the value).
  std::vector<std::function<void(karto::Mapper&)>> mapper_settings;
  /// The node's scan filter: a scan is handed to the Mapper after the robot moved 0.8 * minimum_travel_distance
  /// (Mapper's value) and minimum_time_interval seconds passed since the last one handed over; throttle_scans
  /// keeps every n-th scan.
  double minimum_travel_distance = 0.5;
  double minimum_time_interval_s = 0.5;
  int throttle_scans = 1;
  /// The laser's range threshold: max_laser_range, at most the scan's own maximum range.
  double max_laser_range_m = 20.0;
  /// The occupancy grid's cell size (the node's `resolution`).
  double resolution_m = 0.05;
  /// The ceres_* parameters (and debug_logging), as the node holds them for the solver to declare and read.
  std::map<std::string, std::string> solver_parameters;
};

SlamToolboxOptions ReadSlamToolboxOptions(Parameters& parameters);

}  // namespace slamsweep::slam::slam_toolbox_driver
