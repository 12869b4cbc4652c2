#include "evaluator/map_metrics/sparse_harris_response.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "evaluator/map_metrics/harris_area.h"
#include "evaluator/map_metrics/zero_scan.h"

namespace slamsweep::evaluator::inline map_metrics {

namespace {

constexpr int kTileCells = 64;

// How far (in cells) the response at a pixel looks into the image: the derivative kernel's
// radius (a 1-wide aperture still reads one neighbour) plus the block window.
int ResponseReach(const HarrisResponseOptions& options) {
  return std::max(1, options.aperture_cells / 2) + options.block_size_cells;
}

}  // namespace

// Bounding box of the non-zero pixels of one tile (empty when max_row < 0).
struct TileExtent {
  int min_row = std::numeric_limits<int>::max();
  int max_row = -1;
  int min_col = std::numeric_limits<int>::max();
  int max_col = -1;
};

// Tiles of 64 x 64 cells; the last tile of each row and column absorbs the remainder, so every
// tile is 64 to 127 cells on a side (the image is at least 128 x 128 here).
class TileGrid {
 public:
  // Extents from a scan of the image, or from runs covering its non-zero pixels.
  TileGrid(const cv::Mat& image, const RowRuns* nonzero)
      : image_rows_(image.rows),
        image_cols_(image.cols),
        rows_(image.rows / kTileCells),
        cols_(image.cols / kTileCells),
        extents_(static_cast<std::size_t>(rows_) * cols_) {
    for (int row = 0; row < image.rows; ++row) {
      if (nonzero != nullptr) {
        for (int run = nonzero->row_first_run(row); run < nonzero->row_end_run(row); ++run) {
          const int last = nonzero->end_col(run) - 1;
          for (int tile_col = std::min(nonzero->begin_col(run) / kTileCells, cols_ - 1);
               tile_col < cols_ && ColRange(tile_col).start <= last; ++tile_col) {
            const cv::Range cols = ColRange(tile_col);
            Extend(row, tile_col, std::max(cols.start, nonzero->begin_col(run)), std::min(cols.end - 1, last));
          }
        }
        continue;
      }
      const float* pixels = image.ptr<float>(row);
      for (int tile_col = 0; tile_col < cols_; ++tile_col) {
        const cv::Range cols = ColRange(tile_col);
        if (AllZero(pixels + cols.start, cols.size())) continue;
        int first = cols.start;
        while (pixels[first] == 0.0f) ++first;
        int last = cols.end - 1;
        while (pixels[last] == 0.0f) --last;
        Extend(row, tile_col, first, last);
      }
    }
  }

  int rows() const { return rows_; }
  int cols() const { return cols_; }
  void Extend(int row, int tile_col, int first_col, int last_col) {
    TileExtent& e = extents_[static_cast<std::size_t>(std::min(row / kTileCells, rows_ - 1)) * cols_ + tile_col];
    e.min_row = std::min(e.min_row, row);
    e.max_row = std::max(e.max_row, row);
    e.min_col = std::min(e.min_col, first_col);
    e.max_col = std::max(e.max_col, last_col);
  }
  cv::Range RowRange(int tile_row) const {
    return {tile_row * kTileCells, tile_row == rows_ - 1 ? image_rows_ : (tile_row + 1) * kTileCells};
  }
  cv::Range ColRange(int tile_col) const {
    return {tile_col * kTileCells, tile_col == cols_ - 1 ? image_cols_ : (tile_col + 1) * kTileCells};
  }
  cv::Rect Tile(int tile_row, int tile_col) const {
    const cv::Range rows = RowRange(tile_row);
    const cv::Range cols = ColRange(tile_col);
    return {cols.start, rows.start, cols.size(), rows.size()};
  }

  // True when a non-zero pixel lies within `reach` cells (Chebyshev) of the tile, so that its
  // response may be non-zero. reach <= kTileCells, so only the neighbouring tiles can hold one.
  bool Active(int tile_row, int tile_col, int reach) const {
    const cv::Rect tile = Tile(tile_row, tile_col);
    const int row0 = tile.y - reach;
    const int row1 = tile.y + tile.height - 1 + reach;
    const int col0 = tile.x - reach;
    const int col1 = tile.x + tile.width - 1 + reach;
    for (int r = std::max(0, tile_row - 1); r <= std::min(rows_ - 1, tile_row + 1); ++r) {
      for (int c = std::max(0, tile_col - 1); c <= std::min(cols_ - 1, tile_col + 1); ++c) {
        const TileExtent& e = extents_[static_cast<std::size_t>(r) * cols_ + c];
        if (e.max_row >= 0 && e.max_row >= row0 && e.min_row <= row1 && e.max_col >= col0 && e.min_col <= col1) {
          return true;
        }
      }
    }
    return false;
  }

 private:
  int image_rows_;
  int image_cols_;
  int rows_;
  int cols_;
  std::vector<TileExtent> extents_;
};

namespace {

// Computes the response of `area` (image coordinates) into the band that starts at image row
// `band_first_row`, running cv::cornerHarris on that area widened by `margin` (clipped to the
// image). cornerHarris reads the real pixels around a sub-image for its derivatives, but its
// block sum reflects at the sub-image's edge, hence the margin, which is computed and thrown
// away.
void HarrisOnArea(const cv::Mat& image, cv::Rect area, int margin, const HarrisResponseOptions& options,
                  int band_first_row, cv::Mat& band) {
  const cv::Rect widened =
      cv::Rect(area.x - margin, area.y - margin, area.width + 2 * margin, area.height + 2 * margin) &
      cv::Rect(0, 0, image.cols, image.rows);
  cv::Mat out = band(cv::Rect(area.x, area.y - band_first_row, area.width, area.height));
  if (HarrisAreaSupported(options.block_size_cells, widened.size())) {
    HarrisResponseOfArea(image, widened, area, options.aperture_cells, options.harris_k, out);
    return;
  }
  cv::Mat area_response;  // fresh, hence continuous like the whole-image call's (see below)
  cv::cornerHarris(image(widened), area_response, options.block_size_cells, options.aperture_cells, options.harris_k,
                   cv::BORDER_DEFAULT);
  area_response(cv::Rect(area.x - widened.x, area.y - widened.y, area.width, area.height)).copyTo(out);
}

// Zero outside `computed` (disjoint column spans covering whole rows of the band, left to right):
// only where nothing was computed is the fresh band written twice.
void ZeroOutside(const std::vector<cv::Rect>& computed, cv::Mat& band) {
  for (int row = 0; row < band.rows; ++row) {
    float* pixels = band.ptr<float>(row);
    int col = 0;
    for (const cv::Rect& span : computed) {
      std::fill(pixels + col, pixels + span.x, 0.0f);
      col = span.x + span.width;
    }
    std::fill(pixels + col, pixels + band.cols, 0.0f);
  }
}

// The band of tile row `tr`. cornerHarris's last step treats a continuous image as one long row
// and leaves a scalar remainder of fewer than 64 pixels at its end. A tile's sub-image ends with
// margin rows at least 64 wide, so its remainder is thrown away; the last tile row is computed as
// one full-width band starting at a multiple of 64 rows, so that its remainder is the same pixels
// as the whole-image call's. Consecutive active tiles of a tile row share one call (fewer calls,
// shared margins).
HarrisResponseBand ComputeBand(const cv::Mat& image, const TileGrid& tiles, int tr,
                               const HarrisResponseOptions& options) {
  const int reach = ResponseReach(options);
  const int margin = options.block_size_cells + 1;
  const int last_tile_row = tiles.rows() - 1;
  const cv::Range rows = tiles.RowRange(tr);
  HarrisResponseBand band;
  band.first_row = rows.start;
  band.response.create(rows.size(), image.cols, CV_32FC1);
  bool active = false;
  for (int tc = 0; tc < tiles.cols();) {
    if (!tiles.Active(tr, tc, reach)) {
      ++tc;
      continue;
    }
    const int first_tile = tc;
    while (tc < tiles.cols() && tiles.Active(tr, tc, reach)) ++tc;
    active = true;
    if (tr == last_tile_row) break;  // computed below, whole
    const cv::Rect span = tiles.Tile(tr, first_tile) | tiles.Tile(tr, tc - 1);
    band.computed_areas.push_back(span);
    HarrisOnArea(image, span, margin, options, band.first_row, band.response);
  }
  if (tr == last_tile_row && active) {
    const int band_row = std::max(0, (rows.start - margin) / 64 * 64);
    const cv::Rect call_area(0, band_row, image.cols, image.rows - band_row);
    const cv::Rect kept(0, rows.start, image.cols, rows.size());
    if (HarrisAreaSupported(options.block_size_cells, call_area.size())) {
      HarrisResponseOfArea(image, call_area, kept, options.aperture_cells, options.harris_k, band.response);
    } else {
      cv::Mat band_response;
      cv::cornerHarris(image(call_area), band_response, options.block_size_cells, options.aperture_cells,
                       options.harris_k, cv::BORDER_DEFAULT);
      band_response.rowRange(rows.start - band_row, band_response.rows).copyTo(band.response);
    }
    band.computed_areas.push_back(kept);
  }
  ZeroOutside(band.computed_areas, band.response);
  return band;
}

}  // namespace

HarrisResponseBands::HarrisResponseBands(const cv::Mat& image, const HarrisResponseOptions& options,
                                         const RowRuns* nonzero)
    : image_(image), options_(options) {
  if (image.empty()) return;
  whole_ = image.rows < 2 * kTileCells || image.cols < 2 * kTileCells || ResponseReach(options) > kTileCells;
  if (!whole_) tiles_ = std::make_shared<const TileGrid>(image, nonzero);
}

int HarrisResponseBands::count() const {
  if (image_.empty()) return 0;
  return whole_ ? 1 : tiles_->rows();
}

HarrisResponseBand HarrisResponseBands::Compute(int index) const {
  if (!whole_) return ComputeBand(image_, *tiles_, index, options_);
  HarrisResponseBand whole;
  cv::cornerHarris(image_, whole.response, options_.block_size_cells, options_.aperture_cells, options_.harris_k,
                   cv::BORDER_DEFAULT);
  whole.computed_areas.push_back(cv::Rect(0, 0, image_.cols, image_.rows));
  return whole;
}

}  // namespace slamsweep::evaluator::inline map_metrics
