#pragma once

#include <filesystem>

#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::evaluator::inline formats::inline map {

/// MRPT's unknown grey level: COccupancyGridMap2D stores p(free) and draws the prior 0.5 as 127.
inline constexpr int kMrptUnknownValue = 127;

/// `<dir>/<stem>_limits.txt` for `<dir>/<stem>.png`: where
/// COccupancyGridMap2D::saveMetricMapRepresentationToFile(prefix) puts the grid extent
/// (icp-slam / rbpf-slam save `<prefix>.png` and `<prefix>_limits.txt`).
std::filesystem::path MrptLimitsPath(const std::filesystem::path& image_path);

/// Reads an MRPT grid bitmap: an 8-bit grey image (getAsImage: row 0 is the largest y, so +y is
/// up, as in OccupancyGrid), value `unknown_value` = unknown, any other value v has
/// p = (255 - v) / 255 (MRPT draws p(free) * 255). The limits file holds one line
/// `x_min x_max y_min y_max` (metres) after `%` comment lines; resolution =
/// (x_max - x_min) / width, origin = (x_min, y_min, 0).
/// Throws InputError naming the image or limits file: missing limits (naming both), a limits
/// line that is not four numbers, an empty extent, cells that are not square (x and y
/// resolution differing by more than 0.01 %), a colour or 16-bit image.
OccupancyGrid ReadMrptGridmap(const std::filesystem::path& image_path, int unknown_value = kMrptUnknownValue);

/// Writes `grid` as MRPT does: a grey PNG with value round(255 * (1 - p)) and 127 for unknown,
/// and `<stem>_limits.txt` ("% Grid limits: [x_min x_max y_min y_max]" then the four numbers,
/// "%.16f" as MRPT's MATRIX_FORMAT_FIXED). MRPT has no separate unknown state: a known cell whose
/// grey level rounds to 127 (0.5 < p <= 0.504) reads back as unknown, as it would in MRPT.
/// Throws InputError for a rotated origin (MRPT grids are axis-aligned) or a malformed grid.
void WriteMrptGridmap(const OccupancyGrid& grid, const std::filesystem::path& image_path);

}  // namespace slamsweep::evaluator::inline formats::inline map
