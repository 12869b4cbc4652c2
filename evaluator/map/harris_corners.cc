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

  // One pass over the computed areas collects the positive local maxima of the 3 x 3
  // neighbourhood (goodFeaturesToTrack's dilation test, which never looks at the outermost rows
  // and columns) and the largest response. Only positive responses matter: the threshold
  // quality_level * max is positive when any corner exists, and pixels never computed are 0.
  // A pixel survives the dilation test on the thresholded image when it is above the
  // threshold and not below any neighbour (neighbours zeroed by the threshold are below it
  // anyway), so filtering these maxima by the threshold afterwards gives the same set.
  std::vector<Candidate> candidates;
  float max_response = 0.0f;
  constexpr int kBlock = 16;
  for (const cv::Rect& area : computed_areas) {
    for (int row = area.y; row < area.y + area.height; ++row) {
      const float* here = response.ptr<float>(row);
      const bool interior_row = row >= 1 && row + 1 < image.rows;
      const float* above = interior_row ? response.ptr<float>(row - 1) : here;
      const float* below = interior_row ? response.ptr<float>(row + 1) : here;
      for (int block = area.x; block < area.x + area.width; block += kBlock) {
        const int block_end = std::min(area.x + area.width, block + kBlock);
        int any_positive = 0;  // a branch-free test that vectorises: most blocks have none
        for (int col = block; col < block_end; ++col) any_positive |= static_cast<int>(here[col] > 0.0f);
        if (any_positive == 0) continue;
        for (int col = block; col < block_end; ++col) {
          const float v = here[col];
          if (!(v > 0.0f)) continue;
          max_response = std::max(max_response, v);
          if (!interior_row || col < 1 || col + 1 >= image.cols) continue;
          if (v < above[col - 1] || v < above[col] || v < above[col + 1] || v < here[col - 1] || v < here[col + 1] ||
              v < below[col - 1] || v < below[col] || v < below[col + 1]) {
            continue;
          }
          candidates.push_back({v, static_cast<std::int64_t>(row) * image.cols + col});
        }
      }
    }
  }
  if (!(max_response > 0.0f)) return corners;
  // cv::threshold with THRESH_TOZERO compares a float image with a float threshold.
  const float threshold = static_cast<float>(static_cast<double>(max_response) * options.quality_level);
  candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                  [threshold](const Candidate& c) { return !(c.response > threshold); }),
                   candidates.end());
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
