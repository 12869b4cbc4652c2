#include "evaluator/map_metrics/level_runs.h"

#include <cstddef>
#include <cstring>

namespace slamsweep::evaluator::inline map_metrics {

LevelRuns BuildLevelRuns(const OccupancyGrid& grid) {
  LevelRuns runs;
  runs.width = grid.width;
  runs.height = grid.height;
  runs.row_offsets.reserve(static_cast<std::size_t>(grid.height) + 1);
  runs.row_offsets.push_back(0);
  for (int row = 0; row < grid.height; ++row) {
    const float* cells = grid.cells.data() + static_cast<std::size_t>(row) * grid.width;
    int previous_level = -1;
    int col = 0;
    while (col < grid.width) {
      // Cells with identical bits share a value; only the first of a stretch is converted.
      std::uint32_t bits;
      std::memcpy(&bits, &cells[col], sizeof bits);
      const int begin = col;
      for (++col; col < grid.width; ++col) {
        std::uint32_t next;
        std::memcpy(&next, &cells[col], sizeof next);
        if (next != bits) break;
      }
      const float p = cells[begin];
      const int length = col - begin;
      int level = LevelRuns::kUnknownLevel;
      if (OccupancyGrid::IsUnknown(p)) {
        runs.unknown_cells += length;
      } else {
        level = ImageValue(p);
        runs.known_histogram[level] += length;
      }
      if (level != previous_level) {  // different p can round to one value: one run
        runs.begin_col.push_back(begin);
        runs.level.push_back(static_cast<std::uint16_t>(level));
        previous_level = level;
      }
    }
    runs.row_offsets.push_back(static_cast<std::int32_t>(runs.begin_col.size()));
  }
  return runs;
}

}  // namespace slamsweep::evaluator::inline map_metrics
