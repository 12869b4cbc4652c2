#pragma once

#include <string>

#include "slam/common/parameters.h"

namespace slamsweep::slam::hector {

/// hector_mapping's parameter names. Defaults are hector_mapping's, except the map: 0.05 m cells
/// (the evaluation resolution) on 2048 x 2048 cells, so a 100 m building fits around the start, and
/// 4 resolution levels instead of 3: the coarsest 0.4 m level widens the matcher's basin for logs
/// whose scans are a metre apart (intel, 300 scans, 2 % odometry noise, three noise draws: ATE
/// 3.49 / 6.89 / 0.82 m with 4 levels against 3.68 / 8.21 / 2.79 m with 3; odometry 5.47 / 9.82 / 7.72 m).
struct HectorOptions {
  double map_resolution = 0.05;
  int map_size = 2048;
  double map_start_x = 0.5;
  double map_start_y = 0.5;
  int map_multi_res_levels = 4;
  double update_factor_free = 0.4;
  double update_factor_occupied = 0.9;
  double map_update_distance_thresh = 0.4;
  double map_update_angle_thresh = 0.9;
  double laser_min_dist = 0.4;
  double laser_max_dist = 30.0;
  /// Where each scan match starts: "odometry" (the last estimate moved by the odometry since the
  /// last scan) or "previous" (the last estimate, hector_mapping's behaviour without odometry).
  std::string pose_hint = "odometry";
};

HectorOptions ReadHectorOptions(Parameters& parameters);

}  // namespace slamsweep::slam::hector
