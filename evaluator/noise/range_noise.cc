#include "evaluator/noise/range_noise.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "evaluator/core/input_error.h"
#include "evaluator/noise/json_fields.h"

namespace slamsweep::evaluator::inline noise {
namespace {

constexpr const char* kRangeModelName = "range_noise";

bool IsProbability(double value) { return std::isfinite(value) && value >= 0.0 && value <= 1.0; }

void CheckFields(const RangeNoise& noise, const std::string& prefix) {
  RequireNoiseField(prefix, std::isfinite(noise.sigma_m) && noise.sigma_m >= 0.0, "sigma_m", noise.sigma_m,
                    "a finite number >= 0");
  RequireNoiseField(prefix, IsProbability(noise.dropout_probability), "dropout_probability", noise.dropout_probability,
                    "a probability in [0, 1]");
  RequireNoiseField(prefix, IsProbability(noise.short_reading_probability), "short_reading_probability",
                    noise.short_reading_probability, "a probability in [0, 1]");
}

}  // namespace

float NoReturnRangeM(double range_max_m) {
  float stored = static_cast<float>(range_max_m);
  if (stored < range_max_m) stored = std::nextafter(stored, std::numeric_limits<float>::infinity());
  return stored;
}

void ValidateRangeNoise(const RangeNoise& noise) { CheckFields(noise, "range noise: "); }

void AddRangeNoise(LaserScan& scan, const RangeNoise& noise, RandomEngine& engine) {
  if (!(scan.range_min_m >= 0.0 && scan.range_max_m > scan.range_min_m)) {
    throw InputError("range noise: the scan at " + std::to_string(scan.stamp_s) + " s has range_min_m = " +
                     std::to_string(scan.range_min_m) + " and range_max_m = " + std::to_string(scan.range_max_m) +
                     ", expected 0 <= range_min_m < range_max_m");
  }
  const float range_min = static_cast<float>(scan.range_min_m);
  const float range_max = NoReturnRangeM(scan.range_max_m);
  // The largest float below range_max_m: noise must not turn a return into "no return".
  const float largest_return = std::max(range_min, std::nextafter(range_max, range_min));
  for (float& range : scan.ranges_m) {
    const double dropout_draw = UniformUnit(engine);
    const double short_draw = UniformUnit(engine);
    const double short_fraction = UniformUnit(engine);
    const double gaussian = StandardNormal(engine);
    const bool hit = scan.IsHit(range);
    if (dropout_draw < noise.dropout_probability) {
      range = range_max;
    } else if (short_draw < noise.short_reading_probability) {
      const double upper = hit ? range : scan.range_max_m;
      range = static_cast<float>(scan.range_min_m + short_fraction * std::max(0.0, upper - scan.range_min_m));
    } else if (hit && noise.sigma_m > 0.0) {
      const float noisy = static_cast<float>(range + noise.sigma_m * gaussian);
      range = std::clamp(noisy, range_min, largest_return);
    }
  }
}

std::vector<LaserScan> ApplyRangeNoise(std::span<const LaserScan> scans, const RangeNoise& noise, std::uint64_t seed) {
  ValidateRangeNoise(noise);
  RandomEngine engine(seed);
  std::vector<LaserScan> noisy(scans.begin(), scans.end());
  for (LaserScan& scan : noisy) AddRangeNoise(scan, noise, engine);
  return noisy;
}

void to_json(nlohmann::json& out, const RangeNoise& noise) {
  out = nlohmann::json{{"model", kRangeModelName},
                       {"sigma_m", noise.sigma_m},
                       {"dropout_probability", noise.dropout_probability},
                       {"short_reading_probability", noise.short_reading_probability}};
}

RangeNoise RangeNoiseFromJson(const nlohmann::json& in, const std::string& path) {
  JsonFields fields(in, path);
  const std::string model = fields.Text("model", kRangeModelName);
  if (model != kRangeModelName) {
    throw InputError(fields.PathOf("model") + ": expected \"" + kRangeModelName + "\", got \"" + model + "\"");
  }
  RangeNoise noise;
  noise.sigma_m = fields.Number("sigma_m", 0.0);
  noise.dropout_probability = fields.Number("dropout_probability", 0.0);
  noise.short_reading_probability = fields.Number("short_reading_probability", 0.0);
  fields.Finish();
  CheckFields(noise, path + ".");
  return noise;
}

void from_json(const nlohmann::json& in, RangeNoise& noise) { noise = RangeNoiseFromJson(in); }

}  // namespace slamsweep::evaluator::inline noise
