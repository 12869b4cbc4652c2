#include "evaluator/borders/vector_map.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <span>
#include <string>
#include <utility>

#include "evaluator/borders/border_tracing.h"
#include "evaluator/borders/polygon_simplify.h"
#include "evaluator/borders/threshold.h"
#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline borders {
namespace {

constexpr std::size_t kCoordinateBytes = 4;  // float32, as the handout counts
constexpr std::size_t kCountBytes = 4;       // one int32 vertex count per polygon
constexpr std::size_t kRasterCellBytes = 4;  // one float per cell

// Length of the closed walk through the cells, in cells.
double TracedLengthCells(const Border& border) {
  std::size_t straight = 0;
  std::size_t diagonal = 0;
  if (border.cells.empty()) return 0.0;
  const GridCell* a = &border.cells.back();  // the closing step first, so no modulo in the loop
  for (const GridCell& b : border.cells) {
    if (a->x != b.x && a->y != b.y) {
      ++diagonal;
    } else {
      ++straight;
    }
    a = &b;
  }
  return static_cast<double>(straight) + std::numbers::sqrt2 * static_cast<double>(diagonal);
}

// The border cells Douglas-Peucker could keep, as points in cells. A cell strictly inside a
// straight run (the same step into and out of it) is never kept: the distance to a segment is
// convex along a line, so every chain's farthest point -- first one on ties -- is a run end,
// and the anchors (farthest from cell 0, then from that one) are run ends by strict convexity.
// Leaving those cells out gives the same polygon with far less work on long walls. Cell 0
// always stays, because the anchors are measured from it.
void ListSimplificationCandidates(const Border& border, std::vector<PlanarPoint>& points) {
  points.clear();
  const std::vector<GridCell>& cells = border.cells;
  const std::size_t n = cells.size();
  for (std::size_t i = 0; i < n; ++i) {
    const GridCell& cell = cells[i];
    if (i != 0 && n >= 3) {
      const GridCell& before = cells[i - 1];
      const GridCell& after = cells[i + 1 == n ? 0 : i + 1];
      if (cell.x - before.x == after.x - cell.x && cell.y - before.y == after.y - cell.y) continue;
    }
    points.push_back({static_cast<double>(cell.x), static_cast<double>(cell.y)});
  }
}

double RequireNumber(const nlohmann::json& value, const std::string& key) {
  if (!value.is_number()) {
    throw InputError(fmt::format("option {}: expected a number, got {}", key, value.dump()));
  }
  return value.get<double>();
}

}  // namespace

void ValidateVectorizeOptions(const VectorizeOptions& options) {
  if (!std::isfinite(options.threshold) || options.threshold < 0.0 || options.threshold > 100.0) {
    throw InputError(
        fmt::format("option threshold: expected a number in [0, 100] (occupancy scale), got {}", options.threshold));
  }
  if (!std::isfinite(options.simplify_tolerance_cells) || options.simplify_tolerance_cells < 0.0) {
    throw InputError(fmt::format("option simplify_tolerance_cells: expected a finite number >= 0, got {}",
                                 options.simplify_tolerance_cells));
  }
}

void to_json(nlohmann::json& out, const VectorizeOptions& options) {
  out =
      nlohmann::json{{"threshold", options.threshold}, {"simplify_tolerance_cells", options.simplify_tolerance_cells}};
}

void from_json(const nlohmann::json& in, VectorizeOptions& options) {
  if (!in.is_object()) throw InputError("vectorize options: expected an object, got " + in.dump());
  VectorizeOptions parsed;
  for (const auto& [key, value] : in.items()) {
    if (key == "threshold") {
      parsed.threshold = RequireNumber(value, key);
    } else if (key == "simplify_tolerance_cells") {
      parsed.simplify_tolerance_cells = RequireNumber(value, key);
    } else {
      throw InputError("vectorize options: unknown key '" + key + "' (expected threshold, simplify_tolerance_cells)");
    }
  }
  ValidateVectorizeOptions(parsed);
  options = parsed;
}

nlohmann::json VectorMap::StatsJson() const {
  return nlohmann::json{
      {"metric", "vector_map"},
      {"options", options},
      {"obstacle_count", obstacle_count},
      {"hole_count", hole_count},
      {"border_count", polygons.size()},
      {"border_length_m", border_length_m},
      {"border_length_definition", "traced border before simplification, 1 or sqrt(2) cells per step"},
      {"vertex_count", vertex_count},
      {"raster_bytes", raster_bytes},
      {"vector_bytes", vector_bytes},
      {"isolated_cell_count", isolated_cell_count},
  };
}

VectorMap Vectorize(const OccupancyGrid& grid, const VectorizeOptions& options) {
  ValidateVectorizeOptions(options);
  if (!std::isfinite(grid.resolution_m) || grid.resolution_m <= 0.0) {
    throw InputError(
        fmt::format("occupancy grid: resolution must be a positive number of m/cell, got {}", grid.resolution_m));
  }
  BorderTracing tracing = TraceBorders(Threshold(grid, options.threshold));

  VectorMap map;
  map.options = options;
  map.resolution_m = grid.resolution_m;
  map.bounds = {grid.origin.x_m, grid.origin.y_m, grid.origin.x_m + grid.width * grid.resolution_m,
                grid.origin.y_m + grid.height * grid.resolution_m};
  map.isolated_cell_count = tracing.erased_cell_count;
  map.raster_bytes = grid.CellCount() * kRasterCellBytes;
  map.polygons.reserve(tracing.borders.size());
  std::vector<PlanarPoint> points;
  RingSimplifier simplifier;
  for (const Border& border : tracing.borders) {
    ListSimplificationCandidates(border, points);
    Polygon polygon;
    polygon.kind = TwiceSignedAreaCells2(border) >= 0 ? BorderKind::kOuter : BorderKind::kHole;
    polygon.traced_cell_count = border.cells.size();
    polygon.border_length_m = TracedLengthCells(border) * grid.resolution_m;
    const std::span<const std::size_t> kept = simplifier.Simplify(points, options.simplify_tolerance_cells);
    polygon.vertices.reserve(kept.size());
    for (const std::size_t i : kept) {
      const int x = static_cast<int>(points[i].x);
      const int y = static_cast<int>(points[i].y);
      polygon.vertices.push_back({grid.CellCenterXM(x), grid.CellCenterYM(grid.height - 1 - y)});
    }
    (polygon.kind == BorderKind::kOuter ? map.obstacle_count : map.hole_count) += 1;
    map.border_length_m += polygon.border_length_m;
    map.vertex_count += polygon.vertices.size();
    map.polygons.push_back(std::move(polygon));
  }
  map.vector_bytes = map.vertex_count * 2 * kCoordinateBytes + map.polygons.size() * kCountBytes;
  return map;
}

}  // namespace slamsweep::evaluator::inline borders
