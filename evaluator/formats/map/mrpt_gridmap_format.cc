#include "evaluator/formats/map/mrpt_gridmap_format.h"

#include <fmt/format.h>

#include <cmath>
#include <opencv2/core.hpp>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "evaluator/formats/map/image8.h"
#include "evaluator/formats/map/image_file.h"

namespace slamsweep::evaluator::inline formats::inline map {
namespace {

/// The grid extent in metres as `<stem>_limits.txt` gives it.
struct MrptLimits {
  double x_min_m = 0.0;
  double x_max_m = 0.0;
  double y_min_m = 0.0;
  double y_max_m = 0.0;
};

constexpr std::string_view kLimitsLayout = "x_min x_max y_min y_max";
// MRPT keeps the limits in float, so x and y cell sizes may differ in the 7th digit.
constexpr double kSquareCellTolerance = 1e-4;

MrptLimits ReadLimits(const std::filesystem::path& limits_path) {
  const std::string content = ReadTextFile(limits_path);
  std::vector<MrptLimits> lines;
  ForEachRecord(
      limits_path, content,
      [&](const TextRecord& record) {
        record.RequireFields(4, kLimitsLayout);
        if (record.size() > 4)
          record.Fail(fmt::format("expected 4 numbers ({}), got {} fields", kLimitsLayout, record.size()));
        if (!lines.empty()) record.Fail(fmt::format("expected one line of limits ({}), found a second", kLimitsLayout));
        lines.push_back({record.Number(0, "x_min"), record.Number(1, "x_max"), record.Number(2, "y_min"),
                         record.Number(3, "y_max")});
        if (!(lines.back().x_max_m > lines.back().x_min_m) || !(lines.back().y_max_m > lines.back().y_min_m)) {
          record.Fail("expected x_min < x_max and y_min < y_max");
        }
      },
      " \t\r", "%");
  if (lines.empty())
    throw InputError(Located(limits_path, 0, fmt::format("no limits line; expected '{}'", kLimitsLayout)));
  return lines.front();
}

}  // namespace

std::filesystem::path MrptLimitsPath(const std::filesystem::path& image_path) {
  return image_path.parent_path() / (image_path.stem().string() + "_limits.txt");
}

OccupancyGrid ReadMrptGridmap(const std::filesystem::path& image_path, int unknown_value) {
  const std::filesystem::path limits_path = MrptLimitsPath(image_path);
  std::error_code error;
  if (!std::filesystem::is_regular_file(limits_path, error)) {
    throw InputError(Located(image_path, 0,
                             fmt::format("MRPT grid map without its limits file '{}' (expected '{}' in metres)",
                                         limits_path.string(), kLimitsLayout)));
  }
  const MrptLimits limits = ReadLimits(limits_path);
  const cv::Mat image = ReadGreyImageFile(image_path);
  const double resolution_x_m = (limits.x_max_m - limits.x_min_m) / image.cols;
  const double resolution_y_m = (limits.y_max_m - limits.y_min_m) / image.rows;
  if (std::abs(resolution_x_m - resolution_y_m) > kSquareCellTolerance * resolution_x_m) {
    throw InputError(
        Located(limits_path, 0,
                fmt::format("limits give {} m/cell along x ({} cells) but {} m/cell along y ({} cells) for image '{}'; "
                            "expected square cells",
                            resolution_x_m, image.cols, resolution_y_m, image.rows, image_path.string())));
  }
  return FromImage8(image, unknown_value, resolution_x_m, GridOrigin{limits.x_min_m, limits.y_min_m, 0.0});
}

void WriteMrptGridmap(const OccupancyGrid& grid, const std::filesystem::path& image_path) {
  if (image_path.extension() != ".png") {
    throw InputError(Located(image_path, 0, "expected a .png file name (MRPT saves grid maps as PNG)"));
  }
  if (grid.origin.yaw_rad != 0.0) {
    throw InputError(Located(
        image_path, 0,
        fmt::format("MRPT grid maps are axis-aligned; cannot write an origin yaw of {} rad", grid.origin.yaw_rad)));
  }
  if (!std::isfinite(grid.resolution_m) || grid.resolution_m <= 0.0 || !std::isfinite(grid.origin.x_m) ||
      !std::isfinite(grid.origin.y_m)) {
    throw InputError(Located(image_path, 0, "cannot write a grid without a positive resolution and a finite origin"));
  }
  const cv::Mat image = ToImage8(grid, kMrptUnknownValue);
  WriteBinaryFile(image_path, EncodePng(image));
  const double x_max_m = grid.origin.x_m + grid.width * grid.resolution_m;
  const double y_max_m = grid.origin.y_m + grid.height * grid.resolution_m;
  WriteBinaryFile(MrptLimitsPath(image_path),
                  fmt::format("% Grid limits: [x_min x_max y_min y_max]\n{:.16f} {:.16f} {:.16f} {:.16f}\n",
                              grid.origin.x_m, x_max_m, grid.origin.y_m, y_max_m));
}

}  // namespace slamsweep::evaluator::inline formats::inline map
