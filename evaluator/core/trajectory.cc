#include "evaluator/core/trajectory.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "evaluator/core/huge_pages.h"
#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline core {
namespace {

void CheckPose(double stamp_s, const Pose& pose, std::size_t index) {
  if (!std::isfinite(stamp_s)) {
    throw InputError("pose " + std::to_string(index) + ": timestamp is not a finite number");
  }
  if (!pose.IsValid()) {
    throw InputError("pose " + std::to_string(index) +
                     ": expected finite position and unit quaternion, got NaN/inf or non-unit rotation");
  }
}

}  // namespace

Trajectory::Trajectory(std::vector<double> stamps_s, std::vector<Pose> poses)
    : stamps_s_(std::move(stamps_s)), poses_(std::move(poses)) {
  if (stamps_s_.size() != poses_.size()) {
    throw InputError("trajectory has " + std::to_string(stamps_s_.size()) + " stamps but " +
                     std::to_string(poses_.size()) + " poses");
  }
  for (std::size_t i = 0; i < poses_.size(); ++i) CheckPose(stamps_s_[i], poses_[i], i);
}

void Trajectory::Add(double stamp_s, const Pose& pose) {
  CheckPose(stamp_s, pose, poses_.size());
  stamps_s_.push_back(stamp_s);
  poses_.push_back(pose);
}

void Trajectory::Reserve(std::size_t count) {
  stamps_s_.reserve(count);
  poses_.reserve(count);
  AdviseHugePages(stamps_s_);
  AdviseHugePages(poses_);
}

double Trajectory::StartS() const {
  if (empty()) throw InputError("trajectory is empty");
  return stamps_s_.front();
}

double Trajectory::EndS() const {
  if (empty()) throw InputError("trajectory is empty");
  return stamps_s_.back();
}

bool Trajectory::IsPlanar(double tolerance) const {
  for (const Pose& pose : poses_) {
    if (std::abs(pose.position.z()) > tolerance) return false;
    if (std::abs(pose.orientation.x()) > tolerance || std::abs(pose.orientation.y()) > tolerance) return false;
  }
  return true;
}

Trajectory Trajectory::Subset(std::span<const std::size_t> indices) const {
  for (std::size_t index : indices) {
    if (index >= poses_.size()) {
      throw std::out_of_range("Trajectory::Subset: index " + std::to_string(index) + " of " +
                              std::to_string(poses_.size()) + " poses");
    }
  }
  Trajectory subset;
  subset.Reserve(indices.size());
  for (std::size_t index : indices) {
    subset.stamps_s_.push_back(stamps_s_[index]);
    subset.poses_.push_back(poses_[index]);
  }
  return subset;
}

Trajectory Trajectory::Select(std::span<const std::size_t> indices) && {
  bool increasing = indices.empty() || indices.back() < poses_.size();
  for (std::size_t k = 1; increasing && k < indices.size(); ++k) increasing = indices[k - 1] < indices[k];
  if (!increasing) return Subset(indices);
  // indices[k] >= k, so every pose is read before its slot is overwritten.
  for (std::size_t k = 0; k < indices.size(); ++k) {
    stamps_s_[k] = stamps_s_[indices[k]];
    poses_[k] = poses_[indices[k]];
  }
  stamps_s_.resize(indices.size());
  poses_.resize(indices.size());
  return std::move(*this);
}

Trajectory Trajectory::Shifted(double offset_s) const {
  Trajectory shifted = *this;
  for (double& stamp : shifted.stamps_s_) stamp += offset_s;
  return shifted;
}

std::string DescribeTimeRange(const Trajectory& trajectory) {
  if (trajectory.empty()) return "no poses";
  char buffer[128];
  std::snprintf(buffer, sizeof(buffer), "[%.6f, %.6f] s (%zu poses)", trajectory.StartS(), trajectory.EndS(),
                trajectory.size());
  return buffer;
}

}  // namespace slamsweep::evaluator::inline core
