#pragma once

namespace slamsweep::slam::slam_toolbox_driver {

/// slam_toolbox's node decides which scans reach Karto's Mapper (SlamToolbox::shouldProcessScan), and the
/// driver decides the same way: the first scan passes; every later scan counts, and passes only when it is
/// the throttle_scans-th, at least minimum_time_interval seconds after the last scan that passed, at least
/// sqrt(0.8) * minimum_travel_distance from it by odometry, and not among the first four scans. Only the
/// distance is tested (a turn on the spot never passes); the Mapper then applies its own test (travel or turn).
class NodeScanFilter {
 public:
  NodeScanFilter(double minimum_travel_distance, double minimum_time_interval_s, int throttle_scans)
      : minimum_distance_squared_(minimum_travel_distance * minimum_travel_distance),
        minimum_time_interval_s_(minimum_time_interval_s),
        throttle_scans_(throttle_scans) {}

  /// Whether the scan at `stamp_s`, taken with the robot at (x, y) by odometry, is handed to the Mapper.
  bool Pass(double stamp_s, double x, double y);

 private:
  double minimum_distance_squared_;
  double minimum_time_interval_s_;
  int throttle_scans_;
  int scan_count_ = 0;
  bool first_ = true;
  double last_stamp_s_ = 0.0;
  double last_x_ = 0.0;
  double last_y_ = 0.0;
};

}  // namespace slamsweep::slam::slam_toolbox_driver
