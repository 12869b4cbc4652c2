#include "evaluator/map_metrics/harris_area.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <opencv2/imgproc.hpp>
#include <utility>
#include <vector>

// Built with -ffp-contract=off (CMakeLists.txt): every product and sum below is rounded on its own,
// as in OpenCV's code, never fused into an FMA. The loops run over one channel at a time so that
// the compiler turns them into vector code; the arithmetic per cell stays the same.

namespace slamsweep::evaluator::inline map_metrics {
namespace {

constexpr int kChannels = 3;  // dx*dx, dx*dy, dy*dy

// cornerHarris's final step in its three forms (see the header for which cells take which).
[[gnu::always_inline]] inline float HarrisWide(float a, float b, float c, float k) {
  const float s = a + c;
  return (a * c - b * b) - k * (s * s);
}
[[gnu::always_inline]] inline float HarrisFour(float a, float b, float c, float k) {
  const float s = a + c;
  return (a * c - b * b) - (k * s) * s;
}
[[gnu::always_inline]] inline float HarrisScalar(float a, float b, float c, double k) {
  return static_cast<float>(a * c - b * b - k * (a + c) * (a + c));
}

// The three channels of one cell side by side (the fourth lane is 0): the running sums of the
// three channels advance together, one vector operation for the three scalar ones of OpenCV.
using Float4 = float __attribute__((vector_size(16)));
using Double4 = double __attribute__((vector_size(32)));

// Row and column sums live in plain double arrays (4 a cell), read and written without any
// alignment assumption.
[[gnu::always_inline]] inline Double4 Load(const double* at) {
  Double4 value;
  std::memcpy(&value, at, sizeof value);
  return value;
}
[[gnu::always_inline]] inline void Store(double* at, Double4 value) { std::memcpy(at, &value, sizeof value); }

[[gnu::always_inline]] inline Double4 Products(const float* dx, const float* dy, int col) {
  const float x = dx[col];
  const float y = dy[col];
  const Float4 left = {x, x, y, 0.0f};
  const Float4 right = {x, y, y, 0.0f};
  return __builtin_convertvector(left * right, Double4);
}

// The box filter's row pass over `n` rows of the call area (1 or 2), for the kept columns: s starts
// as (0 + X[1]) + X[0] (column -1 reflected to 1), then s += X[c] - X[c - 2] column by column, in
// double. Row i's sums go to sums[i] from column kept_begin on, 4 doubles a cell. Two rows advance
// side by side so that their chains of dependent additions overlap in the processor.
template <int n>
[[gnu::always_inline]] inline void RowPasses(const float* const* dx, const float* const* dy, int kept_begin,
                                             int kept_end, double* const* sums) {
  Double4 back2[n];  // X[c - 2], starting as X[-1] = X[1]
  Double4 back1[n];  // X[c - 1]
  Double4 s[n];
  for (int i = 0; i < n; ++i) {
    back2[i] = Products(dx[i], dy[i], 1);
    back1[i] = Products(dx[i], dy[i], 0);
    s[i] = Double4{} + back2[i];
    s[i] += back1[i];
    if (kept_begin == 0) Store(sums[i], s[i]);
  }
  for (int c = 1; c < kept_end; ++c) {
    for (int i = 0; i < n; ++i) {
      const Double4 here = Products(dx[i], dy[i], c);
      s[i] += here - back2[i];
      back2[i] = back1[i];
      back1[i] = here;
      if (c >= kept_begin) Store(sums[i] + 4 * static_cast<std::size_t>(c - kept_begin), s[i]);
    }
  }
}

// The block sums and the response from the derivatives of the call area. Also compiled for AVX2,
// picked at run time where the processor has it: the same IEEE operations either way, the four
// lanes of a Double4 in one register instead of two.
__attribute__((target_clones("avx2", "default"))) void BoxSumResponse(const cv::Mat& dx, const cv::Mat& dy,
                                                                      cv::Rect call_area, cv::Rect kept,
                                                                      double harris_k, cv::Mat& out) {
  const int kept_begin = kept.x - call_area.x;
  const int kept_end = kept_begin + kept.width;
  const int first_row = kept.y - call_area.y;
  const int end_row = first_row + kept.height;
  const int width = kept.width;

  const std::size_t lanes = 4 * static_cast<std::size_t>(width);
  // Row sums of the row above the one in hand and of the next two rows.
  std::array<std::vector<double>, 3> row_sums = {std::vector<double>(lanes), std::vector<double>(lanes),
                                                 std::vector<double>(lanes)};
  std::vector<double> column_sums(lanes);
  std::array<std::vector<float>, kChannels> box = {std::vector<float>(width), std::vector<float>(width),
                                                   std::vector<float>(width)};

  // The final step's forms by the cell's position in the call area taken as one row.
  const std::int64_t cells = static_cast<std::int64_t>(call_area.width) * call_area.height;
  const std::int64_t wide_end = cells / 8 * 8;
  const std::int64_t four_end = cells - wide_end >= 4 ? wide_end + 4 : wide_end;
  const float k = static_cast<float>(harris_k);

  // The column pass on `row`, whose row sums are `here` (the row above's: `above`): s = SUM + R[r]
  // rounded to float, then SUM = s - R[r - 1]; then the row's response when it is kept.
  const auto finish_row = [&](int row, const double* here, const double* above) {
    float* a = box[0].data();
    float* b = box[1].data();
    float* c = box[2].data();
    for (int col = 0; col < width; ++col) {
      const std::size_t at = 4 * static_cast<std::size_t>(col);
      const Double4 sum = Load(&column_sums[at]) + Load(&here[at]);
      const Float4 rounded = __builtin_convertvector(sum, Float4);
      a[col] = rounded[0];
      b[col] = rounded[1];
      c[col] = rounded[2];
      Store(&column_sums[at], sum - Load(&above[at]));
    }
    if (row < first_row) return;
    float* response = out.ptr<float>(row - first_row);
    for (int col = 0; col < width; ++col) response[col] = HarrisWide(a[col], b[col], c[col], k);
    // Cells past the last multiple of 8 of the call area, if this row holds any.
    const std::int64_t row_start = static_cast<std::int64_t>(row) * call_area.width + kept_begin;
    for (std::int64_t position = std::max(wide_end, row_start); position < row_start + width; ++position) {
      const int col = static_cast<int>(position - row_start);
      response[col] =
          position < four_end ? HarrisFour(a[col], b[col], c[col], k) : HarrisScalar(a[col], b[col], c[col], harris_k);
    }
  };

  // The column pass starts with SUM = 0 + R[-1] (row -1 reflected to 1).
  double* above = row_sums[0].data();
  double* next[2] = {row_sums[1].data(), row_sums[2].data()};
  {
    const float* x = dx.ptr<float>(1);
    const float* y = dy.ptr<float>(1);
    RowPasses<1>(&x, &y, kept_begin, kept_end, &above);
  }
  for (std::size_t i = 0; i < lanes; ++i) column_sums[i] = 0.0 + above[i];
  for (int row = 0; row < end_row; row += 2) {
    const bool pair = row + 1 < end_row;
    const float* x[2] = {dx.ptr<float>(row), dx.ptr<float>(pair ? row + 1 : row)};
    const float* y[2] = {dy.ptr<float>(row), dy.ptr<float>(pair ? row + 1 : row)};
    if (pair) {
      RowPasses<2>(x, y, kept_begin, kept_end, next);
    } else {
      RowPasses<1>(x, y, kept_begin, kept_end, next);
    }
    finish_row(row, next[0], above);
    if (!pair) break;
    finish_row(row + 1, next[1], next[0]);
    std::swap(above, next[1]);  // the pair's second row is the next row above; the others take the next pair
  }
}

}  // namespace

bool HarrisAreaSupported(int block_size_cells, cv::Size call_area) {
  return block_size_cells == 2 && call_area.width >= 2 && call_area.height >= 2;
}

void HarrisResponseOfArea(const cv::Mat& image, cv::Rect call_area, cv::Rect kept, int aperture_cells, double harris_k,
                          cv::Mat out) {
  CV_Assert(image.type() == CV_32FC1 && HarrisAreaSupported(2, call_area.size()));
  CV_Assert((kept & call_area) == kept && out.type() == CV_32FC1 && out.size() == kept.size());
  // cornerHarris's derivative scale for a 2 x 2 block: 1 / (2^(aperture - 1) * 2).
  const double scale = 1.0 / (static_cast<double>(1 << (aperture_cells - 1)) * 2.0);
  cv::Mat dx, dy;
  cv::Sobel(image(call_area), dx, CV_32F, 1, 0, aperture_cells, scale, 0, cv::BORDER_DEFAULT);
  cv::Sobel(image(call_area), dy, CV_32F, 0, 1, aperture_cells, scale, 0, cv::BORDER_DEFAULT);
  BoxSumResponse(dx, dy, call_area, kept, harris_k, out);
}

}  // namespace slamsweep::evaluator::inline map_metrics
