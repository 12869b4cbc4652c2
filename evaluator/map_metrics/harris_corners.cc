#include "evaluator/map_metrics/harris_corners.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "evaluator/map_metrics/two_thread_sequence.h"

namespace slamsweep::evaluator::inline map_metrics {
namespace {

struct Candidate {
  float response;
  std::int64_t index;  // row * width + col: the order of addresses in goodFeaturesToTrack
};

// cv::threshold with THRESH_TOZERO compares a float image with a float threshold.
float Threshold(float max_response, double quality_level) {
  return static_cast<float>(static_cast<double>(max_response) * quality_level);
}

// Largest response of a band (0 when nothing was computed): a branch-free reduction that vectorises.
float MaxResponse(const HarrisResponseBand& band) {
  float largest = 0.0f;
  for (const cv::Rect& area : band.computed_areas) {
    for (int row = area.y; row < area.y + area.height; ++row) {
      const float* here = band.response.ptr<float>(row - band.first_row);
      for (int col = area.x; col < area.x + area.width; ++col) largest = here[col] > largest ? here[col] : largest;
    }
  }
  return largest;
}

// goodFeaturesToTrack keeps the pixels above quality_level * max response (a positive threshold
// whenever a corner exists; pixels never computed are 0) that are not below any of their 8
// neighbours, away from the outermost rows and columns. Neighbours zeroed by its threshold are
// below such a pixel anyway, so testing against the raw neighbours gives the same set, and the
// local-maximum test does not depend on the threshold: any threshold up to the final one may sort
// out candidates early, the final one is applied once every band is seen.
//
// Appends the local maxima above `threshold` of `band`'s computed areas in image rows
// [row_begin, row_end); `above` is the image row just above the band and `below` the one just below
// it, read only where a searched row needs them.
void SearchRows(const HarrisResponseBand& band, int row_begin, int row_end, const float* above_band,
                const float* below_band, int image_rows, int image_cols, float threshold,
                std::vector<Candidate>& candidates) {
  constexpr int kBlock = 16;
  const int band_end = band.first_row + band.response.rows;
  const auto row_pointer = [&](int row) -> const float* {
    if (row < band.first_row) return above_band;
    if (row >= band_end) return below_band;
    return band.response.ptr<float>(row - band.first_row);
  };
  for (const cv::Rect& area : band.computed_areas) {
    const int first = std::max({area.y, row_begin, 1});
    const int last = std::min({area.y + area.height, row_end, image_rows - 1});
    for (int row = first; row < last; ++row) {
      const float* here = row_pointer(row);
      const float* above = row_pointer(row - 1);
      const float* below = row_pointer(row + 1);
      const int col_end = std::min(area.x + area.width, image_cols - 1);
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
          candidates.push_back({v, static_cast<std::int64_t>(row) * image_cols + col});
        }
      }
    }
  }
}

// A band with what can be found in it alone: its largest response and the local maxima of the
// rows whose neighbours are all in it (above the band's own largest response times the quality
// level, at most the final threshold). Made on either thread.
struct SearchedBand {
  HarrisResponseBand band;
  float max_response = 0.0f;
  std::vector<Candidate> inner;
};

SearchedBand SearchBand(HarrisResponseBand band, int image_rows, int image_cols, double quality_level) {
  SearchedBand searched;
  searched.max_response = MaxResponse(band);
  const int first = band.first_row + 1;
  const int last = band.first_row + band.response.rows - 1;
  SearchRows(band, first, last, nullptr, nullptr, image_rows, image_cols,
             Threshold(searched.max_response, quality_level), searched.inner);
  searched.band = std::move(band);
  return searched;
}

// The bands in order, top to bottom: gathers their inner local maxima and searches the rows
// where two bands meet.
class LocalMaximaSearch {
 public:
  LocalMaximaSearch(const cv::Mat& image, double quality_level)
      : rows_(image.rows), cols_(image.cols), quality_level_(quality_level) {}

  void Add(SearchedBand& searched) {
    max_response_ = std::max(max_response_, searched.max_response);
    candidates_.insert(candidates_.end(), searched.inner.begin(), searched.inner.end());
    const HarrisResponseBand& band = searched.band;
    if (previous_.response.empty()) {
      SearchRows(band, band.first_row, band.first_row + 1, nullptr, nullptr, rows_, cols_, threshold(), candidates_);
    } else {
      const int previous_last = band.first_row - 1;
      const float* previous_row = previous_.response.ptr<float>(previous_.response.rows - 1);
      SearchRows(previous_, previous_last, previous_last + 1, nullptr, band.response.ptr<float>(0), rows_, cols_,
                 threshold(), candidates_);
      SearchRows(band, band.first_row, band.first_row + 1, previous_row, nullptr, rows_, cols_, threshold(),
                 candidates_);
    }
    previous_ = band;  // the image's last row is never searched: no band comes below the last one
  }

  /// The local maxima above the final threshold, once every band was added.
  std::vector<Candidate> Finish() {
    if (!(max_response_ > 0.0f)) return {};
    const float final_threshold = threshold();
    std::erase_if(candidates_, [final_threshold](const Candidate& c) { return !(c.response > final_threshold); });
    return std::move(candidates_);
  }

 private:
  float threshold() const { return Threshold(max_response_, quality_level_); }

  int rows_;
  int cols_;
  double quality_level_;
  float max_response_ = 0.0f;
  HarrisResponseBand previous_;
  std::vector<Candidate> candidates_;
};

}  // namespace

std::vector<CornerCell> FindHarrisCorners(const cv::Mat& image, const HarrisSelectionOptions& options,
                                          const RowRuns* nonzero) {
  std::vector<CornerCell> corners;
  if (image.empty()) return corners;
  CV_Assert(image.type() == CV_32FC1);
  const HarrisResponseOptions response_options{options.block_size_cells, options.aperture_cells, options.harris_k};
  const HarrisResponseBands bands(image, response_options, nonzero);
  LocalMaximaSearch search(image, options.quality_level);
  // Both cores compute bands and search inside them; the rows where bands meet are searched here,
  // in order.
  ForEachInOrderOnTwoThreads<SearchedBand>(
      bands.count(),
      [&](int index) { return SearchBand(bands.Compute(index), image.rows, image.cols, options.quality_level); },
      [&](int, SearchedBand searched) { search.Add(searched); });
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
