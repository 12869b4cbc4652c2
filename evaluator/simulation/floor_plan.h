#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::evaluator::inline simulation {

/// Parameters of a generated office floor: a straight corridor with a row of rooms on each
/// side, one door from every room to the corridor, some doors between neighbouring rooms, and
/// boxes of clutter in the rooms. Lengths are rounded to whole cells.
struct FloorPlanOptions {
  double resolution_m = 0.05;
  int rooms_per_side = 3;
  /// Interior width of a room along the corridor: room_width_m +- room_width_jitter_m.
  double room_width_m = 5.0;
  double room_width_jitter_m = 1.0;
  /// Interior depth of a room away from the corridor: room_depth_m +- room_depth_jitter_m (per side).
  double room_depth_m = 4.0;
  double room_depth_jitter_m = 0.5;
  double corridor_width_m = 2.0;
  double door_width_m = 1.0;
  double wall_thickness_m = 0.15;
  /// Probability that two neighbouring rooms share a door (gives the laser views across rooms).
  double connecting_door_probability = 0.5;
  int clutter_per_room = 3;
  /// Clutter boxes have sides uniform in [clutter_min_size_m, clutter_max_size_m].
  double clutter_min_size_m = 0.3;
  double clutter_max_size_m = 0.8;
  /// Unknown border around the building.
  double margin_m = 1.0;
  std::uint64_t seed = 1;

  bool operator==(const FloorPlanOptions&) const = default;
};

/// An axis-aligned box in world metres.
struct Box {
  double min_x_m = 0.0;
  double min_y_m = 0.0;
  double max_x_m = 0.0;
  double max_y_m = 0.0;
  double CenterXM() const { return 0.5 * (min_x_m + max_x_m); }
  double CenterYM() const { return 0.5 * (min_y_m + max_y_m); }
};

/// A room's free interior, its door to the corridor and a round trip through it that no
/// clutter blocks: enter through the door to tour[0], visit the other points, return to tour[0].
struct Room {
  Box interior;
  /// Centre of the door opening (in the middle of the wall's thickness).
  Eigen::Vector2d door_m = Eigen::Vector2d::Zero();
  /// +1 when the room lies on the +y side of the corridor, -1 otherwise.
  int side = 1;
  std::vector<Eigen::Vector2d> tour_m;
};

/// The generated floor: the map (walls and clutter p = 1, free space inside the building
/// p = 0, the margin around it unknown) and the geometry a path planner needs.
struct FloorPlan {
  OccupancyGrid grid;
  Box corridor;
  std::vector<Room> rooms;
};

/// Throws InputError naming the option unless the rooms, doors and corridor fit together
/// (e.g. a door narrower than its room, positive sizes, a wall at least one cell thick).
void ValidateFloorPlanOptions(const FloorPlanOptions& options);

/// The same options give the same plan, cell for cell, on every machine: only mt19937_64's
/// raw output, integer arithmetic and correctly rounded + - * / are used.
FloorPlan GenerateFloorPlan(const FloorPlanOptions& options);

void to_json(nlohmann::json& out, const FloorPlanOptions& options);
/// Strict reader (unknown or mistyped fields are InputErrors naming `path`.field); missing
/// fields keep their defaults; the result is validated.
FloorPlanOptions FloorPlanOptionsFromJson(const nlohmann::json& in, const std::string& path = "floor_plan");

}  // namespace slamsweep::evaluator::inline simulation
