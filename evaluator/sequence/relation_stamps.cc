#include "evaluator/sequence/relation_stamps.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <optional>

namespace slamsweep::evaluator::inline sequence {

Relations MapRelationsOntoRecords(Relations relations, std::span<const double> logged_s,
                                  std::span<const double> chosen_s, double tolerance_s, std::size_t& unmatched) {
  unmatched = 0;
  std::vector<std::size_t> order(logged_s.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  // Stable: among equal logged stamps the first in file order comes first.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return logged_s[a] < logged_s[b]; });
  const auto map_stamp = [&](double& stamp_s) {
    const auto at = std::lower_bound(order.begin(), order.end(), stamp_s,
                                     [&](std::size_t index, double value) { return logged_s[index] < value; });
    std::optional<std::size_t> best;
    double best_distance = std::numeric_limits<double>::infinity();
    if (at != order.end()) {
      best = *at;
      best_distance = logged_s[*at] - stamp_s;
    }
    if (at != order.begin()) {
      // The first record (in file order) of the run of equal stamps just below.
      auto below = std::prev(at);
      while (below != order.begin() && logged_s[*std::prev(below)] == logged_s[*below]) --below;
      if (stamp_s - logged_s[*below] < best_distance) {
        best = *below;
        best_distance = stamp_s - logged_s[*below];
      }
    }
    if (!best || best_distance > tolerance_s) {
      ++unmatched;
      return;
    }
    stamp_s = chosen_s[*best];
  };
  for (Relation& relation : relations) {
    map_stamp(relation.t1_s);
    map_stamp(relation.t2_s);
  }
  return relations;
}

double MedianSpacingS(std::vector<double> stamps) {
  if (stamps.size() < 2) return 0.0;
  std::sort(stamps.begin(), stamps.end());
  std::vector<double> gaps(stamps.size() - 1);
  for (std::size_t i = 1; i < stamps.size(); ++i) gaps[i - 1] = stamps[i] - stamps[i - 1];
  std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2), gaps.end());
  return gaps[gaps.size() / 2];
}

}  // namespace slamsweep::evaluator::inline sequence
