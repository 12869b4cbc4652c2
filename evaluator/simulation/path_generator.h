#pragma once

#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "evaluator/core/trajectory.h"
#include "evaluator/simulation/floor_plan.h"

namespace slamsweep::evaluator::inline simulation {

/// How the simulated robot moves along a polyline of waypoints: straight at speed_m_per_s;
/// corners of at most max_arc_turn_rad are rounded with arcs of corner_radius_m (when the
/// neighbouring segments are long enough), sharper corners are turned in place at
/// turn_rate_rad_per_s. Poses are sampled at rate_hz, starting at t = 0.
struct PathOptions {
  double speed_m_per_s = 0.5;
  double turn_rate_rad_per_s = 0.8;
  double rate_hz = 10.0;
  double corner_radius_m = 0.4;
  double max_arc_turn_rad = 1.75;

  bool operator==(const PathOptions&) const = default;
};

/// Throws InputError naming the option unless all values are finite and positive.
void ValidatePathOptions(const PathOptions& options);

/// A loop through the floor plan: from the west end of the corridor eastwards, into every room
/// (in order along the corridor) through its door, round its tour and back out, to the east
/// end, and back along the corridor to the start, so that the sequence closes a loop.
std::vector<Eigen::Vector2d> TourWaypoints(const FloorPlan& plan);

/// Poses (z = 0, yaw = direction of travel) sampled along the waypoints. Consecutive duplicate
/// waypoints are ignored; throws InputError when fewer than two distinct waypoints remain or
/// the path would exceed 10 million poses.
Trajectory FollowWaypoints(std::span<const Eigen::Vector2d> waypoints, const PathOptions& options);

void to_json(nlohmann::json& out, const PathOptions& options);
/// Strict reader (see JsonFields); missing fields keep their defaults; validated.
PathOptions PathOptionsFromJson(const nlohmann::json& in, const std::string& path = "path");

}  // namespace slamsweep::evaluator::inline simulation
