#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <vector>

#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator::inline trajectory_metrics {

struct AssociationOptions {
  /// Largest accepted |t_ref - (t_est + t_offset_s)| of a pair, seconds (evo's --t_max_diff).
  double t_max_diff_s = 0.01;
  /// Added to the estimate's stamps before matching (evo's --t_offset); the associated
  /// trajectories keep their own, unshifted stamps.
  double t_offset_s = 0.0;
};

/// Throws InputError naming the option when t_max_diff_s is negative or not finite, or
/// t_offset_s is not finite.
void ValidateAssociationOptions(const AssociationOptions& options);

/// {"t_max_diff_s", "t_offset_s"}.
nlohmann::json ToJson(const AssociationOptions& options);

/// Two trajectories of equal size: pose i of `reference` is paired with pose i of `estimate`.
struct Association {
  Trajectory reference;
  Trajectory estimate;
  /// Input poses that appear in no pair. A pose of the longer trajectory can appear in more
  /// than one pair (see Associate), so these counts are not simply size differences.
  std::size_t reference_unpaired = 0;
  std::size_t estimate_unpaired = 0;
};

/// Pairs poses by nearest timestamp exactly as evo's sync.associate_trajectories (nearest_time):
/// - the trajectory with fewer poses is iterated (the estimate when both have the same size);
///   each of its poses, in order, is paired with the pose of the longer one whose shifted stamp
///   is nearest (the lowest index on a tie, like numpy.argmin) when that difference is at most
///   t_max_diff_s; the shift adds t_offset_s to the estimate's stamps (when the reference is the
///   longer one, evo subtracts t_offset_s from the reference's stamps instead);
/// - a pose of the longer trajectory may therefore be paired twice, and pairs follow the order
///   of the shorter trajectory.
/// Gives evo's O(n^2) result in O(n log n) (a search per pose, also for unsorted stamps), and in
/// O(n) when the stamps ascend (each search starts where the previous one ended).
/// Throws InputError when either trajectory is empty or no pair is found; the message names
/// both time ranges and suggests a larger --t-max-diff or a --t-offset.
Association Associate(const Trajectory& reference, const Trajectory& estimate, const AssociationOptions& options);

/// The pairs of Associate as indices, without copying a pose: pair k is reference pose reference_ids[k]
/// with estimate pose estimate_ids[k], in Associate's order, with the same unpaired counts.
struct AssociatedIndices {
  std::vector<std::size_t> reference_ids;
  std::vector<std::size_t> estimate_ids;
  std::size_t reference_unpaired = 0;
  std::size_t estimate_unpaired = 0;

  std::size_t size() const { return reference_ids.size(); }
};

/// Associate's pairing as indices (same options, same errors).
AssociatedIndices AssociateIndices(const Trajectory& reference, const Trajectory& estimate,
                                   const AssociationOptions& options);

/// One side of an association in pair order: the input trajectory itself when every one of its poses is
/// paired, in order (ids 0, 1, ..., n - 1: two trajectories on one clock), otherwise a copy of just the
/// paired poses. Holds a reference to `trajectory`, which must outlive it.
class PairedSide {
 public:
  PairedSide(const Trajectory& trajectory, std::span<const std::size_t> ids);

  const Trajectory& trajectory() const { return copy_ ? *copy_ : *input_; }

 private:
  const Trajectory* input_;
  std::optional<Trajectory> copy_;
};

}  // namespace slamsweep::evaluator::inline trajectory_metrics
