#include "evaluator/simulation/path_generator.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "evaluator/core/input_error.h"
#include "evaluator/noise/json_fields.h"

namespace slamsweep::evaluator::inline simulation {
namespace {

constexpr double kMaxPoses = 1e7;

void CheckOptions(const PathOptions& o, const std::string& prefix) {
  auto positive = [&](const char* name, double value) {
    if (!(std::isfinite(value) && value > 0.0)) {
      throw InputError(prefix + name + " = " + std::to_string(value) + ", expected a finite number > 0");
    }
  };
  positive("speed_m_per_s", o.speed_m_per_s);
  positive("turn_rate_rad_per_s", o.turn_rate_rad_per_s);
  positive("rate_hz", o.rate_hz);
  positive("corner_radius_m", o.corner_radius_m);
  positive("max_arc_turn_rad", o.max_arc_turn_rad);
}

// One piece of motion, lasting duration_s; Evaluate(s) gives the pose at fraction s in [0, 1].
struct Motion {
  enum class Kind { kLine, kArc, kTurn } kind;
  Eigen::Vector2d start;   // line start, arc centre, turn position
  double heading_rad;      // heading at the start
  double length_or_sweep;  // line length (m), or signed arc/turn angle (rad)
  double radius_m;         // arcs only
  double duration_s;

  Pose Evaluate(double s) const {
    switch (kind) {
      case Kind::kLine: {
        const Eigen::Vector2d p =
            start + s * length_or_sweep * Eigen::Vector2d(std::cos(heading_rad), std::sin(heading_rad));
        return Pose::Planar(p.x(), p.y(), heading_rad);
      }
      case Kind::kArc: {
        // Left turns (positive sweep) circle the centre counter-clockwise; the robot sits at
        // angle heading - pi/2 from the centre (heading + pi/2 for right turns).
        const double heading = heading_rad + s * length_or_sweep;
        const double around = heading + (length_or_sweep > 0.0 ? -0.5 : 0.5) * std::numbers::pi;
        return Pose::Planar(start.x() + radius_m * std::cos(around), start.y() + radius_m * std::sin(around),
                            NormalizeAngleRad(heading));
      }
      case Kind::kTurn:
        return Pose::Planar(start.x(), start.y(), NormalizeAngleRad(heading_rad + s * length_or_sweep));
    }
    return Pose();
  }
};

}  // namespace

void ValidatePathOptions(const PathOptions& options) { CheckOptions(options, "path option "); }

std::vector<Eigen::Vector2d> TourWaypoints(const FloorPlan& plan) {
  const double corridor_y = plan.corridor.CenterYM();
  const double start_x = plan.corridor.min_x_m + std::min(1.0, 0.25 * (plan.corridor.max_x_m - plan.corridor.min_x_m));
  const double end_x = plan.corridor.max_x_m - std::min(1.0, 0.25 * (plan.corridor.max_x_m - plan.corridor.min_x_m));
  std::vector<const Room*> rooms;
  for (const Room& room : plan.rooms) rooms.push_back(&room);
  std::stable_sort(rooms.begin(), rooms.end(),
                   [](const Room* a, const Room* b) { return a->door_m.x() < b->door_m.x(); });

  std::vector<Eigen::Vector2d> waypoints = {{start_x, corridor_y}};
  for (const Room* room : rooms) {
    const Eigen::Vector2d in_corridor(room->door_m.x(), corridor_y);
    waypoints.push_back(in_corridor);
    for (const Eigen::Vector2d& point : room->tour_m) waypoints.push_back(point);
    if (!room->tour_m.empty()) waypoints.push_back(room->tour_m.front());
    waypoints.push_back(in_corridor);
  }
  waypoints.push_back({end_x, corridor_y});
  waypoints.push_back({start_x, corridor_y});
  return waypoints;
}

Trajectory FollowWaypoints(std::span<const Eigen::Vector2d> waypoints, const PathOptions& options) {
  ValidatePathOptions(options);
  std::vector<Eigen::Vector2d> points;
  for (const Eigen::Vector2d& point : waypoints) {
    if (!point.allFinite()) throw InputError("waypoint " + std::to_string(points.size()) + " is not finite");
    if (points.empty() || (point - points.back()).norm() > 1e-9) points.push_back(point);
  }
  if (points.size() < 2)
    throw InputError("a path needs at least two distinct waypoints, got " + std::to_string(points.size()));

  const std::size_t segments = points.size() - 1;
  std::vector<double> length(segments), heading(segments);
  for (std::size_t i = 0; i < segments; ++i) {
    const Eigen::Vector2d d = points[i + 1] - points[i];
    length[i] = d.norm();
    heading[i] = std::atan2(d.y(), d.x());
  }
  // Per corner (between segment i-1 and i): the signed turn and whether it is an arc, whose
  // tangent length is taken from both neighbouring segments.
  std::vector<double> turn(segments, 0.0), tangent(segments, 0.0);
  for (std::size_t i = 1; i < segments; ++i) {
    turn[i] = NormalizeAngleRad(heading[i] - heading[i - 1]);
    const double needed = options.corner_radius_m * std::tan(0.5 * std::abs(turn[i]));
    if (std::abs(turn[i]) <= options.max_arc_turn_rad && needed <= 0.5 * std::min(length[i - 1], length[i])) {
      tangent[i] = needed;
    }
  }

  std::vector<Motion> motions;
  for (std::size_t i = 0; i < segments; ++i) {
    const Eigen::Vector2d direction(std::cos(heading[i]), std::sin(heading[i]));
    if (i > 0 && std::abs(turn[i]) > 1e-12) {
      if (tangent[i] > 0.0) {
        const double sweep = turn[i];
        const Eigen::Vector2d previous(std::cos(heading[i - 1]), std::sin(heading[i - 1]));
        const Eigen::Vector2d arc_start = points[i] - tangent[i] * previous;
        const Eigen::Vector2d normal =
            sweep > 0.0 ? Eigen::Vector2d(-previous.y(), previous.x()) : Eigen::Vector2d(previous.y(), -previous.x());
        const Eigen::Vector2d centre = arc_start + options.corner_radius_m * normal;
        motions.push_back({Motion::Kind::kArc, centre, heading[i - 1], sweep, options.corner_radius_m,
                           options.corner_radius_m * std::abs(sweep) / options.speed_m_per_s});
      } else {
        motions.push_back({Motion::Kind::kTurn, points[i], heading[i - 1], turn[i], 0.0,
                           std::abs(turn[i]) / options.turn_rate_rad_per_s});
      }
    }
    const double trim_start = tangent[i];
    const double trim_end = i + 1 < segments ? tangent[i + 1] : 0.0;
    const double line_length = length[i] - trim_start - trim_end;
    if (line_length > 0.0) {
      motions.push_back({Motion::Kind::kLine, points[i] + trim_start * direction, heading[i], line_length, 0.0,
                         line_length / options.speed_m_per_s});
    }
  }

  if (motions.empty()) throw InputError("the waypoints describe no motion");
  double total_s = 0.0;
  for (const Motion& motion : motions) total_s += motion.duration_s;
  const double pose_count = std::floor(total_s * options.rate_hz) + 1.0;
  if (!(pose_count <= kMaxPoses)) {
    throw InputError("the path would take " + std::to_string(total_s) + " s, more than 10 million poses at " +
                     std::to_string(options.rate_hz) + " Hz");
  }
  Trajectory trajectory;
  trajectory.Reserve(static_cast<std::size_t>(pose_count));
  std::size_t current = 0;
  double motion_start_s = 0.0;
  for (std::size_t k = 0; k < static_cast<std::size_t>(pose_count); ++k) {
    const double t = static_cast<double>(k) / options.rate_hz;
    while (current + 1 < motions.size() && t > motion_start_s + motions[current].duration_s) {
      motion_start_s += motions[current].duration_s;
      ++current;
    }
    const Motion& motion = motions[current];
    const double fraction =
        motion.duration_s > 0.0 ? std::clamp((t - motion_start_s) / motion.duration_s, 0.0, 1.0) : 1.0;
    trajectory.Add(t, motion.Evaluate(fraction));
  }
  return trajectory;
}

void to_json(nlohmann::json& out, const PathOptions& o) {
  out = nlohmann::json{{"speed_m_per_s", o.speed_m_per_s},
                       {"turn_rate_rad_per_s", o.turn_rate_rad_per_s},
                       {"rate_hz", o.rate_hz},
                       {"corner_radius_m", o.corner_radius_m},
                       {"max_arc_turn_rad", o.max_arc_turn_rad}};
}

PathOptions PathOptionsFromJson(const nlohmann::json& in, const std::string& path) {
  JsonFields fields(in, path);
  PathOptions o;
  o.speed_m_per_s = fields.Number("speed_m_per_s", o.speed_m_per_s);
  o.turn_rate_rad_per_s = fields.Number("turn_rate_rad_per_s", o.turn_rate_rad_per_s);
  o.rate_hz = fields.Number("rate_hz", o.rate_hz);
  o.corner_radius_m = fields.Number("corner_radius_m", o.corner_radius_m);
  o.max_arc_turn_rad = fields.Number("max_arc_turn_rad", o.max_arc_turn_rad);
  fields.Finish();
  CheckOptions(o, path + ".");
  return o;
}

}  // namespace slamsweep::evaluator::inline simulation
