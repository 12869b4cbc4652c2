#include "slam/hector/hector_options.h"

#include "evaluator/core/input_error.h"

namespace slamsweep::slam::hector {

HectorOptions ReadHectorOptions(Parameters& parameters) {
  HectorOptions o;
  o.map_resolution = parameters.Real("map_resolution", o.map_resolution);
  o.map_size = parameters.Integer("map_size", o.map_size);
  o.map_start_x = parameters.Real("map_start_x", o.map_start_x);
  o.map_start_y = parameters.Real("map_start_y", o.map_start_y);
  o.map_multi_res_levels = parameters.Integer("map_multi_res_levels", o.map_multi_res_levels);
  o.update_factor_free = parameters.Real("update_factor_free", o.update_factor_free);
  o.update_factor_occupied = parameters.Real("update_factor_occupied", o.update_factor_occupied);
  o.map_update_distance_thresh = parameters.Real("map_update_distance_thresh", o.map_update_distance_thresh);
  o.map_update_angle_thresh = parameters.Real("map_update_angle_thresh", o.map_update_angle_thresh);
  o.laser_min_dist = parameters.Real("laser_min_dist", o.laser_min_dist);
  o.laser_max_dist = parameters.Real("laser_max_dist", o.laser_max_dist);
  o.pose_hint = parameters.Text("pose_hint", o.pose_hint);
  if (!(o.map_resolution > 0)) throw evaluator::InputError("parameter map_resolution: expected a value > 0");
  if (o.map_size < 16) throw evaluator::InputError("parameter map_size: expected at least 16 cells");
  if (o.map_multi_res_levels < 1) throw evaluator::InputError("parameter map_multi_res_levels: expected at least 1");
  if (o.pose_hint != "odometry" && o.pose_hint != "previous") {
    throw evaluator::InputError("parameter pose_hint: expected odometry or previous, got '" + o.pose_hint + "'");
  }
  return o;
}

}  // namespace slamsweep::slam::hector
