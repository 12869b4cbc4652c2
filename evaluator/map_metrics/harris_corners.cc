#include "evaluator/map_metrics/harris_corners.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace slamsweep::evaluator::inline map_metrics {
namespace {

struct Candidate {
  float response;
  std::int64_t index;  // row * width + col: the order of addresses in goodFeaturesToTrack
};

// goodFeaturesToTrack keeps the pixels above quality_level * max response (a positive
// threshold whenever a corner exists; pixels never computed are 0) that are not below any of
// their 8 neighbours, away from the outermost rows and columns. Neighbours zeroed by its
// threshold are below such a pixel anyway, so testing against the raw neighbours gives the
// same set, and the local-maximum test does not depend on the threshold: the bands of the
// response are searched as they come (each needs one row of its neighbours), keeping the local
// maxima above the threshold of the largest response so far, which never exceeds the final
// one; the final threshold is applied once every band is seen.
class LocalMaximaSearch {
 public:
  LocalMaximaSearch(const cv::Mat& image, double quality_level)
      : rows_(image.rows), cols_(image.cols), quality_level_(quality_level) {}

  void Add(const HarrisResponseBand& band) {
    for (const cv::Rect& area : band.computed_areas) {
      for (int row = area.y; row < area.y + area.height; ++row) {
        const float* here = band.response.ptr<float>(row - band.first_row);
        float row_max = 0.0f;  // a branch-free reduction that vectorises
        for (int col = area.x; col < area.x + area.width; ++col) row_max = here[col] > row_max ? here[col] : row_max;
        max_response_ = std::max(max_response_, row_max);
      }
    }
    if (!pending_.empty()) Search(pending_[pending_.size() - 1], &band);
    if (pending_.size() == 2) pending_.erase(pending_.begin());
    pending_.push_back(band);
  }

  /// The local maxima above the final threshold, once every band was added.
  std::vector<Candidate> Finish() {
    if (!pending_.empty()) Search(pending_.back(), nullptr);
    pending_.clear();
    if (!(max_response_ > 0.0f)) return {};
    const float threshold = Threshold();
    std::erase_if(candidates_, [threshold](const Candidate& c) { return !(c.response > threshold); });
    return std::move(candidates_);
  }

 private:
  // cv::threshold with THRESH_TOZERO compares a float image with a float threshold.
  float Threshold() const { return static_cast<float>(static_cast<double>(max_response_) * quality_level_); }

  // The local maxima of `band`, whose neighbours are the last row of the band added before it
  // (pending_ holds it, when there is one) and the first row of `next`.
  void Search(const HarrisResponseBand& band, const HarrisResponseBand* next) {
    constexpr int kBlock = 16;
    const float threshold = Threshold();
    const HarrisResponseBand* before = pending_.size() == 2 ? &pending_[0] : nullptr;
    const int band_end = band.first_row + band.response.rows;
    const auto row_pointer = [&](int row) -> const float* {
      if (row < band.first_row) return before->response.ptr<float>(before->response.rows - 1);
      if (row >= band_end) return next->response.ptr<float>(0);
      return band.response.ptr<float>(row - band.first_row);
    };
    for (const cv::Rect& area : band.computed_areas) {
      for (int row = std::max(area.y, 1); row < std::min(area.y + area.height, rows_ - 1); ++row) {
        const float* here = row_pointer(row);
        const float* above = row_pointer(row - 1);
        const float* below = row_pointer(row + 1);
        const int col_end = std::min(area.x + area.width, cols_ - 1);
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
            candidates_.push_back({v, static_cast<std::int64_t>(row) * cols_ + col});
          }
        }
      }
    }
  }

  int rows_;
  int cols_;
  double quality_level_;
  float max_response_ = 0.0f;
  std::vector<HarrisResponseBand> pending_;  // the band searched next, and the one before it
  std::vector<Candidate> candidates_;
};

}  // namespace

std::vector<CornerCell> FindHarrisCorners(const cv::Mat& image, const HarrisSelectionOptions& options,
                                          const RowRuns* nonzero) {
  std::vector<CornerCell> corners;
  if (image.empty()) return corners;
  CV_Assert(image.type() == CV_32FC1);
  const HarrisResponseOptions response_options{options.block_size_cells, options.aperture_cells, options.harris_k};
  LocalMaximaSearch search(image, options.quality_level);
  ForEachHarrisResponseBand(image, response_options, nonzero,
                            [&search](const HarrisResponseBand& band) { search.Add(band); });
  std::vector<Candidate> candidates = search.Finish();
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

}  // namespace slamsweep::evaluator::inline map_metrics
