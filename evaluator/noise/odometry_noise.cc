#include "evaluator/noise/odometry_noise.h"

#include <cmath>
#include <numbers>

#include "evaluator/core/input_error.h"
#include "evaluator/noise/json_fields.h"
#include "evaluator/noise/random.h"

namespace slamsweep::evaluator::inline noise {
namespace {

constexpr const char* kOdometryModelName = "odometry_motion_model";

// Driving backwards decomposes into a half turn, a translation and another half turn; that is
// not half a turn of heading uncertainty, so the variance uses the smaller of |rot| and pi - |rot|.
double RotationForVariance(double rot_rad) {
  const double magnitude = std::abs(rot_rad);
  return std::min(magnitude, std::numbers::pi - magnitude);
}

struct PlanarPose {
  double x_m;
  double y_m;
  double yaw_rad;
};

PlanarPose ToPlanar(const Pose& pose) { return {pose.position.x(), pose.position.y(), pose.Yaw()}; }

void CheckFields(const OdometryNoise& noise, const std::string& prefix) {
  const char* non_negative = "a finite number >= 0";
  RequireNoiseField(prefix, std::isfinite(noise.alpha1) && noise.alpha1 >= 0.0, "alpha1", noise.alpha1, non_negative);
  RequireNoiseField(prefix, std::isfinite(noise.alpha2) && noise.alpha2 >= 0.0, "alpha2", noise.alpha2, non_negative);
  RequireNoiseField(prefix, std::isfinite(noise.alpha3) && noise.alpha3 >= 0.0, "alpha3", noise.alpha3, non_negative);
  RequireNoiseField(prefix, std::isfinite(noise.alpha4) && noise.alpha4 >= 0.0, "alpha4", noise.alpha4, non_negative);
  RequireNoiseField(prefix, std::isfinite(noise.drift_heading_rad_per_m), "drift_heading_rad_per_m",
                    noise.drift_heading_rad_per_m, "a finite number");
  RequireNoiseField(prefix, std::isfinite(noise.scale_error) && noise.scale_error > -1.0, "scale_error",
                    noise.scale_error, "a finite number > -1");
}

}  // namespace

void ValidateOdometryNoise(const OdometryNoise& noise) { CheckFields(noise, "odometry noise: "); }

OdometryIncrement DecomposeOdometry(const Pose& from, const Pose& to) {
  const PlanarPose a = ToPlanar(from);
  const PlanarPose b = ToPlanar(to);
  OdometryIncrement step;
  step.trans_m = std::hypot(b.x_m - a.x_m, b.y_m - a.y_m);
  if (step.trans_m >= kBearingMinTranslationM) {
    step.rot1_rad = NormalizeAngleRad(std::atan2(b.y_m - a.y_m, b.x_m - a.x_m) - a.yaw_rad);
  }
  step.rot2_rad = NormalizeAngleRad(b.yaw_rad - a.yaw_rad - step.rot1_rad);
  return step;
}

Trajectory ApplyOdometryNoise(const Trajectory& reference, const OdometryNoise& noise, std::uint64_t seed) {
  ValidateOdometryNoise(noise);
  RandomEngine engine(seed);
  Trajectory odometry;
  odometry.Reserve(reference.size());
  // The noisy pose is kept as correction * reference pose rather than by chaining increments:
  // chaining would re-add the reference motion through sin/cos round trips and drift from the
  // reference by rounding alone, while here every term of the correction is a product of noise
  // samples, so zero noise gives the identity correction and the reference exactly.
  Pose correction;
  const std::vector<Pose>& poses = reference.poses();
  for (std::size_t i = 0; i < poses.size(); ++i) {
    if (i > 0) {
      const OdometryIncrement step = DecomposeOdometry(poses[i - 1], poses[i]);
      const double rot1 = RotationForVariance(step.rot1_rad);
      const double rot2 = RotationForVariance(step.rot2_rad);
      const double trans2 = step.trans_m * step.trans_m;
      const double rot1_error = std::sqrt(noise.alpha1 * rot1 * rot1 + noise.alpha2 * trans2) * StandardNormal(engine);
      const double trans_error =
          std::sqrt(noise.alpha3 * trans2 + noise.alpha4 * (rot1 * rot1 + rot2 * rot2)) * StandardNormal(engine);
      const double rot2_error = std::sqrt(noise.alpha1 * rot2 * rot2 + noise.alpha2 * trans2) * StandardNormal(engine) +
                                noise.drift_heading_rad_per_m * step.trans_m;
      const double noisy_trans_m = (step.trans_m + trans_error) * (1.0 + noise.scale_error);

      // error = true_step^-1 * noisy_step with true_step = R(rot1) T(trans) R(rot2) and
      // noisy_step = R(rot1 + e1) T(trans') R(rot2 + e2), which simplifies to
      // R(-rot2) [T(-trans) R(e1) T(trans')] R(rot2 + e2): expressed in the frame of the new pose.
      const double local_x = noisy_trans_m * std::cos(rot1_error) - step.trans_m;
      const double local_y = noisy_trans_m * std::sin(rot1_error);
      const double cos_rot2 = std::cos(step.rot2_rad);
      const double sin_rot2 = std::sin(step.rot2_rad);
      const double error_x = cos_rot2 * local_x + sin_rot2 * local_y;
      const double error_y = -sin_rot2 * local_x + cos_rot2 * local_y;
      const double error_yaw = rot1_error + rot2_error;

      // Move the error into the world frame: P * E * P^-1 for planar P = (t, yaw) is the
      // rotation by error_yaw with translation t - R(error_yaw) t + R(yaw) t_error.
      const PlanarPose p = ToPlanar(poses[i]);
      const double cos_e = std::cos(error_yaw);
      const double sin_e = std::sin(error_yaw);
      const double cos_p = std::cos(p.yaw_rad);
      const double sin_p = std::sin(p.yaw_rad);
      const double world_x = p.x_m - (cos_e * p.x_m - sin_e * p.y_m) + (cos_p * error_x - sin_p * error_y);
      const double world_y = p.y_m - (sin_e * p.x_m + cos_e * p.y_m) + (sin_p * error_x + cos_p * error_y);
      correction = correction * Pose::Planar(world_x, world_y, error_yaw);
      correction.orientation.normalize();
    }
    odometry.Add(reference.stamps_s()[i], correction * poses[i]);
  }
  return odometry;
}

void to_json(nlohmann::json& out, const OdometryNoise& noise) {
  out = nlohmann::json{{"model", kOdometryModelName},     {"alpha1", noise.alpha1},
                       {"alpha2", noise.alpha2},          {"alpha3", noise.alpha3},
                       {"alpha4", noise.alpha4},          {"drift_heading_rad_per_m", noise.drift_heading_rad_per_m},
                       {"scale_error", noise.scale_error}};
}

OdometryNoise OdometryNoiseFromJson(const nlohmann::json& in, const std::string& path) {
  JsonFields fields(in, path);
  const std::string model = fields.Text("model", kOdometryModelName);
  if (model != kOdometryModelName) {
    throw InputError(fields.PathOf("model") + ": expected \"" + kOdometryModelName + "\", got \"" + model + "\"");
  }
  OdometryNoise noise;
  noise.alpha1 = fields.Number("alpha1", 0.0);
  noise.alpha2 = fields.Number("alpha2", 0.0);
  noise.alpha3 = fields.Number("alpha3", 0.0);
  noise.alpha4 = fields.Number("alpha4", 0.0);
  noise.drift_heading_rad_per_m = fields.Number("drift_heading_rad_per_m", 0.0);
  noise.scale_error = fields.Number("scale_error", 0.0);
  fields.Finish();
  CheckFields(noise, path + ".");
  return noise;
}

void from_json(const nlohmann::json& in, OdometryNoise& noise) { noise = OdometryNoiseFromJson(in); }

Trajectory NoisyReadings(const Trajectory& readings, const Trajectory& clean_scans, const Trajectory& noisy_scans) {
  if (clean_scans.size() != noisy_scans.size() || clean_scans.empty()) {
    throw InputError("noisy readings: expected the clean and noisy scan odometry to have the same, non-zero size");
  }
  Trajectory out;
  out.Reserve(readings.size());
  std::size_t scan = 0;
  for (std::size_t i = 0; i < readings.size(); ++i) {
    const double stamp = readings.stamps_s()[i];
    while (scan + 1 < clean_scans.size() && clean_scans.stamps_s()[scan + 1] <= stamp) ++scan;
    const Pose shift = noisy_scans.poses()[scan] * clean_scans.poses()[scan].Inverse();
    out.Add(stamp, shift * readings.poses()[i]);
  }
  return out;
}

}  // namespace slamsweep::evaluator::inline noise
