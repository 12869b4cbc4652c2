#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "evaluator/core/pose.h"

namespace slamsweep::evaluator::inline core {

/// Timestamped poses in the order they were recorded. Invariant: as many stamps as
/// poses, every stamp finite, every pose valid (checked by the constructor and Add,
/// which throw InputError naming the offending index).
class Trajectory {
 public:
  Trajectory() = default;
  Trajectory(std::vector<double> stamps_s, std::vector<Pose> poses);

  void Add(double stamp_s, const Pose& pose);
  void Reserve(std::size_t count);

  std::size_t size() const { return poses_.size(); }
  bool empty() const { return poses_.empty(); }
  const std::vector<double>& stamps_s() const { return stamps_s_; }
  const std::vector<Pose>& poses() const { return poses_; }
  std::vector<Pose>& mutable_poses() { return poses_; }

  /// First and last stamp; throws InputError when empty.
  double StartS() const;
  double EndS() const;
  /// True when all poses lie in the z = 0 plane and rotate about z only.
  bool IsPlanar(double tolerance = 1e-9) const;
  /// The poses at the given indices, in that order.
  Trajectory Subset(std::span<const std::size_t> indices) const;
  /// Subset of a trajectory that is no longer needed: when the indices strictly increase (the
  /// usual selection) the poses are moved down in place, without new memory; otherwise a Subset.
  Trajectory Select(std::span<const std::size_t> indices) &&;
  /// A copy whose stamps are shifted by offset_s.
  Trajectory Shifted(double offset_s) const;

 private:
  std::vector<double> stamps_s_;
  std::vector<Pose> poses_;
};

/// "[t0, t1] s (N poses)" for error messages.
std::string DescribeTimeRange(const Trajectory& trajectory);

}  // namespace slamsweep::evaluator::inline core
