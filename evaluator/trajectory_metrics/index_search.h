#pragma once

#include <algorithm>
#include <cstddef>
#include <ranges>

namespace slamsweep::evaluator::inline trajectory_metrics {

/// The first index in [begin, end) at which `before` is false, for a predicate that holds on a
/// prefix of the range: std::ranges::partition_point over indices instead of over a container,
/// because association and pair selection search derived quantities (time gaps, path lengths).
template <typename Predicate>
std::size_t PartitionPointIndex(std::size_t begin, std::size_t end, Predicate before) {
  if (begin >= end) return begin;  // an empty range: iota(begin, end) requires begin <= end
  const auto indices = std::views::iota(begin, end);
  const auto found = std::ranges::partition_point(indices, before);
  return begin + static_cast<std::size_t>(std::ranges::distance(indices.begin(), found));
}

}  // namespace slamsweep::evaluator::inline trajectory_metrics
