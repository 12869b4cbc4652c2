#include "evaluator/map_compare/map_resample.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

constexpr std::uint8_t kSeenFree = 1, kSeenOccupied = 2;

std::uint8_t ClassBits(float p, const MapCompareOptions& options) {
  if (OccupancyGrid::IsUnknown(p)) return 0;
  if (p >= options.occupied_threshold) return kSeenOccupied;
  if (p <= options.free_threshold) return kSeenFree;
  return 0;
}

}  // namespace

OccupancyGrid ClassifyCells(const OccupancyGrid& grid, const MapCompareOptions& options) {
  OccupancyGrid out = grid;
  for (float& cell : out.cells) {
    const std::uint8_t bits = ClassBits(cell, options);
    cell = bits == kSeenOccupied ? 1.0f : bits == kSeenFree ? 0.0f : OccupancyGrid::kUnknown;
  }
  return out;
}

OccupancyGrid ResampleToResolution(const OccupancyGrid& grid, double resolution_m, const MapCompareOptions& options) {
  if (!(resolution_m > 0.0) || !std::isfinite(resolution_m)) {
    throw InputError("map resampling: expected a cell size > 0 m, got " + std::to_string(resolution_m));
  }
  if (std::abs(grid.resolution_m - resolution_m) <= 1e-9 * resolution_m) return grid;
  const double scale = grid.resolution_m / resolution_m;  // new cells per old cell
  const int width = std::max(1, static_cast<int>(std::ceil(grid.width * scale - 1e-9)));
  const int height = std::max(1, static_cast<int>(std::ceil(grid.height * scale - 1e-9)));
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(width) * height, 0);
  std::vector<bool> has_centre(seen.size(), false);
  // Rows counted from the bottom (world y) so that both lattices share the lower-left corner.
  for (int r = 0; r < grid.height; ++r) {
    const int from_bottom = grid.height - 1 - r;
    const int new_from_bottom = static_cast<int>(std::floor((from_bottom + 0.5) * scale));
    if (new_from_bottom >= height) continue;
    for (int c = 0; c < grid.width; ++c) {
      const int new_col = static_cast<int>(std::floor((c + 0.5) * scale));
      if (new_col >= width) continue;
      const std::size_t index = static_cast<std::size_t>(height - 1 - new_from_bottom) * width + new_col;
      seen[index] |= ClassBits(grid.at(r, c), options);
      has_centre[index] = true;
    }
  }
  OccupancyGrid out(width, height, resolution_m, grid.origin);
  for (int r = 0; r < height; ++r) {
    const int from_bottom = height - 1 - r;
    for (int c = 0; c < width; ++c) {
      const std::size_t index = static_cast<std::size_t>(r) * width + c;
      std::uint8_t bits = seen[index];
      if (!has_centre[index]) {
        // A finer lattice: the old cell under this cell's centre.
        const int old_col = static_cast<int>(std::floor((c + 0.5) / scale));
        const int old_from_bottom = static_cast<int>(std::floor((from_bottom + 0.5) / scale));
        if (old_col < grid.width && old_from_bottom < grid.height) {
          bits = ClassBits(grid.at(grid.height - 1 - old_from_bottom, old_col), options);
        }
      }
      out.cells[index] = (bits & kSeenOccupied) ? 1.0f : (bits & kSeenFree) ? 0.0f : OccupancyGrid::kUnknown;
    }
  }
  return out;
}

OccupancyGrid ResampleKeepingProbabilities(const OccupancyGrid& grid, double resolution_m) {
  if (!(resolution_m > 0.0) || !std::isfinite(resolution_m)) {
    throw InputError("map resampling: expected a cell size > 0 m, got " + std::to_string(resolution_m));
  }
  if (std::abs(grid.resolution_m - resolution_m) <= 1e-9 * resolution_m) return grid;
  const double scale = grid.resolution_m / resolution_m;  // new cells per old cell
  const int width = std::max(1, static_cast<int>(std::ceil(grid.width * scale - 1e-9)));
  const int height = std::max(1, static_cast<int>(std::ceil(grid.height * scale - 1e-9)));
  OccupancyGrid out(width, height, resolution_m, grid.origin);  // every cell unknown
  std::vector<bool> has_centre(out.cells.size(), false);
  // Rows counted from the bottom (world y) so that both lattices share the lower-left corner.
  for (int r = 0; r < grid.height; ++r) {
    const int new_from_bottom = static_cast<int>(std::floor((grid.height - 1 - r + 0.5) * scale));
    if (new_from_bottom >= height) continue;
    for (int c = 0; c < grid.width; ++c) {
      const int new_col = static_cast<int>(std::floor((c + 0.5) * scale));
      if (new_col >= width) continue;
      const std::size_t index = static_cast<std::size_t>(height - 1 - new_from_bottom) * width + new_col;
      has_centre[index] = true;
      const float p = grid.at(r, c);
      if (OccupancyGrid::IsUnknown(p)) continue;
      float& cell = out.cells[index];
      if (OccupancyGrid::IsUnknown(cell) || p > cell) cell = p;
    }
  }
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) {
      const std::size_t index = static_cast<std::size_t>(r) * width + c;
      if (has_centre[index]) continue;
      // A finer lattice: the old cell under this cell's centre.
      const int old_col = static_cast<int>(std::floor((c + 0.5) / scale));
      const int old_from_bottom = static_cast<int>(std::floor((height - 1 - r + 0.5) / scale));
      if (old_col < grid.width && old_from_bottom < grid.height) {
        out.cells[index] = grid.at(grid.height - 1 - old_from_bottom, old_col);
      }
    }
  }
  return out;
}

}  // namespace slamsweep::evaluator
