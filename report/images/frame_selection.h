#pragma once

#include <cstddef>
#include <vector>

namespace slamsweep::report::inline images {

/// `keep` indices out of 0..count-1, evenly spread, ascending and distinct, always holding the
/// first and the last (when keep >= 2): index i of the result is round(i (count - 1) / (keep - 1)).
/// keep >= count gives every index; keep == 1 gives {count - 1} (the finished map); keep == 0 or
/// count == 0 gives none.
std::vector<std::size_t> EvenlySpacedIndices(std::size_t count, std::size_t keep);

}  // namespace slamsweep::report::inline images
