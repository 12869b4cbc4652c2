#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/core/laser_scan.h"
#include "evaluator/noise/random.h"

namespace slamsweep::evaluator::inline noise {

/// Noise of a laser range finder. Per beam, in this order of precedence:
/// - a dropout (probability dropout_probability): no return, the range becomes range_max_m,
///   as a scanner reports a dark or glancing surface;
/// - else a spurious short reading (probability short_reading_probability): uniform in
///   [range_min_m, true range), as from dust, people or a sensor glitch;
/// - else, for a beam that hit something, Gaussian noise of standard deviation sigma_m, kept in
///   [range_min_m, range_max_m) so that a return stays a return.
/// All fields default to 0, which leaves scans unchanged.
struct RangeNoise {
  double sigma_m = 0.0;
  double dropout_probability = 0.0;
  double short_reading_probability = 0.0;

  bool operator==(const RangeNoise&) const = default;
};

/// The range a beam without return stores: the smallest float >= range_max_m, so that
/// LaserScan::IsHit is false for it even when range_max_m has no exact float (81.9 m).
float NoReturnRangeM(double range_max_m);

/// Throws InputError naming the field unless sigma_m is finite and >= 0 and both probabilities
/// lie in [0, 1].
void ValidateRangeNoise(const RangeNoise& noise);

/// Adds noise to every beam of `scan`. Every beam consumes the same number of draws whatever
/// happens to it, so changing one probability does not reshuffle the noise of other beams.
void AddRangeNoise(LaserScan& scan, const RangeNoise& noise, RandomEngine& engine);

/// Noisy copies of `scans`, all drawn from one engine seeded with `seed`.
std::vector<LaserScan> ApplyRangeNoise(std::span<const LaserScan> scans, const RangeNoise& noise, std::uint64_t seed);

/// JSON record {"model": "range_noise", "sigma_m": ..., ...}; the seed is recorded beside it.
void to_json(nlohmann::json& out, const RangeNoise& noise);
/// Strict reader: unknown fields and wrong types are InputErrors naming `path`.field; missing
/// fields stay 0; the result is validated.
RangeNoise RangeNoiseFromJson(const nlohmann::json& in, const std::string& path = "range_noise");
void from_json(const nlohmann::json& in, RangeNoise& noise);

}  // namespace slamsweep::evaluator::inline noise
