#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <vector>

#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::evaluator::inline borders {

/// Options of Vectorize (handout steps 1-3). Defaults: the handout's strictest threshold and
/// a one-cell simplification tolerance (removes the staircase of diagonal walls).
struct VectorizeOptions {
  double threshold = 75;                  ///< Obstacle when p * 100 > threshold; in [0, 100].
  double simplify_tolerance_cells = 1.0;  ///< Douglas-Peucker tolerance in cells; finite, >= 0.
};

/// Throws InputError naming the option when a field is out of range.
void ValidateVectorizeOptions(const VectorizeOptions& options);
/// JSON keys "threshold" and "simplify_tolerance_cells"; both optional on read (defaults
/// above), any other key is an InputError so that a typo in a config cannot pass silently.
void to_json(nlohmann::json& out, const VectorizeOptions& options);
void from_json(const nlohmann::json& in, VectorizeOptions& options);

/// A point in world coordinates (metres).
struct PointM {
  double x_m = 0.0;
  double y_m = 0.0;
  friend bool operator==(const PointM&, const PointM&) = default;
};

/// Outer borders run counter-clockwise around an obstacle, hole borders clockwise inside one.
enum class BorderKind { kOuter, kHole };

/// One traced border as a simplified polygon.
struct Polygon {
  BorderKind kind = BorderKind::kOuter;
  /// Simplified ring in traced order (orientation kept), closing vertex not repeated; each
  /// vertex is a border cell's centre (OccupancyGrid::CellCenterXM / CellCenterYM).
  std::vector<PointM> vertices;
  std::size_t traced_cell_count = 0;  ///< Cells of the traced border (with repeats).
  double border_length_m = 0.0;       ///< Traced length, see VectorMap::border_length_m.
};

/// Extent of the grid in world metres (cell edges, not centres).
struct WorldBoundsM {
  double min_x_m = 0.0;
  double min_y_m = 0.0;
  double max_x_m = 0.0;
  double max_y_m = 0.0;
};

/// An occupancy grid's obstacle borders as polygons, with the handout's storage comparison.
struct VectorMap {
  VectorizeOptions options;  ///< The specification these numbers were computed under.
  double resolution_m = 0.0;
  WorldBoundsM bounds;
  std::vector<Polygon> polygons;  ///< One per traced border, in scan order.
  /// Number of outer borders: traced borders whose cell ring has a signed (shoelace) area
  /// >= 0 in the Y-up frame. The trace keeps the obstacle on its left, so an obstacle's outer
  /// border is counter-clockwise (> 0) and a hole's border clockwise (< 0); a one-cell-wide
  /// obstacle encloses no area (0) and still counts. Isolated single cells are erased by the
  /// handout's trace and are not obstacles; objects lying on row Y = 0 only are never traced.
  std::size_t obstacle_count = 0;
  std::size_t hole_count = 0;  ///< Traced borders with negative signed area.
  /// Sum over all borders (outer and hole) of the length of the TRACED border, BEFORE
  /// simplification, in metres: the closed walk through the border cells' centres, 1 cell per
  /// straight step and sqrt(2) per diagonal step, times the resolution. Independent of the
  /// simplification tolerance; a one-cell-wide wall counts twice (the trace walks both faces).
  double border_length_m = 0.0;
  std::size_t vertex_count = 0;         ///< Vertices of all simplified polygons (closing vertex not counted).
  std::size_t raster_bytes = 0;         ///< Handout: cells * 4 (a float grid).
  std::size_t vector_bytes = 0;         ///< Handout: vertex_count * 2 * 4 + 4 per polygon (a count).
  std::size_t isolated_cell_count = 0;  ///< Single obstacle cells the trace erased.

  /// The derived numbers with the options they were computed under (no polygons).
  nlohmann::json StatsJson() const;
};

/// Handout steps 1-3: threshold the grid, trace every border, simplify each into a polygon in
/// world metres. Throws InputError for invalid options, a grid whose cell count is not
/// width * height, or a resolution that is not a positive number. Origin yaw is ignored, as in
/// OccupancyGrid::CellCenterXM.
VectorMap Vectorize(const OccupancyGrid& grid, const VectorizeOptions& options);

}  // namespace slamsweep::evaluator::inline borders
