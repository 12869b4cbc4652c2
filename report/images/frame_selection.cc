#include "report/images/frame_selection.h"

namespace slamsweep::report::inline images {

std::vector<std::size_t> EvenlySpacedIndices(std::size_t count, std::size_t keep) {
  std::vector<std::size_t> indices;
  if (count == 0 || keep == 0) return indices;
  if (keep == 1) return {count - 1};
  if (keep > count) keep = count;
  indices.reserve(keep);
  for (std::size_t i = 0; i < keep; ++i) {
    // Integer rounding of i (count - 1) / (keep - 1): exact, so the last index is count - 1.
    indices.push_back((2 * i * (count - 1) + (keep - 1)) / (2 * (keep - 1)));
  }
  return indices;
}

}  // namespace slamsweep::report::inline images
