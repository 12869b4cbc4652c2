#pragma once

// Maps side by side at one scale: every panel of a table shows the same world window with the same
// metres per pixel, whatever the cell size of each map, so a broken map and a good one differ at a glance.
#include <optional>

#include <opencv2/core.hpp>

#include "evaluator/core/occupancy_grid.h"
#include "report/images/map_comparison_types.h"

namespace slamsweep::report::inline images {

/// An axis-aligned rectangle of the common frame, metres.
struct WorldWindow {
  double min_x = 0.0, min_y = 0.0, max_x = 0.0, max_y = 0.0;
  double Width() const { return max_x - min_x; }
  double Height() const { return max_y - min_y; }
  WorldWindow Union(const WorldWindow& other) const;
};

/// The pixels of every panel: `window` drawn at `metres_per_pixel`, width_px x height_px.
struct PanelGeometry {
  WorldWindow window;
  double metres_per_pixel = 1.0;
  int width_px = 1;
  int height_px = 1;
};

/// The bounding box of the known cells of `grid` placed by `placement` (cell corners), or nothing
/// when the grid has no known cell.
std::optional<WorldWindow> KnownExtent(const evaluator::OccupancyGrid& grid, const MapPlacement& placement);

/// The known part of `grid` with one cell to spare (evaluator KnownCellsWindow and CropGrid), so that the
/// steps below touch the map's cells, not its unknown padding. When the map will be brought to
/// `later_resolution_m` cells (a whole multiple or fraction of its own), the crop's lower-left corner stays on
/// that coarser lattice of the uncropped map, so the cells merged are the ones the map scores merged; for any
/// other ratio the grid is returned whole. A grid without a known cell is returned whole.
evaluator::OccupancyGrid KnownPart(evaluator::OccupancyGrid grid, double later_resolution_m);

/// `window` widened by `margin_fraction` of its longer side on each side, drawn so that its longer side
/// is `max_side_px` pixels: one metres-per-pixel for every panel of the window. Throws InputError for an
/// empty window or max_side_px < 1.
PanelGeometry ChoosePanelGeometry(const WorldWindow& window, int max_side_px, double margin_fraction = 0.03);

/// The map as a grey image of the panel (map_saver's greys: free white, occupied black, p as
/// 255 (1 - p), unknown and outside the map 205). Each pixel shows the cell under its centre after the map
/// is brought to the panel's metres per pixel keeping the highest probability of the cells merged, so a
/// one-cell wall stays visible on a coarse panel.
cv::Mat RenderMapPanel(const evaluator::OccupancyGrid& grid, const MapPlacement& placement, const PanelGeometry& panel);

/// Classes of a difference image, in drawing priority (a coarse pixel shows the highest class it covers).
enum WallClass : unsigned char {
  kWallUnknown = 0,
  kWallFree = 1,
  kWallBoth = 2,
  kWallRunOnly = 3,
  kWallReferenceOnly = 4
};

/// The run's walls against the reference's, on the reference's cell lattice (the run's map brought to
/// the reference's cell size as the scores do: evaluator ResampleToResolution, then the cell under each
/// reference cell's centre). `classes` covers both maps (CV_8U WallClass, row 0 at the top); its lower-left
/// corner is (origin_x_m, origin_y_m) in the reference's frame.
struct WallDifference {
  cv::Mat classes;
  double origin_x_m = 0.0;
  double origin_y_m = 0.0;
  double resolution_m = 0.0;
  WallCounts counts;
};

/// Occupied (p >= occupied_threshold) cells of the placed run and of the reference: a cell occupied in
/// one with an occupied cell of the other within match_radius_cells (Euclidean, in reference cells) is in
/// both, else only in its own map; other cells are free when free in either map (p <= free_threshold),
/// else unknown. Throws InputError for a reference with resolution_m <= 0.
WallDifference CompareWalls(const evaluator::OccupancyGrid& run, const MapPlacement& placement,
                            const evaluator::OccupancyGrid& reference, const WallMatchOptions& options);

/// Colours of the difference image (B, G, R): walls only in the run blue (#0072B2), only in the reference
/// vermillion (#D55E00), in both black; free white, unknown light grey.
inline constexpr unsigned char kRunOnlyBgr[3] = {0xB2, 0x72, 0x00};
inline constexpr unsigned char kReferenceOnlyBgr[3] = {0x00, 0x5E, 0xD5};
inline constexpr unsigned char kBothBgr[3] = {0x00, 0x00, 0x00};

/// The difference as a colour image of the panel: each pixel the highest class among the cells its
/// footprint covers (a pixel of several cells keeps a lone wall), by WallClass priority.
cv::Mat RenderDifferencePanel(const WallDifference& difference, const PanelGeometry& panel);

/// A scale bar (1, 2 or 5 x 10^k metres, about a fifth of the width) with its length, bottom left.
void DrawScaleBar(cv::Mat& bgr, double metres_per_pixel);

}  // namespace slamsweep::report::inline images
