#include "evaluator/map_compare/map_resample.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline map_compare {
namespace {

constexpr std::uint8_t kSeenFree = 1, kSeenOccupied = 2;

std::uint8_t ClassBits(float p, const MapCompareOptions& options) {
  if (OccupancyGrid::IsUnknown(p)) return 0;
  if (p >= options.occupied_threshold) return kSeenOccupied;
  if (p <= options.free_threshold) return kSeenFree;
  return 0;
}

/// The lattice of cells of `resolution_m` that covers `grid` from the same lower-left corner (rows counted from
/// the bottom, world y), and which cells of the two lattices lie under each other's centres.
struct Lattice {
  double scale = 1.0;  ///< new cells per old cell
  int width = 0;
  int height = 0;

  /// The new cell under the centre of old cell (r, c), if inside the new lattice.
  std::optional<std::size_t> NewIndexOf(const OccupancyGrid& grid, int r, int c) const {
    const int new_from_bottom = static_cast<int>(std::floor((grid.height - 1 - r + 0.5) * scale));
    const int new_col = static_cast<int>(std::floor((c + 0.5) * scale));
    if (new_from_bottom >= height || new_col >= width) return std::nullopt;
    return static_cast<std::size_t>(height - 1 - new_from_bottom) * width + new_col;
  }
  /// The old cell under the centre of new cell (r, c) (a finer lattice), if inside the old grid.
  std::optional<float> OldCellUnder(const OccupancyGrid& grid, int r, int c) const {
    const int old_col = static_cast<int>(std::floor((c + 0.5) / scale));
    const int old_from_bottom = static_cast<int>(std::floor((height - 1 - r + 0.5) / scale));
    if (old_col >= grid.width || old_from_bottom >= grid.height) return std::nullopt;
    return grid.at(grid.height - 1 - old_from_bottom, old_col);
  }
};

/// The lattice for `resolution_m`, or none when the grid already has that cell size. Throws InputError for a
/// cell size that is not > 0.
std::optional<Lattice> TargetLattice(const OccupancyGrid& grid, double resolution_m) {
  if (!(resolution_m > 0.0) || !std::isfinite(resolution_m)) {
    throw InputError("map resampling: expected a cell size > 0 m, got " + std::to_string(resolution_m));
  }
  if (std::abs(grid.resolution_m - resolution_m) <= 1e-9 * resolution_m) return std::nullopt;
  Lattice lattice;
  lattice.scale = grid.resolution_m / resolution_m;
  lattice.width = std::max(1, static_cast<int>(std::ceil(grid.width * lattice.scale - 1e-9)));
  lattice.height = std::max(1, static_cast<int>(std::ceil(grid.height * lattice.scale - 1e-9)));
  return lattice;
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
  const std::optional<Lattice> lattice = TargetLattice(grid, resolution_m);
  if (!lattice) return grid;
  const int width = lattice->width, height = lattice->height;
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(width) * height, 0);
  std::vector<bool> has_centre(seen.size(), false);
  for (int r = 0; r < grid.height; ++r) {
    for (int c = 0; c < grid.width; ++c) {
      const std::optional<std::size_t> index = lattice->NewIndexOf(grid, r, c);
      if (!index) continue;
      seen[*index] |= ClassBits(grid.at(r, c), options);
      has_centre[*index] = true;
    }
  }
  OccupancyGrid out(width, height, resolution_m, grid.origin);
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) {
      const std::size_t index = static_cast<std::size_t>(r) * width + c;
      std::uint8_t bits = seen[index];
      if (!has_centre[index]) {
        if (const std::optional<float> old = lattice->OldCellUnder(grid, r, c)) bits = ClassBits(*old, options);
      }
      out.cells[index] = (bits & kSeenOccupied) ? 1.0f : (bits & kSeenFree) ? 0.0f : OccupancyGrid::kUnknown;
    }
  }
  return out;
}

OccupancyGrid ResampleKeepingProbabilities(const OccupancyGrid& grid, double resolution_m) {
  const std::optional<Lattice> lattice = TargetLattice(grid, resolution_m);
  if (!lattice) return grid;
  OccupancyGrid out(lattice->width, lattice->height, resolution_m, grid.origin);  // every cell unknown
  std::vector<bool> has_centre(out.cells.size(), false);
  for (int r = 0; r < grid.height; ++r) {
    for (int c = 0; c < grid.width; ++c) {
      const std::optional<std::size_t> index = lattice->NewIndexOf(grid, r, c);
      if (!index) continue;
      has_centre[*index] = true;
      const float p = grid.at(r, c);
      if (OccupancyGrid::IsUnknown(p)) continue;
      float& cell = out.cells[*index];
      if (OccupancyGrid::IsUnknown(cell) || p > cell) cell = p;
    }
  }
  for (int r = 0; r < lattice->height; ++r) {
    for (int c = 0; c < lattice->width; ++c) {
      const std::size_t index = static_cast<std::size_t>(r) * lattice->width + c;
      if (has_centre[index]) continue;
      if (const std::optional<float> old = lattice->OldCellUnder(grid, r, c)) out.cells[index] = *old;
    }
  }
  return out;
}

}  // namespace slamsweep::evaluator::inline map_compare
