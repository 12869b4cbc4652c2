#include "evaluator/trajectory_metrics/association.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/trajectory_metrics/index_search.h"

namespace slamsweep::evaluator::inline trajectory_metrics {
namespace {

std::string FormatSeconds(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.9g", value);
  return buffer;
}

// Answers "which stamp is nearest to t, and how near" with numpy.argmin's tie rule (the lowest
// index wins) in O(log n). The stamps are kept sorted by (value, index). |v - t| computed in
// floating point is monotone in v on either side of t, so the stamps at the smallest difference
// form one contiguous run of the sorted order around t's insertion point, found by two galloping
// searches; the lowest original index in that run is then read from a segment tree (or is simply
// the run's first element when the stamps were already sorted, the usual case).
class NearestStamp {
 public:
  struct Match {
    std::size_t index = 0;
    double difference_s = 0.0;
  };

  // Reads `stamps_s` in place when they ascend and need no shift (the usual case), else sorts a shifted copy.
  NearestStamp(std::span<const double> stamps_s, double shift_s) : sorted_(stamps_s) {
    if (shift_s == 0.0 && std::is_sorted(stamps_s.begin(), stamps_s.end())) return;
    std::vector<double> shifted(stamps_s.begin(), stamps_s.end());
    for (double& stamp : shifted) stamp += shift_s;
    const std::size_t n = shifted.size();
    if (std::is_sorted(shifted.begin(), shifted.end())) {
      owned_ = std::move(shifted);
      sorted_ = owned_;
      return;
    }
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), std::size_t{0});
    std::stable_sort(order_.begin(), order_.end(),
                     [&](std::size_t a, std::size_t b) { return shifted[a] < shifted[b]; });
    owned_.resize(n);
    for (std::size_t k = 0; k < n; ++k) owned_[k] = shifted[order_[k]];
    sorted_ = owned_;
    tree_.assign(2 * n, 0);
    for (std::size_t k = 0; k < n; ++k) tree_[n + k] = order_[k];
    for (std::size_t k = n - 1; k > 0; --k) tree_[k] = std::min(tree_[2 * k], tree_[2 * k + 1]);
  }

  // `cursor` is where the previous query's insertion point was; queries in ascending order (the
  // usual case) then cost O(1) each instead of a full binary search. Any cursor gives the same answer.
  Match Nearest(double stamp_s, std::size_t& cursor) const {
    const std::size_t n = sorted_.size();
    const auto difference = [&](std::size_t position) { return std::abs(sorted_[position] - stamp_s); };
    const std::size_t split = FirstFalse(0, n, cursor, [&](std::size_t q) { return sorted_[q] < stamp_s; });
    cursor = split;
    double best = std::numeric_limits<double>::infinity();
    if (split > 0) best = difference(split - 1);
    if (split < n) best = std::min(best, difference(split));

    std::size_t begin = split;
    std::size_t end = split;
    if (split > 0 && difference(split - 1) == best) {
      begin = FirstFalse(0, split, split - 1, [&](std::size_t q) { return difference(q) > best; });
    }
    if (split < n && difference(split) == best) {
      end = FirstFalse(split, n, split, [&](std::size_t q) { return difference(q) <= best; });
    }
    return Match{MinIndex(begin, end), best};
  }

 private:
  // First position in [begin, end) where `before` turns false (it is true, then false), searched
  // outwards from `hint` with doubling steps: O(1) when the answer is near the hint, O(log n) at worst.
  template <typename Predicate>
  static std::size_t FirstFalse(std::size_t begin, std::size_t end, std::size_t hint, Predicate before) {
    hint = std::clamp(hint, begin, end);
    if (hint < end && before(hint)) {
      std::size_t known_true = hint;
      std::size_t step = 1;
      while (known_true + step < end && before(known_true + step)) {
        known_true += step;
        step *= 2;
      }
      return PartitionPointIndex(known_true + 1, std::min(known_true + step, end), before);
    }
    std::size_t known_false_or_end = hint;
    std::size_t step = 1;
    while (known_false_or_end - begin >= step && !before(known_false_or_end - step)) {
      known_false_or_end -= step;
      step *= 2;
    }
    const std::size_t lower = known_false_or_end - begin >= step ? known_false_or_end - step + 1 : begin;
    return PartitionPointIndex(lower, known_false_or_end, before);
  }

  std::size_t MinIndex(std::size_t begin, std::size_t end) const {
    if (order_.empty()) return begin;
    const std::size_t n = sorted_.size();
    std::size_t lowest = std::numeric_limits<std::size_t>::max();
    for (std::size_t l = begin + n, r = end + n; l < r; l /= 2, r /= 2) {
      if (l & 1) lowest = std::min(lowest, tree_[l++]);
      if (r & 1) lowest = std::min(lowest, tree_[--r]);
    }
    return lowest;
  }

  std::span<const double> sorted_;  // stamp values in ascending order (the input's, or owned_)
  std::vector<double> owned_;       // shifted or sorted stamps, when the input's could not be read in place
  std::vector<std::size_t> order_;  // original index of each sorted position; empty = identity
  std::vector<std::size_t> tree_;   // segment tree of minimum original index over sorted positions
};

[[noreturn]] void ThrowNoPairs(const Trajectory& reference, const Trajectory& estimate,
                               const AssociationOptions& options) {
  throw InputError("association: no matching timestamps between reference " + DescribeTimeRange(reference) +
                   " and estimate " + DescribeTimeRange(estimate) +
                   " within t_max_diff = " + FormatSeconds(options.t_max_diff_s) +
                   " s after adding t_offset = " + FormatSeconds(options.t_offset_s) +
                   " s to the estimate stamps; try a larger --t-max-diff, or a --t-offset that moves the "
                   "estimate onto the reference clock");
}

}  // namespace

void ValidateAssociationOptions(const AssociationOptions& options) {
  if (!std::isfinite(options.t_max_diff_s) || options.t_max_diff_s < 0.0) {
    throw InputError("option t_max_diff_s (--t-max-diff): expected a finite number >= 0 seconds, got " +
                     FormatSeconds(options.t_max_diff_s));
  }
  if (!std::isfinite(options.t_offset_s)) {
    throw InputError("option t_offset_s (--t-offset): expected a finite number of seconds, got " +
                     FormatSeconds(options.t_offset_s));
  }
}

nlohmann::json ToJson(const AssociationOptions& options) {
  return nlohmann::json{{"t_max_diff_s", options.t_max_diff_s}, {"t_offset_s", options.t_offset_s}};
}

namespace {

/// The pairs Associate forms, as indices, before any pose is copied.
struct Pairing {
  bool estimate_longer = false;
  std::vector<std::size_t> shorter_ids;
  std::vector<std::size_t> longer_ids;
  std::size_t shorter_unpaired = 0;
  std::size_t longer_unpaired = 0;
};

Pairing PairByStamp(const Trajectory& reference, const Trajectory& estimate, const AssociationOptions& options) {
  ValidateAssociationOptions(options);
  if (reference.empty() || estimate.empty()) {
    throw InputError(std::string("association: the ") + (reference.empty() ? "reference" : "estimate") +
                     " trajectory has no poses (reference " + DescribeTimeRange(reference) + ", estimate " +
                     DescribeTimeRange(estimate) + ")");
  }
  Pairing pairing;
  // evo iterates the trajectory with fewer poses so that none of its poses can be lost.
  pairing.estimate_longer = estimate.size() > reference.size();
  const Trajectory& shorter = pairing.estimate_longer ? reference : estimate;
  const Trajectory& longer = pairing.estimate_longer ? estimate : reference;
  // The offset belongs to the estimate: shift it forward, or the reference backward.
  const double shift_s = pairing.estimate_longer ? options.t_offset_s : -options.t_offset_s;

  const NearestStamp nearest(longer.stamps_s(), shift_s);

  pairing.shorter_ids.reserve(shorter.size());
  pairing.longer_ids.reserve(shorter.size());
  const std::vector<double>& shorter_stamps = shorter.stamps_s();
  std::size_t cursor = 0;
  for (std::size_t i = 0; i < shorter_stamps.size(); ++i) {
    const NearestStamp::Match match = nearest.Nearest(shorter_stamps[i], cursor);
    if (match.difference_s <= options.t_max_diff_s) {
      pairing.shorter_ids.push_back(i);
      pairing.longer_ids.push_back(match.index);
    }
  }
  if (pairing.shorter_ids.empty()) ThrowNoPairs(reference, estimate, options);

  std::vector<char> longer_used(longer.size(), 0);
  std::size_t longer_distinct = 0;
  for (std::size_t index : pairing.longer_ids) {
    if (!longer_used[index]) {
      longer_used[index] = 1;
      ++longer_distinct;
    }
  }
  pairing.shorter_unpaired = shorter.size() - pairing.shorter_ids.size();
  pairing.longer_unpaired = longer.size() - longer_distinct;
  return pairing;
}

}  // namespace

AssociatedIndices AssociateIndices(const Trajectory& reference, const Trajectory& estimate,
                                   const AssociationOptions& options) {
  Pairing pairing = PairByStamp(reference, estimate, options);
  AssociatedIndices indices;
  const bool estimate_longer = pairing.estimate_longer;
  indices.reference_ids = std::move(estimate_longer ? pairing.shorter_ids : pairing.longer_ids);
  indices.estimate_ids = std::move(estimate_longer ? pairing.longer_ids : pairing.shorter_ids);
  indices.reference_unpaired = estimate_longer ? pairing.shorter_unpaired : pairing.longer_unpaired;
  indices.estimate_unpaired = estimate_longer ? pairing.longer_unpaired : pairing.shorter_unpaired;
  return indices;
}

Association Associate(const Trajectory& reference, const Trajectory& estimate, const AssociationOptions& options) {
  const AssociatedIndices indices = AssociateIndices(reference, estimate, options);
  Association association;
  association.reference = reference.Subset(indices.reference_ids);
  association.estimate = estimate.Subset(indices.estimate_ids);
  association.reference_unpaired = indices.reference_unpaired;
  association.estimate_unpaired = indices.estimate_unpaired;
  return association;
}

namespace {

bool IsEveryIndexInOrder(std::span<const std::size_t> ids, std::size_t size) {
  if (ids.size() != size) return false;
  for (std::size_t k = 0; k < size; ++k) {
    if (ids[k] != k) return false;
  }
  return true;
}

}  // namespace

PairedSide::PairedSide(const Trajectory& trajectory, std::span<const std::size_t> ids) : input_(&trajectory) {
  if (!IsEveryIndexInOrder(ids, trajectory.size())) copy_ = trajectory.Subset(ids);
}

}  // namespace slamsweep::evaluator::inline trajectory_metrics
