#include "slam/slam_toolbox/node_scan_filter.h"

namespace slamsweep::slam::slam_toolbox_driver {

bool NodeScanFilter::Pass(double stamp_s, double x, double y) {
  ++scan_count_;
  if (first_) {
    first_ = false;
    last_stamp_s_ = stamp_s, last_x_ = x, last_y_ = y;
    return true;
  }
  if (scan_count_ % throttle_scans_ != 0) return false;
  if (stamp_s - last_stamp_s_ < minimum_time_interval_s_) return false;
  // The node allows 20 % of the squared distance for odometry error.
  const double dx = x - last_x_, dy = y - last_y_;
  if (dx * dx + dy * dy < 0.8 * minimum_distance_squared_ || scan_count_ < 5) return false;
  last_stamp_s_ = stamp_s, last_x_ = x, last_y_ = y;
  return true;
}

}  // namespace slamsweep::slam::slam_toolbox_driver
