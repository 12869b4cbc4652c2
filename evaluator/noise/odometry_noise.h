#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "evaluator/core/pose.h"
#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator::inline noise {

/// Noise of wheel odometry: the odometry motion model of Thrun, Burgard and Fox,
/// "Probabilistic Robotics" (sample_motion_model_odometry), plus systematic errors that the
/// model lacks but real robots have. Each step between consecutive reference poses is split
/// into a rotation rot1 towards the new position, a translation trans and a rotation rot2,
/// and each part is perturbed by a zero-mean Gaussian whose VARIANCE is
///   rot1:  alpha1 * rot1^2 + alpha2 * trans^2
///   trans: alpha3 * trans^2 + alpha4 * (rot1^2 + rot2^2)
///   rot2:  alpha1 * rot2^2 + alpha2 * trans^2
/// then the sampled distance is scaled by (1 + scale_error) and rot2 gains
/// drift_heading_rad_per_m * trans (a constant yaw bias per metre, e.g. unequal wheel radii).
/// All fields default to 0, which leaves the trajectory unchanged.
struct OdometryNoise {
  double alpha1 = 0.0;  ///< rad^2 of rotation noise per rad^2 of rotation
  double alpha2 = 0.0;  ///< rad^2 of rotation noise per m^2 of translation
  double alpha3 = 0.0;  ///< m^2 of translation noise per m^2 of translation
  double alpha4 = 0.0;  ///< m^2 of translation noise per rad^2 of rotation
  double drift_heading_rad_per_m = 0.0;
  double scale_error = 0.0;  ///< relative; 0.01 makes every distance 1 % too long

  bool operator==(const OdometryNoise&) const = default;
};

/// One odometry step in the model's parametrisation. Below kBearingMinTranslationM of
/// translation the direction of motion is meaningless (pose jitter at standstill would give
/// rot1 anywhere in (-pi, pi]), so rot1 is 0 and the whole turn is rot2.
struct OdometryIncrement {
  double rot1_rad = 0.0;
  double trans_m = 0.0;
  double rot2_rad = 0.0;
};
inline constexpr double kBearingMinTranslationM = 0.01;

/// The planar (x, y, yaw) step from `from` to `to`.
OdometryIncrement DecomposeOdometry(const Pose& from, const Pose& to);

/// Throws InputError naming the field unless every alpha is finite and >= 0, the drift is
/// finite and scale_error is finite and > -1.
void ValidateOdometryNoise(const OdometryNoise& noise);

/// Noisy odometry for `reference`: same stamps, first pose equal to the reference's, then the
/// noisy increments composed one after another. Planar: noise acts in x, y and yaw; z, roll and
/// pitch of the reference are carried along. Same (noise, seed) -> the same poses bit for bit;
/// with all-zero noise the result equals the reference exactly. Use DeriveSeed(base, k) for
/// iteration k of a sweep.
Trajectory ApplyOdometryNoise(const Trajectory& reference, const OdometryNoise& noise, std::uint64_t seed);

/// The readings of a denser odometry stream after noise was drawn on the scans' odometry
/// (`noisy_scans` = ApplyOdometryNoise(`clean_scans`, ...), whose stamps are among the readings'):
/// a reading at a scan's stamp is that scan's noisy pose; any other reading keeps its recorded
/// motion from the last scan before it, composed onto that scan's noisy pose (readings before the
/// first scan are moved with it). So the alphas keep their meaning, variances per scan step.
Trajectory NoisyReadings(const Trajectory& readings, const Trajectory& clean_scans, const Trajectory& noisy_scans);

/// JSON record of the noise specification, {"model": "odometry_motion_model", "alpha1": ...},
/// to be stored with every run (the seed is recorded by the caller beside it).
void to_json(nlohmann::json& out, const OdometryNoise& noise);
/// Strict reader: unknown fields and wrong types are InputErrors naming `path`.field; missing
/// fields stay 0; the result is validated.
OdometryNoise OdometryNoiseFromJson(const nlohmann::json& in, const std::string& path = "odometry_noise");
void from_json(const nlohmann::json& in, OdometryNoise& noise);

}  // namespace slamsweep::evaluator::inline noise
