#include "orchestrator/adapters/stage_image.h"

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "evaluator/formats/map/map_options.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace slamsweep::orchestrator::inline adapters {

namespace {

/// The smallest float p with 100.0 * p >= percent (computed in double, as the rule does): the
/// product is monotonic in p, so comparing p with it decides exactly what comparing the product
/// with `percent` decides.
float SmallestWithPercentAtLeast(double percent) {
  float p = static_cast<float>(percent / 100.0);
  while (100.0 * static_cast<double>(p) < percent) p = std::nextafter(p, 2.0f);
  while (100.0 * static_cast<double>(std::nextafter(p, -1.0f)) >= percent) p = std::nextafter(p, -1.0f);
  return p;
}

#if defined(__SSE2__)
/// Sixteen 32-bit compare masks (all ones or zero) as sixteen byte masks, in order.
__m128i PackMasks(const __m128i (&lanes)[4]) {
  return _mm_packs_epi16(_mm_packs_epi32(lanes[0], lanes[1]), _mm_packs_epi32(lanes[2], lanes[3]));
}
#endif

}  // namespace

cv::Mat StageImage(const evaluator::OccupancyGrid& grid) {
  const evaluator::MapWriteOptions thresholds;
  // For v = lround(100 p) (halves away from zero): v >= T exactly when 100 p >= T - 0.5, and
  // v <= F exactly when 100 p < F + 0.5, i.e. when p is below the smallest float reaching it. A NaN
  // p rounds to LONG_MIN, i.e. free, and fails `p >= free_from` too. Float comparisons instead of a
  // libm call per cell, sixteen cells per SSE2 step.
  const float occupied_from = SmallestWithPercentAtLeast(thresholds.occupied_threshold_percent - 0.5);
  const float free_from = SmallestWithPercentAtLeast(thresholds.free_threshold_percent + 0.5);
  cv::Mat image(grid.height, grid.width, CV_8UC1);
  const std::size_t width = static_cast<std::size_t>(grid.width);
  for (int row = 0; row < grid.height; ++row) {
    auto* out = image.ptr<std::uint8_t>(row);
    const float* cells = grid.cells.data() + static_cast<std::size_t>(row) * width;
    std::size_t col = 0;
#if defined(__SSE2__)
    // The three float compares become byte masks that pick the grey.
    const __m128 occupied = _mm_set1_ps(occupied_from);
    const __m128 free = _mm_set1_ps(free_from);
    const __m128 zero = _mm_setzero_ps();
    const __m128i unknown_grey = _mm_set1_epi8(static_cast<char>(kStageUnknown));
    const __m128i free_grey = _mm_set1_epi8(static_cast<char>(kStageFree));
    for (; col + 16 <= width; col += 16) {
      __m128i occupied_lanes[4];
      __m128i free_lanes[4];
      __m128i unknown_lanes[4];
      for (int k = 0; k < 4; ++k) {
        const __m128 p = _mm_loadu_ps(cells + col + 4 * static_cast<std::size_t>(k));
        occupied_lanes[k] = _mm_castps_si128(_mm_cmpge_ps(p, occupied));  // false for NaN
        free_lanes[k] = _mm_castps_si128(_mm_cmpnge_ps(p, free));         // true for NaN, as the rule
        unknown_lanes[k] = _mm_castps_si128(_mm_cmplt_ps(p, zero));       // false for NaN, as IsUnknown
      }
      const __m128i is_occupied = PackMasks(occupied_lanes);
      const __m128i is_free = PackMasks(free_lanes);
      const __m128i is_unknown = PackMasks(unknown_lanes);
      __m128i grey = _mm_andnot_si128(is_occupied, unknown_grey);  // kStageOccupied is 0
      grey = _mm_or_si128(_mm_and_si128(is_free, free_grey), _mm_andnot_si128(is_free, grey));
      grey = _mm_or_si128(_mm_and_si128(is_unknown, unknown_grey), _mm_andnot_si128(is_unknown, grey));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(out + col), grey);
    }
#endif
    for (; col < width; ++col) {
      const float p = cells[col];
      std::uint8_t grey = p >= occupied_from ? kStageOccupied : kStageUnknown;
      grey = !(p >= free_from) ? static_cast<std::uint8_t>(kStageFree) : grey;
      out[col] = evaluator::OccupancyGrid::IsUnknown(p) ? static_cast<std::uint8_t>(kStageUnknown) : grey;
    }
  }
  return image;
}

}  // namespace slamsweep::orchestrator::inline adapters
