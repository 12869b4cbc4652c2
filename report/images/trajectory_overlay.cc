#include "report/images/trajectory_overlay.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/image_file.h"
#include "evaluator/formats/map/map_file.h"
#include "evaluator/formats/trajectory/tum_format.h"
#include "report/images/area_shrink.h"
#include "report/images/overlay_alignment.h"
#include "report/images/map_greys.h"

namespace slamsweep::report::inline images {
namespace {

using evaluator::OccupancyGrid;
using evaluator::Trajectory;

/// Sub-pixel precision of the drawn lines: 4 fractional bits.
constexpr int kShift = 4;
constexpr double kShiftScale = 1 << kShift;
/// Bound on path coordinates, in cells (see ToCells).
constexpr double kFarCells = 1e6;

cv::Scalar Colour(const unsigned char (&bgr)[3]) { return cv::Scalar(bgr[0], bgr[1], bgr[2]); }

/// A path in continuous cell coordinates of the map: x = column, y = row from the top edge.
std::vector<cv::Point2d> ToCells(const Trajectory& trajectory, const OccupancyGrid& grid) {
  const double c = std::cos(grid.origin.yaw_rad);
  const double s = std::sin(grid.origin.yaw_rad);
  std::vector<cv::Point2d> cells;
  cells.reserve(trajectory.size());
  for (const auto& pose : trajectory.poses()) {
    const double dx = pose.position.x() - grid.origin.x_m;
    const double dy = pose.position.y() - grid.origin.y_m;
    const double local_x = c * dx + s * dy;
    const double local_y = -s * dx + c * dy;
    // A diverged run can report poses kilometres away: clamped far outside any view, they keep
    // their direction on the picture without overflowing pixel arithmetic.
    const auto clamped = [](double cell) { return std::clamp(cell, -kFarCells, kFarCells); };
    cells.emplace_back(clamped(local_x / grid.resolution_m), clamped(grid.height - local_y / grid.resolution_m));
  }
  return cells;
}

/// The cells shown: known cells and paths with a margin, limited to the map and the paths, and to
/// half a map beyond the map on each side.
cv::Rect ViewOf(const OccupancyGrid& grid, const std::vector<std::vector<cv::Point2d>>& paths) {
  int left = grid.width;
  int top = grid.height;
  int right = 0;
  int bottom = 0;
  const auto include = [&](int x0, int y0, int x1, int y1) {
    left = std::min(left, x0);
    top = std::min(top, y0);
    right = std::max(right, x1);
    bottom = std::max(bottom, y1);
  };
  for (int r = 0; r < grid.height; ++r) {
    for (int col = 0; col < grid.width; ++col) {
      if (!OccupancyGrid::IsUnknown(grid.at(r, col))) include(col, r, col + 1, r + 1);
    }
  }
  int outer_left = 0;
  int outer_top = 0;
  int outer_right = grid.width;
  int outer_bottom = grid.height;
  for (const auto& path : paths) {
    for (const cv::Point2d& p : path) {
      const int x0 = static_cast<int>(std::floor(p.x));
      const int y0 = static_cast<int>(std::floor(p.y));
      include(x0, y0, x0 + 1, y0 + 1);
      outer_left = std::min(outer_left, x0);
      outer_top = std::min(outer_top, y0);
      outer_right = std::max(outer_right, x0 + 1);
      outer_bottom = std::max(outer_bottom, y0 + 1);
    }
  }
  // Paths may reach beyond the map, but the picture shows at most half a map more on each side:
  // a path gone astray must not turn the overlay into a huge, mostly empty image.
  outer_left = std::max(outer_left, -grid.width / 2);
  outer_top = std::max(outer_top, -grid.height / 2);
  outer_right = std::min(outer_right, grid.width + grid.width / 2);
  outer_bottom = std::min(outer_bottom, grid.height + grid.height / 2);
  if (right <= left || bottom <= top) return {0, 0, grid.width, grid.height};
  const int margin = std::max(2, static_cast<int>(0.05 * std::max(right - left, bottom - top)));
  const cv::Rect padded(left - margin, top - margin, right - left + 2 * margin, bottom - top + 2 * margin);
  const cv::Rect view = padded & cv::Rect(outer_left, outer_top, outer_right - outer_left, outer_bottom - outer_top);
  return view.empty() ? cv::Rect(0, 0, grid.width, grid.height) : view;
}

/// The map cells of `view` as a grey image, one pixel per cell; outside the map is unknown. Grey
/// until scaled, so a large map costs one byte per cell, not three.
cv::Mat MapPixels(const OccupancyGrid& grid, const cv::Rect& view) {
  cv::Mat grey(view.height, view.width, CV_8UC1, cv::Scalar(kUnknownGrey));
  for (int r = 0; r < view.height; ++r) {
    const int row = view.y + r;
    if (row < 0 || row >= grid.height) continue;
    uchar* out = grey.ptr<uchar>(r);
    for (int c = 0; c < view.width; ++c) {
      const int col = view.x + c;
      if (col < 0 || col >= grid.width) continue;
      const float p = grid.at(row, col);
      if (!OccupancyGrid::IsUnknown(p)) out[c] = static_cast<uchar>(std::lround(255.0 * (1.0 - p)));
    }
  }
  return grey;
}

struct Placement {
  cv::Rect view;
  double scale_x = 1.0;
  double scale_y = 1.0;
  cv::Point ToPixel(const cv::Point2d& cell) const {
    return {static_cast<int>(std::lround((cell.x - view.x) * scale_x * kShiftScale)),
            static_cast<int>(std::lround((cell.y - view.y) * scale_y * kShiftScale))};
  }
};

void DrawPath(cv::Mat& image, const std::vector<cv::Point2d>& cells, const Placement& placement,
              const cv::Scalar& colour, int thickness) {
  if (cells.empty()) return;
  std::vector<cv::Point> points;
  points.reserve(cells.size());
  for (const auto& cell : cells) points.push_back(placement.ToPixel(cell));
  cv::polylines(image, points, false, colour, thickness, cv::LINE_AA, kShift);
  const cv::Scalar outline(0, 0, 0);
  const int radius = 5 + thickness / 2;
  cv::circle(image, points.front(), radius << kShift, colour, cv::FILLED, cv::LINE_AA, kShift);
  cv::circle(image, points.front(), radius << kShift, outline, 1, cv::LINE_AA, kShift);
  const cv::Point half(radius << kShift, radius << kShift);
  cv::rectangle(image, points.back() - half, points.back() + half, colour, cv::FILLED, cv::LINE_AA, kShift);
  cv::rectangle(image, points.back() - half, points.back() + half, outline, 1, cv::LINE_AA, kShift);
}

struct LegendEntry {
  std::optional<cv::Scalar> colour;
  std::string text;
};

/// `map_image` with a white legend strip below it, one line per entry.
cv::Mat WithLegend(const cv::Mat& map_image, const std::vector<LegendEntry>& entries) {
  constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
  constexpr double kFontScale = 0.45;
  constexpr int kLineHeight = 20;
  constexpr int kSwatch = 24;
  int text_width = 0;
  for (const auto& entry : entries) {
    int baseline = 0;
    text_width = std::max(text_width, cv::getTextSize(entry.text, kFont, kFontScale, 1, &baseline).width);
  }
  const int width = std::max(map_image.cols, 16 + kSwatch + text_width);
  const int height = map_image.rows + 8 + kLineHeight * static_cast<int>(entries.size());
  cv::Mat canvas(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  map_image.copyTo(canvas(cv::Rect(0, 0, map_image.cols, map_image.rows)));
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const int y = map_image.rows + 4 + kLineHeight * static_cast<int>(i) + kLineHeight / 2;
    if (entries[i].colour) {
      cv::line(canvas, {6, y}, {6 + kSwatch - 4, y}, *entries[i].colour, 3, cv::LINE_AA);
    }
    cv::putText(canvas, entries[i].text, {10 + kSwatch, y + 5}, kFont, kFontScale, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  }
  return canvas;
}

/// Hershey fonts draw ASCII only: anything else (e.g. UTF-8 in a path) becomes '?'.
std::string Printable(const std::string& text) {
  std::string out = text.substr(0, 160);
  for (char& c : out) {
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e) c = '?';
  }
  return out;
}

}  // namespace

void WriteTrajectoryOverlay(const std::filesystem::path& map_yaml, const std::filesystem::path& estimate_tum,
                            const std::filesystem::path& reference_tum, const std::filesystem::path& png,
                            const OverlayOptions& options) {
  if (options.max_side_px < 64) {
    throw evaluator::InputError("overlay max_side_px: expected at least 64 pixels, got " +
                                std::to_string(options.max_side_px));
  }
  evaluator::ParseAlignmentMode(options.align);
  const OccupancyGrid grid = evaluator::ReadMap(map_yaml);
  const Trajectory estimate = evaluator::ReadTum(estimate_tum);
  if (estimate.empty()) throw evaluator::InputError(evaluator::Located(estimate_tum, 0, "no poses to draw"));

  std::vector<std::vector<cv::Point2d>> paths = {ToCells(estimate, grid)};
  std::vector<LegendEntry> legend = {{Colour(kEstimateBgr), "estimate (map frame)"}};
  if (!reference_tum.empty()) {
    const ReferenceInMapFrame placed =
        AlignReferenceOntoEstimate(evaluator::ReadTum(reference_tum), estimate, options.align, options.t_max_diff_s);
    if (placed.reference) {
      paths.push_back(ToCells(*placed.reference, grid));
      legend.push_back({Colour(kReferenceBgr), Printable(placed.note)});
    } else {
      legend.push_back({std::nullopt, Printable(placed.note)});
    }
  } else {
    legend.push_back({std::nullopt, "no reference trajectory"});
  }
  legend.push_back({std::nullopt, "circle = start, square = end"});

  Placement placement;
  placement.view = ViewOf(grid, paths);
  const double scale = static_cast<double>(options.max_side_px) / std::max(placement.view.width, placement.view.height);
  const cv::Size size(std::max(1, static_cast<int>(std::lround(placement.view.width * scale))),
                      std::max(1, static_cast<int>(std::lround(placement.view.height * scale))));
  placement.scale_x = static_cast<double>(size.width) / placement.view.width;
  placement.scale_y = static_cast<double>(size.height) / placement.view.height;
  cv::Mat grey;
  // Enlarged cells stay crisp squares; shrunk maps average their cells.
  if (scale >= 1.0) {
    cv::resize(MapPixels(grid, placement.view), grey, size, 0, 0, cv::INTER_NEAREST);
  } else {
    grey = ShrinkByArea(MapPixels(grid, placement.view), size);
  }
  cv::Mat image;
  cv::cvtColor(grey, image, cv::COLOR_GRAY2BGR);

  if (paths.size() > 1) DrawPath(image, paths[1], placement, Colour(kReferenceBgr), 6);
  DrawPath(image, paths[0], placement, Colour(kEstimateBgr), 2);
  evaluator::WriteBinaryFile(png, evaluator::EncodePng(WithLegend(image, legend)));
}

}  // namespace slamsweep::report::inline images
