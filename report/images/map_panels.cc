#include "report/images/map_panels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <opencv2/imgproc.hpp>

#include "evaluator/core/input_error.h"
#include "evaluator/map_metrics/canvas_crop.h"
#include "evaluator/map_compare/map_resample.h"

namespace slamsweep::report::inline images {
namespace {

using evaluator::OccupancyGrid;

constexpr unsigned char kUnknownGrey = 205;
constexpr unsigned char kDifferenceUnknownGrey = 230;

struct Point {
  double x, y;
};

/// A placement with its rotation's cosine and sine computed once (panels apply it to every pixel).
struct Rigid {
  explicit Rigid(const MapPlacement& placement)
      : p(placement), c(std::cos(placement.yaw_rad)), s(std::sin(placement.yaw_rad)) {}
  Point Place(double x, double y) const {
    return {p.x_m + p.scale * (c * x - s * y), p.y_m + p.scale * (s * x + c * y)};
  }
  /// The inverse of Place: from the common frame back to the map's own world coordinates.
  Point Unplace(double x, double y) const {
    const double dx = (x - p.x_m) / p.scale, dy = (y - p.y_m) / p.scale;
    return {c * dx + s * dy, -s * dx + c * dy};
  }
  MapPlacement p;
  double c, s;
};

/// The cell of `grid` holding the map-world point, as (row from the top, column); false outside the grid.
bool CellOf(const OccupancyGrid& grid, const Point& world, int& row, int& col) {
  const double u = (world.x - grid.origin.x_m) / grid.resolution_m;
  const double v = (world.y - grid.origin.y_m) / grid.resolution_m;
  if (!(u >= 0.0 && v >= 0.0 && u < grid.width && v < grid.height)) return false;
  col = static_cast<int>(u);
  row = grid.height - 1 - static_cast<int>(v);
  return true;
}

unsigned char Grey(float p) {
  return OccupancyGrid::IsUnknown(p) ? kUnknownGrey : static_cast<unsigned char>(std::lround(255.0 * (1.0 - p)));
}

evaluator::MapCompareOptions CompareOptionsOf(const WallMatchOptions& options) {
  evaluator::MapCompareOptions compare;
  compare.occupied_threshold = options.occupied_threshold;
  compare.free_threshold = options.free_threshold;
  compare.match_radius_cells = options.match_radius_cells;
  return compare;
}

enum Occupancy : unsigned char { kUnknownCell = 0, kFreeCell = 1, kOccupiedCell = 2 };

Occupancy Classify(float p, const WallMatchOptions& options) {
  if (OccupancyGrid::IsUnknown(p)) return kUnknownCell;
  if (p >= options.occupied_threshold) return kOccupiedCell;
  if (p <= options.free_threshold) return kFreeCell;
  return kUnknownCell;
}

/// For each cell, whether an occupied cell of `occupied` (255) lies within `radius` cells.
cv::Mat WithinRadius(const cv::Mat& occupied, int radius) {
  if (cv::countNonZero(occupied) == 0) return cv::Mat::zeros(occupied.size(), CV_8U);
  cv::Mat distance;
  // distanceTransform measures to the nearest zero pixel: the occupied cells become the zeros.
  cv::distanceTransform(occupied == 0, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return distance <= radius + 1e-6;
}

cv::Vec3b ClassColour(unsigned char wall_class) {
  switch (wall_class) {
    case kWallBoth:
      return {kBothBgr[0], kBothBgr[1], kBothBgr[2]};
    case kWallRunOnly:
      return {kRunOnlyBgr[0], kRunOnlyBgr[1], kRunOnlyBgr[2]};
    case kWallReferenceOnly:
      return {kReferenceOnlyBgr[0], kReferenceOnlyBgr[1], kReferenceOnlyBgr[2]};
    case kWallFree:
      return {255, 255, 255};
    default:
      return {kDifferenceUnknownGrey, kDifferenceUnknownGrey, kDifferenceUnknownGrey};
  }
}

}  // namespace

WorldWindow WorldWindow::Union(const WorldWindow& other) const {
  return {std::min(min_x, other.min_x), std::min(min_y, other.min_y), std::max(max_x, other.max_x),
          std::max(max_y, other.max_y)};
}

std::optional<WorldWindow> KnownExtent(const OccupancyGrid& grid, const MapPlacement& placement) {
  int top = grid.height, bottom = -1, left = grid.width, right = -1;
  for (int r = 0; r < grid.height; ++r) {
    for (int c = 0; c < grid.width; ++c) {
      if (OccupancyGrid::IsUnknown(grid.at(r, c))) continue;
      top = std::min(top, r), bottom = std::max(bottom, r);
      left = std::min(left, c), right = std::max(right, c);
    }
  }
  if (bottom < 0) return std::nullopt;
  const double x0 = grid.origin.x_m + left * grid.resolution_m, x1 = grid.origin.x_m + (right + 1) * grid.resolution_m;
  const double y0 = grid.origin.y_m + (grid.height - 1 - bottom) * grid.resolution_m;
  const double y1 = grid.origin.y_m + (grid.height - top) * grid.resolution_m;
  WorldWindow box{1e300, 1e300, -1e300, -1e300};
  const Rigid rigid(placement);
  for (const auto& [x, y] : {Point{x0, y0}, Point{x1, y0}, Point{x0, y1}, Point{x1, y1}}) {
    const Point p = rigid.Place(x, y);
    box = box.Union({p.x, p.y, p.x, p.y});
  }
  return box;
}

OccupancyGrid KnownPart(OccupancyGrid grid, double later_resolution_m) {
  evaluator::CellWindow window = evaluator::KnownCellsWindow(grid, 1);
  const double ratio = later_resolution_m / grid.resolution_m;
  const long coarser = std::lround(ratio);
  const bool whole_multiple = coarser >= 1 && std::abs(ratio - coarser) < 1e-6 * ratio;
  const bool whole_fraction = ratio < 1.0 && std::abs(1.0 / ratio - std::lround(1.0 / ratio)) < 1e-6 / ratio;
  if (!whole_multiple && !whole_fraction) return grid;
  if (whole_multiple && coarser > 1) {
    // Left column and bottom edge down to multiples of the coarser cell, counted from the lower-left corner.
    const int k = static_cast<int>(coarser);
    const int left = window.col - window.col % k;
    const int below = grid.height - (window.row + window.height);
    const int new_below = below - below % k;
    window.width += window.col - left;
    window.col = left;
    window.height += below - new_below;
  }
  if (window == evaluator::CellWindow{0, 0, grid.width, grid.height}) return grid;
  return evaluator::CropGrid(std::move(grid), window);
}

PanelGeometry ChoosePanelGeometry(const WorldWindow& window, int max_side_px, double margin_fraction) {
  if (max_side_px < 1)
    throw evaluator::InputError("map panel: expected at least 1 pixel, got " + std::to_string(max_side_px));
  if (!(window.Width() > 0.0 && window.Height() > 0.0) || !std::isfinite(window.Width() + window.Height())) {
    throw evaluator::InputError("map panel: the maps have no extent to draw");
  }
  const double margin = margin_fraction * std::max(window.Width(), window.Height());
  PanelGeometry panel;
  panel.window = {window.min_x - margin, window.min_y - margin, window.max_x + margin, window.max_y + margin};
  panel.metres_per_pixel = std::max(panel.window.Width(), panel.window.Height()) / max_side_px;
  panel.width_px = std::max(1, static_cast<int>(std::ceil(panel.window.Width() / panel.metres_per_pixel - 1e-6)));
  panel.height_px = std::max(1, static_cast<int>(std::ceil(panel.window.Height() / panel.metres_per_pixel - 1e-6)));
  // The window becomes whole pixels, so that pixel (c, r) always covers the same metres in every panel.
  panel.window.max_x = panel.window.min_x + panel.width_px * panel.metres_per_pixel;
  panel.window.max_y = panel.window.min_y + panel.height_px * panel.metres_per_pixel;
  return panel;
}

cv::Mat RenderMapPanel(const OccupancyGrid& grid, const MapPlacement& placement, const PanelGeometry& panel) {
  // Cells smaller than a pixel are merged first (keeping the highest probability), so walls survive.
  const double cell_in_panel = grid.resolution_m * placement.scale;
  const OccupancyGrid merged =
      cell_in_panel < panel.metres_per_pixel
          ? evaluator::ResampleKeepingProbabilities(grid, panel.metres_per_pixel / placement.scale)
          : OccupancyGrid();
  const OccupancyGrid& shown = merged.cells.empty() ? grid : merged;
  cv::Mat grey(panel.height_px, panel.width_px, CV_8U, cv::Scalar(kUnknownGrey));
  const Rigid rigid(placement);
  for (int r = 0; r < panel.height_px; ++r) {
    auto* out = grey.ptr<unsigned char>(r);
    const double y = panel.window.max_y - (r + 0.5) * panel.metres_per_pixel;
    for (int c = 0; c < panel.width_px; ++c) {
      const double x = panel.window.min_x + (c + 0.5) * panel.metres_per_pixel;
      int row = 0, col = 0;
      if (CellOf(shown, rigid.Unplace(x, y), row, col)) out[c] = Grey(shown.at(row, col));
    }
  }
  return grey;
}

WallDifference CompareWalls(const OccupancyGrid& run, const MapPlacement& placement, const OccupancyGrid& reference,
                            const WallMatchOptions& options) {
  if (!(reference.resolution_m > 0.0)) throw evaluator::InputError("reference map: cell size must be positive");
  const double res = reference.resolution_m;
  const OccupancyGrid resampled =
      evaluator::ResampleToResolution(run, res / placement.scale, CompareOptionsOf(options));
  WorldWindow extent{reference.origin.x_m, reference.origin.y_m, reference.origin.x_m + reference.width * res,
                     reference.origin.y_m + reference.height * res};
  if (const std::optional<WorldWindow> known = KnownExtent(resampled, placement)) extent = extent.Union(*known);

  WallDifference out;
  out.resolution_m = res;
  // The reference's lattice, wide enough for both maps.
  const double first_col = std::floor((extent.min_x - reference.origin.x_m) / res);
  const double first_row = std::floor((extent.min_y - reference.origin.y_m) / res);
  out.origin_x_m = reference.origin.x_m + first_col * res;
  out.origin_y_m = reference.origin.y_m + first_row * res;
  const int width = static_cast<int>(std::ceil((extent.max_x - out.origin_x_m) / res - 1e-9));
  const int height = static_cast<int>(std::ceil((extent.max_y - out.origin_y_m) / res - 1e-9));

  cv::Mat run_class(height, width, CV_8U, cv::Scalar(kUnknownCell));
  cv::Mat reference_class(height, width, CV_8U, cv::Scalar(kUnknownCell));
  const int col0 = static_cast<int>(-first_col);
  const int row0 = height - reference.height + static_cast<int>(first_row);
  for (int r = 0; r < reference.height; ++r) {
    for (int c = 0; c < reference.width; ++c)
      reference_class.at<unsigned char>(row0 + r, col0 + c) = Classify(reference.at(r, c), options);
  }
  const Rigid rigid(placement);
  for (int r = 0; r < height; ++r) {
    const double y = out.origin_y_m + (height - 1 - r + 0.5) * res;
    for (int c = 0; c < width; ++c) {
      int row = 0, col = 0;
      if (CellOf(resampled, rigid.Unplace(out.origin_x_m + (c + 0.5) * res, y), row, col)) {
        run_class.at<unsigned char>(r, c) = Classify(resampled.at(row, col), options);
      }
    }
  }
  const cv::Mat run_walls = run_class == kOccupiedCell;
  const cv::Mat reference_walls = reference_class == kOccupiedCell;
  const cv::Mat near_reference = WithinRadius(reference_walls, options.match_radius_cells);
  const cv::Mat near_run = WithinRadius(run_walls, options.match_radius_cells);

  out.classes = cv::Mat(height, width, CV_8U, cv::Scalar(kWallUnknown));
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) {
      const bool in_run = run_walls.at<unsigned char>(r, c) != 0;
      const bool in_reference = reference_walls.at<unsigned char>(r, c) != 0;
      unsigned char& cell = out.classes.at<unsigned char>(r, c);
      if ((in_run && near_reference.at<unsigned char>(r, c)) || (in_reference && near_run.at<unsigned char>(r, c))) {
        cell = kWallBoth;
        ++out.counts.both;
      } else if (in_run) {
        cell = kWallRunOnly;
        ++out.counts.run_only;
      } else if (in_reference) {
        cell = kWallReferenceOnly;
        ++out.counts.reference_only;
      } else if (run_class.at<unsigned char>(r, c) == kFreeCell ||
                 reference_class.at<unsigned char>(r, c) == kFreeCell) {
        cell = kWallFree;
      }
    }
  }
  return out;
}

cv::Mat RenderDifferencePanel(const WallDifference& difference, const PanelGeometry& panel) {
  cv::Mat image(panel.height_px, panel.width_px, CV_8UC3, ClassColour(kWallUnknown));
  const cv::Mat& classes = difference.classes;
  const double res = difference.resolution_m;
  const double mpp = panel.metres_per_pixel;
  const auto column = [&](double x) { return (x - difference.origin_x_m) / res; };
  // Rows counted from the top of `classes`.
  const auto row = [&](double y) { return classes.rows - (y - difference.origin_y_m) / res; };
  for (int r = 0; r < panel.height_px; ++r) {
    auto* out = image.ptr<cv::Vec3b>(r);
    const double y_top = panel.window.max_y - r * mpp;
    for (int c = 0; c < panel.width_px; ++c) {
      const double x_left = panel.window.min_x + c * mpp;
      // The cells whose centres fall in the pixel, or the one under its centre when none does.
      int c0 = static_cast<int>(std::ceil(column(x_left) - 0.5)),
          c1 = static_cast<int>(std::ceil(column(x_left + mpp) - 0.5));
      int r0 = static_cast<int>(std::ceil(row(y_top) - 0.5)), r1 = static_cast<int>(std::ceil(row(y_top - mpp) - 0.5));
      if (c1 <= c0) c0 = static_cast<int>(std::floor(column(x_left + mpp / 2))), c1 = c0 + 1;
      if (r1 <= r0) r0 = static_cast<int>(std::floor(row(y_top - mpp / 2))), r1 = r0 + 1;
      c0 = std::max(c0, 0), r0 = std::max(r0, 0);
      c1 = std::min(c1, classes.cols), r1 = std::min(r1, classes.rows);
      unsigned char highest = kWallUnknown;
      for (int rr = r0; rr < r1; ++rr) {
        const auto* in = classes.ptr<unsigned char>(rr);
        for (int cc = c0; cc < c1; ++cc) highest = std::max(highest, in[cc]);
      }
      out[c] = ClassColour(highest);
    }
  }
  return image;
}

void DrawScaleBar(cv::Mat& bgr, double metres_per_pixel) {
  const double target_m = bgr.cols * metres_per_pixel / 5.0;
  if (!(target_m > 0.0) || bgr.rows < 24) return;
  const double decade = std::pow(10.0, std::floor(std::log10(target_m)));
  double length_m = decade;
  for (const double step : {2.0, 5.0}) {
    if (step * decade <= target_m) length_m = step * decade;
  }
  const int length_px = std::max(1, static_cast<int>(std::lround(length_m / metres_per_pixel)));
  const cv::Point start(8, bgr.rows - 10), end(8 + length_px, bgr.rows - 10);
  cv::line(bgr, start, end, cv::Scalar(255, 255, 255), 5);
  cv::line(bgr, start, end, cv::Scalar(0, 0, 0), 2);
  char label[32];
  std::snprintf(label, sizeof label, "%g m", length_m);
  const cv::Point text(8, bgr.rows - 16);
  cv::putText(bgr, label, text, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(255, 255, 255), 3, cv::LINE_AA);
  cv::putText(bgr, label, text, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
}

}  // namespace slamsweep::report::inline images
