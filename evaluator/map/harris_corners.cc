#include "evaluator/map/harris_corners.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace slamsweep::evaluator {
namespace {

struct Candidate {
  float response;
  std::int64_t index;  // row * width + col: the order of addresses in goodFeaturesToTrack
};

}  // namespace

std::vector<CornerCell> FindHarrisCorners(const cv::Mat& image, const HarrisSelectionOptions& options,
                                          const RowRuns* nonzero) {
  std::vector<CornerCell> corners;
  if (image.empty()) return corners;
  CV_Assert(image.type() == CV_32FC1);
  std::vector<cv::Rect> computed_areas;
  const HarrisResponseOptions response_options{options.block_size_cells, options.aperture_cells, options.harris_k};
  const cv::Mat response = SparseHarrisResponse(image, response_options, nonzero, computed_areas);

  // goodFeaturesToTrack keeps the pixels above quality_level * max response (a positive
  // threshold whenever a corner exists; pixels never computed are 0) that are not below any
  // of their 8 neighbours, away from the outermost rows and columns. Neighbours zeroed by its
  // threshold are below such a pixel anyway, so testing against the raw neighbours gives the
  // same set. Two passes: the largest response first, then only the few blocks holding a
  // pixel above the threshold are searched for local maxima (most of the map has none).
  constexpr int kBlock = 16;
  float max_response = 0.0f;
  for (const cv::Rect& area : computed_areas) {
    for (int row = area.y; row < area.y + area.height; ++row) {
      const float* here = response.ptr<float>(row);
      float row_max = 0.0f;  // a branch-free reduction that vectorises
      for (int col = area.x; col < area.x + area.width; ++col) row_max = here[col] > row_max ? here[col] : row_max;
      max_response = std::max(max_response, row_max);
    }
  }
  if (!(max_response > 0.0f)) return corners;
  // cv::threshold with THRESH_TOZERO compares a float image with a float threshold.
  const float threshold = static_cast<float>(static_cast<double>(max_response) * options.quality_level);

  std::vector<Candidate> candidates;
  for (const cv::Rect& area : computed_areas) {
    for (int row = std::max(area.y, 1); row < std::min(area.y + area.height, image.rows - 1); ++row) {
      const float* here = response.ptr<float>(row);
      const float* above = response.ptr<float>(row - 1);
      const float* below = response.ptr<float>(row + 1);
      const int col_end = std::min(area.x + area.width, image.cols - 1);
      for (int block = std::max(area.x, 1); block < col_end; block += kBlock) {
        const int block_end = std::min(col_end, block + kBlock);
        int any_above = 0;  // branch-free, vectorises
        for (int col = block; col < block_end; ++col) any_above |= static_cast<int>(here[col] > threshold);
        if (any_above == 0) continue;
        for (int col = block; col < block_end; ++col) {
          const float v = here[col];
          if (!(v > threshold)) continue;
          if (v < above[col - 1] || v < above[col] || v < above[col + 1] || v < here[col - 1] || v < here[col + 1] ||
              v < below[col - 1] || v < below[col] || v < below[col + 1]) {
            continue;
          }
          candidates.push_back({v, static_cast<std::int64_t>(row) * image.cols + col});
        }
      }
    }
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.response != b.response ? a.response > b.response : a.index > b.index;
  });

  const int width = image.cols;
  if (options.min_distance_cells < 1.0) {
    for (const Candidate& c : candidates)
      corners.push_back({static_cast<int>(c.index / width), static_cast<int>(c.index % width)});
    return corners;
  }
  // goodFeaturesToTrack's acceptance grid: cells of round(min_distance), and a new corner is
  // compared with the accepted ones in its own and the 8 surrounding cells.
  const int cell = static_cast<int>(std::lrint(options.min_distance_cells));
  const int grid_cols = (image.cols + cell - 1) / cell;
  const int grid_rows = (image.rows + cell - 1) / cell;
  const double min_distance_squared = options.min_distance_cells * options.min_distance_cells;
  std::vector<std::vector<CornerCell>> grid(static_cast<std::size_t>(grid_cols) * grid_rows);
  for (const Candidate& c : candidates) {
    const int row = static_cast<int>(c.index / width);
    const int col = static_cast<int>(c.index % width);
    const int grid_row = row / cell;
    const int grid_col = col / cell;
    bool far_enough = true;
    for (int gr = std::max(0, grid_row - 1); gr <= std::min(grid_rows - 1, grid_row + 1) && far_enough; ++gr) {
      for (int gc = std::max(0, grid_col - 1); gc <= std::min(grid_cols - 1, grid_col + 1) && far_enough; ++gc) {
        for (const CornerCell& other : grid[static_cast<std::size_t>(gr) * grid_cols + gc]) {
          const double dr = row - other.row;
          const double dc = col - other.col;
          if (dr * dr + dc * dc < min_distance_squared) {
            far_enough = false;
            break;
          }
        }
      }
    }
    if (!far_enough) continue;
    grid[static_cast<std::size_t>(grid_row) * grid_cols + grid_col].push_back({row, col});
    corners.push_back({row, col});
  }
  return corners;
}

}  // namespace slamsweep::evaluator
