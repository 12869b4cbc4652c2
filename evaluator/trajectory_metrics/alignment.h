#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string_view>

#include "evaluator/core/pose.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/trajectory_metrics/association.h"

namespace slamsweep::evaluator::inline trajectory_metrics {

/// How the estimate is moved onto the reference before errors are taken.
/// - kNone: as recorded.
/// - kOrigin: the first estimated pose is moved onto the first reference pose (evo's
///   `--align_origin`): T = T_ref0 * T_est0^-1.
/// - kSe3 / kSim3: Umeyama's closed form on the 3D positions, without / with scale (evo's
///   `--align` / `--align --correct_scale`).
/// - kSe2 / kSim2: Umeyama's closed form on x and y only; the result rotates about z and
///   translates in the x-y plane, z is left untouched (also by the scale).
enum class AlignmentMode { kNone, kOrigin, kSe2, kSe3, kSim2, kSim3 };

/// "none", "origin", "se2", "se3", "sim2" or "sim3"; anything else is an InputError that
/// lists the valid values.
AlignmentMode ParseAlignmentMode(std::string_view name);
std::string_view AlignmentModeName(AlignmentMode mode);

struct AlignmentOptions {
  AlignmentMode mode = AlignmentMode::kNone;
  /// Umeyama modes only: fit on the first n pairs (evo's `--n_to_align`); -1 = all. A value
  /// above the number of pairs uses all of them, as evo's slicing does.
  int n_to_align = -1;
};

/// Throws InputError naming the option when n_to_align is 0 or below -1.
void ValidateAlignmentOptions(const AlignmentOptions& options);

/// A similarity transform p -> rotation * (scale * p) + translation, applied to positions;
/// orientations are rotated by `rotation`. This is the order evo uses (scale the path, then
/// transform it). When `planar` is set (se2/sim2) the scale acts on x and y only, so z is
/// left as it was.
struct Alignment {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  double scale = 1.0;
  bool planar = false;

  Eigen::Vector3d Apply(const Eigen::Vector3d& position) const;
  Pose Apply(const Pose& pose) const;
};

/// {"scale", "rotation" (3 rows), "translation", "planar"}.
nlohmann::json ToJson(const Alignment& alignment);

/// Umeyama (1991) least-squares similarity mapping `source` positions onto `target`
/// positions (equal, non-zero sizes), exactly as evo's geometry.umeyama_alignment: population
/// (1/n) covariance, reflection fixed when det(U) det(V) < 0, scale = tr(D S) / sigma_source^2.
/// Throws InputError when fewer than dim - 1 singular values of the covariance exceed machine
/// epsilon (points all equal, or collinear in 3D): no unique rotation exists.
/// `planar` fits x and y only (a rotation about z, z untouched).
Alignment UmeyamaAlignment(std::span<const Pose> source, std::span<const Pose> target, bool with_scale, bool planar);

/// The rigid transform that moves `estimate_origin` onto `reference_origin` (evo's align_origin).
Alignment OriginAlignment(const Pose& reference_origin, const Pose& estimate_origin);

/// The alignment of an associated estimate to its reference (equal sizes, pair i = index i),
/// or nullopt for kNone. Throws InputError for empty input or a degenerate configuration.
std::optional<Alignment> ComputeAlignment(const Trajectory& reference, const Trajectory& estimate,
                                          const AlignmentOptions& options);

/// The same for the pairs of an association given as indices into the unpaired trajectories (no pose copied).
std::optional<Alignment> ComputeAlignment(const Trajectory& reference, const Trajectory& estimate,
                                          const AssociatedIndices& pairs, const AlignmentOptions& options);

/// The trajectory with every pose moved by `alignment` (stamps unchanged). Takes its input by
/// value so that a caller done with the original can move it in and avoid a copy.
Trajectory ApplyAlignment(Trajectory trajectory, const Alignment& alignment);

}  // namespace slamsweep::evaluator::inline trajectory_metrics
