#pragma once

#include <cstddef>

namespace slamsweep::evaluator::inline trajectory_metrics {

/// The first index in [begin, end) at which `before` is false, for a predicate that holds on a
/// prefix of the range: a partition point over indices instead of over a container, because
/// association and pair selection search derived quantities (time gaps, path lengths). A plain
/// binary search: clang 14 (the fuzz build's compiler) cannot compile libstdc++ 12's iota_view.
template <typename Predicate>
std::size_t PartitionPointIndex(std::size_t begin, std::size_t end, Predicate before) {
  while (begin < end) {
    const std::size_t middle = begin + (end - begin) / 2;
    if (before(middle)) {
      begin = middle + 1;
    } else {
      end = middle;
    }
  }
  return begin;
}

}  // namespace slamsweep::evaluator::inline trajectory_metrics
