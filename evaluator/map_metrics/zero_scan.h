#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "evaluator/map_metrics/run_components.h"

namespace slamsweep::evaluator::inline map_metrics {

// Scans of float images that are zero on most of their area (the structure images of the
// corner count). They work on bit patterns, in loops without branches per pixel, which
// compilers turn into vector code.

/// True when all `count` floats are +0 or -0.
inline bool AllZero(const float* values, int count) {
  std::uint32_t any = 0;
  for (int i = 0; i < count; ++i) {
    std::uint32_t bits;
    std::memcpy(&bits, &values[i], sizeof bits);
    any |= bits;
  }
  return (any & 0x7FFFFFFFu) == 0;
}

/// Largest |v| of NaN-free floats: with the sign bit cleared, the bit patterns of floats are
/// ordered as their magnitudes, so an integer maximum finds it.
inline float MaxAbs(const float* values, std::size_t count) {
  std::int32_t largest = 0;
  for (std::size_t i = 0; i < count; ++i) {
    std::int32_t bits;
    std::memcpy(&bits, &values[i], sizeof bits);
    bits &= 0x7FFFFFFF;
    largest = bits > largest ? bits : largest;
  }
  return std::bit_cast<float>(largest);
}

/// Appends the runs of one row of `width` pixels and closes the row, given its blocks of 32
/// pixels as bit masks: block_mask(block, n) returns bit k set when pixel block + k belongs to
/// a run (n = 32 but for the last block). Runs are read off the transitions of the masks.
template <typename BlockMask>
void AppendRunsFromMasks(int width, RowRuns& runs, BlockMask block_mask) {
  int open_begin = -1;
  for (int block = 0; block < width; block += 32) {
    const int n = width - block < 32 ? width - block : 32;
    const std::uint32_t set = block_mask(block, n);
    const std::uint32_t valid = n == 32 ? 0xFFFFFFFFu : (1u << n) - 1u;
    const std::uint32_t clear = ~set & valid;
    int k = 0;
    while (k < n) {
      const std::uint32_t rest = (open_begin < 0 ? set : clear) >> k;
      if (rest == 0) break;  // the current state lasts to the end of the block
      k += std::countr_zero(rest);
      if (open_begin < 0) {
        open_begin = block + k;
      } else {
        runs.Add(open_begin, block + k);
        open_begin = -1;
      }
    }
  }
  if (open_begin >= 0) runs.Add(open_begin, width);
  runs.EndRow();
}

/// Appends the runs of non-zero pixels of one row (+0 and -0 are zero) and closes the row.
inline void AppendNonZeroRuns(const float* pixels, int width, RowRuns& runs) {
  AppendRunsFromMasks(width, runs, [pixels](int block, int n) {
    std::uint32_t set = 0;
    for (int k = 0; k < n; ++k) {
      std::uint32_t bits;
      std::memcpy(&bits, &pixels[block + k], sizeof bits);
      set |= static_cast<std::uint32_t>((bits & 0x7FFFFFFFu) != 0) << k;
    }
    return set;
  });
}

}  // namespace slamsweep::evaluator::inline map_metrics
