-- slamsweep's starting point for Cartographer on a planar laser with wheel odometry: upstream's
-- map_builder.lua and trajectory_builder.lua, switched to 2D the way cartographer_ros's 2D demo
-- configurations do it. Any option can be overridden from a sweep by its path in `options`, e.g.
-- trajectory_builder.trajectory_builder_2d.max_range=25 or map_builder.pose_graph.optimize_every_n_nodes=30.
include "map_builder.lua"
include "trajectory_builder.lua"

MAP_BUILDER.use_trajectory_builder_2d = true
-- One background thread: constraint search and optimisation still run beside the scans, but on
-- one core, as the sweep gives every run.
MAP_BUILDER.num_background_threads = 1

-- The driver derives a yaw-rate "IMU" from the wheel odometry (cartographer_main.cc says why).
TRAJECTORY_BUILDER_2D.use_imu_data = true
TRAJECTORY_BUILDER_2D.num_accumulated_range_data = 1
-- Logs like intel's have scans a metre apart: match every one, with the correlative matcher to
-- find the pose before the Ceres refinement (as the 2D demos without IMU do).
TRAJECTORY_BUILDER_2D.use_online_correlative_scan_matching = true
TRAJECTORY_BUILDER_2D.motion_filter.max_angle_radians = math.rad(0.1)
POSE_GRAPH.optimize_every_n_nodes = 30

options = {
  map_builder = MAP_BUILDER,
  trajectory_builder = TRAJECTORY_BUILDER,
}
