#include "evaluator/trajectory_metrics/alignment.h"

#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <limits>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline trajectory_metrics {
namespace {

struct ModeName {
  AlignmentMode mode;
  std::string_view name;
};

constexpr std::array<ModeName, 6> kModeNames = {{{AlignmentMode::kNone, "none"},
                                                 {AlignmentMode::kOrigin, "origin"},
                                                 {AlignmentMode::kSe2, "se2"},
                                                 {AlignmentMode::kSe3, "se3"},
                                                 {AlignmentMode::kSim2, "sim2"},
                                                 {AlignmentMode::kSim3, "sim3"}}};

// The dimension-generic core of Umeyama's method over n pairs; source(i) and target(i) give pair i's poses
// (from spans, or through the indices of an association). kDim = 2 reads x and y only.
template <int kDim, typename Source, typename Target>
Alignment Umeyama(std::size_t n, const Source& source, const Target& target, bool with_scale) {
  using Vector = Eigen::Matrix<double, kDim, 1>;
  using Matrix = Eigen::Matrix<double, kDim, kDim>;
  const auto point = [](const Pose& pose) -> Vector { return pose.position.template head<kDim>(); };
  const double count = static_cast<double>(n);

  Vector mean_source = Vector::Zero();
  Vector mean_target = Vector::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    mean_source += point(source(i));
    mean_target += point(target(i));
  }
  mean_source /= count;
  mean_target /= count;

  double variance_source = 0.0;
  Matrix covariance = Matrix::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Vector dx = point(source(i)) - mean_source;
    const Vector dy = point(target(i)) - mean_target;
    variance_source += dx.squaredNorm();
    covariance.noalias() += dy * dx.transpose();
  }
  variance_source /= count;
  covariance /= count;

  const Eigen::JacobiSVD<Matrix> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Vector singular = svd.singularValues();
  int rank = 0;
  for (int k = 0; k < kDim; ++k) {
    if (singular(k) > std::numeric_limits<double>::epsilon()) ++rank;
  }
  if (rank < kDim - 1) {
    throw InputError("Umeyama alignment (" + std::to_string(kDim) + "D) over " + std::to_string(n) +
                     " pairs: degenerate covariance (rank " + std::to_string(rank) + ", need at least " +
                     std::to_string(kDim - 1) +
                     "); the estimated positions are all equal or collinear, so no unique rotation exists. "
                     "Use more pairs (--n-to-align), alignment 'origin' or 'none'");
  }
  Matrix reflection = Matrix::Identity();
  // A reflection would fit better than any rotation: flip the weakest axis (Kabsch).
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0.0) reflection(kDim - 1, kDim - 1) = -1.0;
  const Matrix rotation = svd.matrixU() * reflection * svd.matrixV().transpose();
  const double scale = with_scale ? (singular.asDiagonal() * reflection).trace() / variance_source : 1.0;
  const Vector translation = mean_target - scale * (rotation * mean_source);

  Alignment alignment;
  alignment.rotation.template topLeftCorner<kDim, kDim>() = rotation;
  alignment.translation.template head<kDim>() = translation;
  alignment.scale = scale;
  alignment.planar = kDim == 2;
  return alignment;
}

// The alignment of n pairs (pair k: reference_at(k), estimate_at(k)) for a mode other than kNone.
template <typename ReferenceAt, typename EstimateAt>
Alignment AlignPairs(std::size_t n, const ReferenceAt& reference_at, const EstimateAt& estimate_at,
                     const AlignmentOptions& options) {
  if (n == 0) throw InputError("alignment: no associated pairs to align");
  if (options.mode == AlignmentMode::kOrigin) return OriginAlignment(reference_at(0), estimate_at(0));
  const std::size_t used = options.n_to_align == -1 ? n : std::min(n, static_cast<std::size_t>(options.n_to_align));
  const bool with_scale = options.mode == AlignmentMode::kSim2 || options.mode == AlignmentMode::kSim3;
  const bool planar = options.mode == AlignmentMode::kSe2 || options.mode == AlignmentMode::kSim2;
  return planar ? Umeyama<2>(used, estimate_at, reference_at, with_scale)
                : Umeyama<3>(used, estimate_at, reference_at, with_scale);
}

}  // namespace

AlignmentMode ParseAlignmentMode(std::string_view name) {
  for (const ModeName& entry : kModeNames) {
    if (entry.name == name) return entry.mode;
  }
  throw InputError("alignment: expected one of none, origin, se2, se3, sim2, sim3; got '" + std::string(name) + "'");
}

std::string_view AlignmentModeName(AlignmentMode mode) {
  for (const ModeName& entry : kModeNames) {
    if (entry.mode == mode) return entry.name;
  }
  return "none";
}

void ValidateAlignmentOptions(const AlignmentOptions& options) {
  if (options.n_to_align == 0 || options.n_to_align < -1) {
    throw InputError("option n_to_align (--n-to-align): expected -1 (all pairs) or a positive count, got " +
                     std::to_string(options.n_to_align));
  }
}

Eigen::Vector3d Alignment::Apply(const Eigen::Vector3d& position) const {
  Eigen::Vector3d scaled = scale * position;
  if (planar) scaled.z() = position.z();
  return rotation * scaled + translation;
}

Pose Alignment::Apply(const Pose& pose) const {
  Pose moved;
  moved.position = Apply(pose.position);
  moved.orientation = (Eigen::Quaterniond(rotation) * pose.orientation).normalized();
  return moved;
}

nlohmann::json ToJson(const Alignment& alignment) {
  nlohmann::json rotation = nlohmann::json::array();
  for (int row = 0; row < 3; ++row) {
    rotation.push_back({alignment.rotation(row, 0), alignment.rotation(row, 1), alignment.rotation(row, 2)});
  }
  return nlohmann::json{
      {"scale", alignment.scale},
      {"rotation", rotation},
      {"translation", {alignment.translation.x(), alignment.translation.y(), alignment.translation.z()}},
      {"planar", alignment.planar}};
}

Alignment UmeyamaAlignment(std::span<const Pose> source, std::span<const Pose> target, bool with_scale, bool planar) {
  if (source.size() != target.size()) {
    throw InputError("Umeyama alignment: " + std::to_string(source.size()) + " source positions but " +
                     std::to_string(target.size()) + " target positions (expected equal counts)");
  }
  if (source.empty()) throw InputError("Umeyama alignment: no position pairs to align");
  const auto source_at = [source](std::size_t i) -> const Pose& { return source[i]; };
  const auto target_at = [target](std::size_t i) -> const Pose& { return target[i]; };
  return planar ? Umeyama<2>(source.size(), source_at, target_at, with_scale)
                : Umeyama<3>(source.size(), source_at, target_at, with_scale);
}

Alignment OriginAlignment(const Pose& reference_origin, const Pose& estimate_origin) {
  const Eigen::Matrix3d rotation =
      (reference_origin.orientation * estimate_origin.orientation.conjugate()).normalized().toRotationMatrix();
  Alignment alignment;
  alignment.rotation = rotation;
  alignment.translation = reference_origin.position - rotation * estimate_origin.position;
  return alignment;
}

std::optional<Alignment> ComputeAlignment(const Trajectory& reference, const Trajectory& estimate,
                                          const AlignmentOptions& options) {
  ValidateAlignmentOptions(options);
  if (options.mode == AlignmentMode::kNone) return std::nullopt;
  if (reference.size() != estimate.size()) {
    throw InputError("alignment: reference has " + std::to_string(reference.size()) + " poses but estimate has " +
                     std::to_string(estimate.size()) + " (expected associated pairs)");
  }
  return AlignPairs(
      estimate.size(), [&](std::size_t k) -> const Pose& { return reference.poses()[k]; },
      [&](std::size_t k) -> const Pose& { return estimate.poses()[k]; }, options);
}

std::optional<Alignment> ComputeAlignment(const Trajectory& reference, const Trajectory& estimate,
                                          const AssociatedIndices& pairs, const AlignmentOptions& options) {
  ValidateAlignmentOptions(options);
  if (options.mode == AlignmentMode::kNone) return std::nullopt;
  return AlignPairs(
      pairs.size(), [&](std::size_t k) -> const Pose& { return reference.poses()[pairs.reference_ids[k]]; },
      [&](std::size_t k) -> const Pose& { return estimate.poses()[pairs.estimate_ids[k]]; }, options);
}

Trajectory ApplyAlignment(Trajectory trajectory, const Alignment& alignment) {
  const Eigen::Quaterniond rotation(alignment.rotation);
  for (Pose& pose : trajectory.mutable_poses()) {
    pose.position = alignment.Apply(pose.position);
    pose.orientation = (rotation * pose.orientation).normalized();
  }
  return trajectory;
}

}  // namespace slamsweep::evaluator::inline trajectory_metrics
