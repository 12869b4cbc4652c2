#include "evaluator/map_metrics/scorable_grid.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "evaluator/core/input_error.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace slamsweep::evaluator::inline map_metrics {
namespace {

[[noreturn]] void ThrowBadCell(const OccupancyGrid& grid, std::size_t index) {
  const std::size_t row = index / static_cast<std::size_t>(grid.width);
  const std::size_t col = index % static_cast<std::size_t>(grid.width);
  std::ostringstream message;
  message << "map cell (row " << row << ", col " << col << ") holds " << grid.cells[index]
          << "; expected an occupancy probability in [0, 1] or unknown";
  throw InputError(message.str());
}

}  // namespace

ScorableGrid ScorableGrid::Check(const OccupancyGrid& grid) {
  if (grid.width <= 0 || grid.height <= 0) {
    throw InputError("map is empty (" + std::to_string(grid.width) + " x " + std::to_string(grid.height) +
                     " cells): nothing to score");
  }
  const std::size_t expected = static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height);
  if (grid.cells.size() != expected) {
    throw InputError("map has " + std::to_string(grid.cells.size()) + " cells; expected width x height = " +
                     std::to_string(grid.width) + " x " + std::to_string(grid.height));
  }
  // One branch-free pass (it vectorises) counts the cells and sums the known probabilities for
  // the occupied proportion; only when it finds a bad cell do we look for which one, so the
  // common case costs one read of the grid. The sum runs in four interleaved double
  // accumulators so that it is not one long chain of dependent adds; unknown cells (negative)
  // add +0 through a bit mask, not a branch.
  std::int64_t in_range = 0;
  std::int64_t unknown = 0;
  double partial[4] = {0.0, 0.0, 0.0, 0.0};
  const auto count = [&](float p) {
    in_range += static_cast<int>((p >= 0.0f) & (p <= 1.0f));  // NaN fails both tests
    unknown += static_cast<int>(p < 0.0f);
    const std::uint32_t keep = 0u - static_cast<std::uint32_t>(p >= 0.0f);
    return static_cast<double>(std::bit_cast<float>(std::bit_cast<std::uint32_t>(p) & keep));
  };
  const std::size_t n = grid.cells.size();
  const float* cells = grid.cells.data();
  std::size_t i = 0;
#if defined(__SSE2__)
  // The same four accumulators as two SSE2 registers (partial 0 and 1, 2 and 3): the same adds in
  // the same order, four cells per step; counts in 32-bit lanes, flushed before they could overflow.
  __m128d sum01 = _mm_setzero_pd();
  __m128d sum23 = _mm_setzero_pd();
  const __m128 zero = _mm_setzero_ps();
  const __m128 one = _mm_set1_ps(1.0f);
  while (i + 4 <= n) {
    __m128i in_range_lanes = _mm_setzero_si128();
    __m128i unknown_lanes = _mm_setzero_si128();
    const std::size_t block_end = std::min(n - n % 4, i + (std::size_t{1} << 28));
    for (; i < block_end; i += 4) {
      const __m128 p = _mm_loadu_ps(cells + i);
      const __m128 known = _mm_cmpge_ps(p, zero);  // false for NaN, as p >= 0.0f
      in_range_lanes = _mm_sub_epi32(in_range_lanes, _mm_castps_si128(_mm_and_ps(known, _mm_cmple_ps(p, one))));
      unknown_lanes = _mm_sub_epi32(unknown_lanes, _mm_castps_si128(_mm_cmplt_ps(p, zero)));
      const __m128 kept = _mm_and_ps(p, known);
      sum01 = _mm_add_pd(sum01, _mm_cvtps_pd(kept));
      sum23 = _mm_add_pd(sum23, _mm_cvtps_pd(_mm_movehl_ps(kept, kept)));
    }
    alignas(16) std::int32_t lanes[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(lanes), in_range_lanes);
    in_range += std::int64_t{lanes[0]} + lanes[1] + lanes[2] + lanes[3];
    _mm_store_si128(reinterpret_cast<__m128i*>(lanes), unknown_lanes);
    unknown += std::int64_t{lanes[0]} + lanes[1] + lanes[2] + lanes[3];
  }
  _mm_storeu_pd(partial, sum01);
  _mm_storeu_pd(partial + 2, sum23);
#else
  for (; i + 4 <= n; i += 4) {
    for (int k = 0; k < 4; ++k) partial[k] += count(cells[i + k]);
  }
#endif
  for (; i < n; ++i) partial[0] += count(cells[i]);
  const std::int64_t known = in_range;
  if (in_range + unknown != static_cast<std::int64_t>(grid.cells.size())) {
    for (std::size_t i = 0; i < grid.cells.size(); ++i) {
      const float p = grid.cells[i];
      if (!OccupancyGrid::IsUnknown(p) && !(p >= 0.0f && p <= 1.0f)) ThrowBadCell(grid, i);
    }
  }
  if (known == 0) throw InputError("map has no known cell: nothing to score");
  return ScorableGrid(grid, known, (partial[0] + partial[1]) + (partial[2] + partial[3]));
}

}  // namespace slamsweep::evaluator::inline map_metrics
