#include "evaluator/simulation/floor_plan.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "evaluator/core/input_error.h"
#include "evaluator/noise/json_fields.h"
#include "evaluator/noise/random.h"

namespace slamsweep::evaluator::inline simulation {
namespace {

constexpr float kWall = 1.0f;
constexpr float kFree = 0.0f;
/// Clearance kept between the round trip through a room and any clutter.
constexpr double kPathClearanceM = 0.5;
/// Distance of the first tour point from the door, into the room.
constexpr double kDoorApproachM = 1.0;

void Require(bool ok, const std::string& prefix, const char* option, double value, const std::string& expected) {
  if (!ok) throw InputError(prefix + option + " = " + std::to_string(value) + ", expected " + expected);
}

void CheckOptions(const FloorPlanOptions& o, const std::string& prefix) {
  auto positive = [&](const char* name, double value) {
    Require(std::isfinite(value) && value > 0.0, prefix, name, value, "a finite number > 0");
  };
  auto non_negative = [&](const char* name, double value) {
    Require(std::isfinite(value) && value >= 0.0, prefix, name, value, "a finite number >= 0");
  };
  positive("resolution_m", o.resolution_m);
  Require(o.rooms_per_side >= 1 && o.rooms_per_side <= 100, prefix, "rooms_per_side", o.rooms_per_side, "in [1, 100]");
  positive("room_width_m", o.room_width_m);
  non_negative("room_width_jitter_m", o.room_width_jitter_m);
  positive("room_depth_m", o.room_depth_m);
  non_negative("room_depth_jitter_m", o.room_depth_jitter_m);
  positive("corridor_width_m", o.corridor_width_m);
  positive("door_width_m", o.door_width_m);
  Require(std::isfinite(o.wall_thickness_m) && o.wall_thickness_m >= o.resolution_m, prefix, "wall_thickness_m",
          o.wall_thickness_m, "at least resolution_m (one cell)");
  Require(std::isfinite(o.connecting_door_probability) && o.connecting_door_probability >= 0.0 &&
              o.connecting_door_probability <= 1.0,
          prefix, "connecting_door_probability", o.connecting_door_probability, "a probability in [0, 1]");
  Require(o.clutter_per_room >= 0 && o.clutter_per_room <= 1000, prefix, "clutter_per_room", o.clutter_per_room,
          "in [0, 1000]");
  positive("clutter_min_size_m", o.clutter_min_size_m);
  Require(std::isfinite(o.clutter_max_size_m) && o.clutter_max_size_m >= o.clutter_min_size_m, prefix,
          "clutter_max_size_m", o.clutter_max_size_m, ">= clutter_min_size_m");
  non_negative("margin_m", o.margin_m);
  // The narrowest room must hold its door with 0.3 m on either side and a round trip of at
  // least 1 m across; the shallowest must hold the tour points 1 m and more from the door.
  const double narrowest = o.room_width_m - o.room_width_jitter_m;
  Require(narrowest >= std::max(o.door_width_m + 0.6, 2.5), prefix, "room_width_m - room_width_jitter_m", narrowest,
          ">= max(door_width_m + 0.6, 2.5) m so that doors and the tour fit");
  const double shallowest = o.room_depth_m - o.room_depth_jitter_m;
  Require(shallowest >= std::max(o.door_width_m + 0.6, 2.5), prefix, "room_depth_m - room_depth_jitter_m", shallowest,
          ">= max(door_width_m + 0.6, 2.5) m so that doors and the tour fit");
  Require(o.corridor_width_m >= 1.0, prefix, "corridor_width_m", o.corridor_width_m, ">= 1 m for the robot to pass");
  Require(o.clutter_max_size_m <= std::min(narrowest, shallowest), prefix, "clutter_max_size_m", o.clutter_max_size_m,
          "at most the narrowest room's width and depth");
  // The largest possible plan, checked before anything is rounded to (int) cells.
  const double width_m = 2.0 * o.margin_m +
                         o.rooms_per_side * (o.room_width_m + o.room_width_jitter_m + o.wall_thickness_m) +
                         o.wall_thickness_m;
  const double height_m =
      2.0 * o.margin_m + 2.0 * (o.room_depth_m + o.room_depth_jitter_m) + o.corridor_width_m + 4.0 * o.wall_thickness_m;
  Require((width_m / o.resolution_m) * (height_m / o.resolution_m) <= 2.5e8, prefix, "resolution_m", o.resolution_m,
          "coarse enough for the plan to stay below 250 million cells");
}

// Half-open box of cells [x0, x1) x [y0, y1), y upwards (cell y = 0 is the bottom row).
struct CellBox {
  int x0, y0, x1, y1;
  bool Intersects(const CellBox& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

class Painter {
 public:
  explicit Painter(OccupancyGrid& grid) : grid_(grid) {}
  void Fill(const CellBox& box, float p) {
    for (int y = std::max(0, box.y0); y < std::min(grid_.height, box.y1); ++y) {
      for (int x = std::max(0, box.x0); x < std::min(grid_.width, box.x1); ++x) grid_.at(grid_.height - 1 - y, x) = p;
    }
  }

 private:
  OccupancyGrid& grid_;
};

// Uniform integer in [low, high]; low when the interval is empty.
int UniformInt(RandomEngine& engine, int low, int high) {
  if (high <= low) return low;
  return low + static_cast<int>(UniformIndex(engine, static_cast<std::uint64_t>(high - low) + 1));
}

}  // namespace

void ValidateFloorPlanOptions(const FloorPlanOptions& options) { CheckOptions(options, "floor plan option "); }

FloorPlan GenerateFloorPlan(const FloorPlanOptions& options) {
  ValidateFloorPlanOptions(options);
  const double resolution = options.resolution_m;
  auto to_cells = [&](double metres) { return std::max(1, static_cast<int>(std::lround(metres / resolution))); };
  RandomEngine engine(options.seed);
  auto jittered = [&](double nominal_m, double jitter_m) {
    return to_cells(nominal_m + jitter_m * (2.0 * UniformUnit(engine) - 1.0));
  };

  const int wall = to_cells(options.wall_thickness_m);
  const int corridor = to_cells(options.corridor_width_m);
  const int door = to_cells(options.door_width_m);
  const int margin = static_cast<int>(std::lround(options.margin_m / resolution));
  const int clearance = to_cells(0.3);
  const int rooms = options.rooms_per_side;

  // Side 0 lies below the corridor (-y), side 1 above it (+y).
  int depth[2];
  std::vector<int> widths[2];
  int length[2];
  for (int side = 0; side < 2; ++side) {
    depth[side] = jittered(options.room_depth_m, options.room_depth_jitter_m);
    length[side] = (rooms - 1) * wall;
    for (int i = 0; i < rooms; ++i) {
      widths[side].push_back(jittered(options.room_width_m, options.room_width_jitter_m));
      length[side] += widths[side].back();
    }
  }
  // Both rows span the whole corridor: the last room of the shorter row takes up the slack.
  const int interior_length = std::max(length[0], length[1]);
  for (int side = 0; side < 2; ++side) widths[side].back() += interior_length - length[side];

  const int building_width = 2 * wall + interior_length;
  const int building_height = 4 * wall + depth[0] + corridor + depth[1];
  FloorPlan plan;
  plan.grid = OccupancyGrid(building_width + 2 * margin, building_height + 2 * margin, resolution);
  Painter paint(plan.grid);
  const int left = margin;
  const int bottom = margin;
  paint.Fill({left, bottom, left + building_width, bottom + building_height}, kFree);
  // Outer walls.
  paint.Fill({left, bottom, left + building_width, bottom + wall}, kWall);
  paint.Fill({left, bottom + building_height - wall, left + building_width, bottom + building_height}, kWall);
  paint.Fill({left, bottom, left + wall, bottom + building_height}, kWall);
  paint.Fill({left + building_width - wall, bottom, left + building_width, bottom + building_height}, kWall);

  const int interior_left = left + wall;
  const int room_bottom[2] = {bottom + wall, bottom + 3 * wall + depth[0] + corridor};
  const int corridor_bottom = bottom + 2 * wall + depth[0];
  const int corridor_wall_bottom[2] = {corridor_bottom - wall, corridor_bottom + corridor};
  plan.corridor = Box{interior_left * resolution, corridor_bottom * resolution,
                      (interior_left + interior_length) * resolution, (corridor_bottom + corridor) * resolution};
  for (int side = 0; side < 2; ++side) {
    paint.Fill(
        {interior_left, corridor_wall_bottom[side], interior_left + interior_length, corridor_wall_bottom[side] + wall},
        kWall);
  }

  for (int side = 0; side < 2; ++side) {
    const int y0 = room_bottom[side];
    const int y1 = y0 + depth[side];
    const int direction = side == 0 ? -1 : 1;
    int x0 = interior_left;
    std::vector<CellBox> interiors;
    for (int i = 0; i < rooms; ++i) {
      const int x1 = x0 + widths[side][i];
      interiors.push_back({x0, y0, x1, y1});
      if (i + 1 < rooms) paint.Fill({x1, y0, x1 + wall, y1}, kWall);
      x0 = x1 + wall;
    }
    for (int i = 0; i < rooms; ++i) {
      const CellBox& room = interiors[i];
      // Door to the corridor, anywhere along the room's corridor wall with some clearance.
      const int door_x0 = UniformInt(engine, room.x0 + clearance, room.x1 - clearance - door);
      const int wall_y0 = corridor_wall_bottom[side];
      paint.Fill({door_x0, wall_y0, door_x0 + door, wall_y0 + wall}, kFree);
      // Door to the next room on this side, sometimes.
      if (i + 1 < rooms && UniformUnit(engine) < options.connecting_door_probability) {
        const int door_y0 = UniformInt(engine, room.y0 + clearance, room.y1 - clearance - door);
        paint.Fill({room.x1, door_y0, room.x1 + wall, door_y0 + door}, kFree);
      }

      Room described;
      described.side = direction;
      described.interior = Box{room.x0 * resolution, room.y0 * resolution, room.x1 * resolution, room.y1 * resolution};
      const double door_x_m = (door_x0 + 0.5 * door) * resolution;
      const double wall_inner_y_m = (side == 0 ? wall_y0 : wall_y0 + wall) * resolution;
      described.door_m = Eigen::Vector2d(door_x_m, (wall_y0 + 0.5 * wall) * resolution);
      const double depth_m = depth[side] * resolution;
      const double width_m = widths[side][i] * resolution;
      const double far_y_m = wall_inner_y_m + direction * 0.6 * depth_m;
      described.tour_m = {Eigen::Vector2d(door_x_m, wall_inner_y_m + direction * kDoorApproachM),
                          Eigen::Vector2d(described.interior.min_x_m + 0.25 * width_m, far_y_m),
                          Eigen::Vector2d(described.interior.max_x_m - 0.25 * width_m, far_y_m)};

      // Clutter anywhere in the room except near the round trip and the door.
      double keep_min_x = door_x_m - 0.5 * options.door_width_m, keep_max_x = door_x_m + 0.5 * options.door_width_m;
      double keep_min_y = wall_inner_y_m, keep_max_y = wall_inner_y_m;
      for (const Eigen::Vector2d& point : described.tour_m) {
        keep_min_x = std::min(keep_min_x, point.x());
        keep_max_x = std::max(keep_max_x, point.x());
        keep_min_y = std::min(keep_min_y, point.y());
        keep_max_y = std::max(keep_max_y, point.y());
      }
      const CellBox keep_out{static_cast<int>(std::floor((keep_min_x - kPathClearanceM) / resolution)),
                             static_cast<int>(std::floor((keep_min_y - kPathClearanceM) / resolution)),
                             static_cast<int>(std::ceil((keep_max_x + kPathClearanceM) / resolution)),
                             static_cast<int>(std::ceil((keep_max_y + kPathClearanceM) / resolution))};
      for (int item = 0; item < options.clutter_per_room; ++item) {
        // A bounded number of tries keeps generation finite however crowded the room is.
        for (int attempt = 0; attempt < 30; ++attempt) {
          const int size_x = to_cells(UniformBetween(engine, options.clutter_min_size_m, options.clutter_max_size_m));
          const int size_y = to_cells(UniformBetween(engine, options.clutter_min_size_m, options.clutter_max_size_m));
          const int cx = UniformInt(engine, room.x0, room.x1 - size_x);
          const int cy = UniformInt(engine, room.y0, room.y1 - size_y);
          const CellBox box{cx, cy, cx + size_x, cy + size_y};
          if (box.Intersects(keep_out) || box.x1 > room.x1 || box.y1 > room.y1) continue;
          paint.Fill(box, kWall);
          break;
        }
      }
      plan.rooms.push_back(std::move(described));
    }
  }
  return plan;
}

void to_json(nlohmann::json& out, const FloorPlanOptions& o) {
  out = nlohmann::json{{"resolution_m", o.resolution_m},
                       {"rooms_per_side", o.rooms_per_side},
                       {"room_width_m", o.room_width_m},
                       {"room_width_jitter_m", o.room_width_jitter_m},
                       {"room_depth_m", o.room_depth_m},
                       {"room_depth_jitter_m", o.room_depth_jitter_m},
                       {"corridor_width_m", o.corridor_width_m},
                       {"door_width_m", o.door_width_m},
                       {"wall_thickness_m", o.wall_thickness_m},
                       {"connecting_door_probability", o.connecting_door_probability},
                       {"clutter_per_room", o.clutter_per_room},
                       {"clutter_min_size_m", o.clutter_min_size_m},
                       {"clutter_max_size_m", o.clutter_max_size_m},
                       {"margin_m", o.margin_m},
                       {"seed", o.seed}};
}

FloorPlanOptions FloorPlanOptionsFromJson(const nlohmann::json& in, const std::string& path) {
  JsonFields fields(in, path);
  FloorPlanOptions o;
  o.resolution_m = fields.Number("resolution_m", o.resolution_m);
  o.rooms_per_side = fields.Integer("rooms_per_side", o.rooms_per_side);
  o.room_width_m = fields.Number("room_width_m", o.room_width_m);
  o.room_width_jitter_m = fields.Number("room_width_jitter_m", o.room_width_jitter_m);
  o.room_depth_m = fields.Number("room_depth_m", o.room_depth_m);
  o.room_depth_jitter_m = fields.Number("room_depth_jitter_m", o.room_depth_jitter_m);
  o.corridor_width_m = fields.Number("corridor_width_m", o.corridor_width_m);
  o.door_width_m = fields.Number("door_width_m", o.door_width_m);
  o.wall_thickness_m = fields.Number("wall_thickness_m", o.wall_thickness_m);
  o.connecting_door_probability = fields.Number("connecting_door_probability", o.connecting_door_probability);
  o.clutter_per_room = fields.Integer("clutter_per_room", o.clutter_per_room);
  o.clutter_min_size_m = fields.Number("clutter_min_size_m", o.clutter_min_size_m);
  o.clutter_max_size_m = fields.Number("clutter_max_size_m", o.clutter_max_size_m);
  o.margin_m = fields.Number("margin_m", o.margin_m);
  o.seed = fields.Unsigned("seed", o.seed);
  fields.Finish();
  CheckOptions(o, path + ".");
  return o;
}

}  // namespace slamsweep::evaluator::inline simulation
