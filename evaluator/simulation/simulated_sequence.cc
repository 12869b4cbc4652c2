#include "evaluator/simulation/simulated_sequence.h"

#include "evaluator/core/input_error.h"
#include "evaluator/noise/json_fields.h"
#include "evaluator/noise/random.h"

namespace slamsweep::evaluator::inline simulation {
namespace {

constexpr const char* kGenerator = "slamsweep.simulation";
// Bump when the same options would produce a different sequence.
constexpr int kVersion = 1;
constexpr std::uint64_t kRangeNoiseStream = 0;
constexpr std::uint64_t kOdometryNoiseStream = 1;

}  // namespace

SimulatedSequence SimulateSequence(const SimulationOptions& options) {
  ValidateLaserOptions(options.laser);
  ValidateRangeNoise(options.range_noise);
  ValidateOdometryNoise(options.odometry_noise);
  FloorPlan plan = GenerateFloorPlan(options.floor_plan);

  SimulatedSequence sequence;
  sequence.ground_truth = FollowWaypoints(TourWaypoints(plan), options.path);
  sequence.scans.reserve(sequence.ground_truth.size());
  RandomEngine range_engine(DeriveSeed(options.noise_seed, kRangeNoiseStream));
  for (std::size_t i = 0; i < sequence.ground_truth.size(); ++i) {
    LaserScan scan =
        SimulateScan(plan.grid, sequence.ground_truth.poses()[i], sequence.ground_truth.stamps_s()[i], options.laser);
    AddRangeNoise(scan, options.range_noise, range_engine);
    sequence.scans.push_back(std::move(scan));
  }
  sequence.odometry = ApplyOdometryNoise(sequence.ground_truth, options.odometry_noise,
                                         DeriveSeed(options.noise_seed, kOdometryNoiseStream));
  sequence.specification = options;
  sequence.specification["scan_count"] = sequence.scans.size();
  sequence.specification["duration_s"] = sequence.ground_truth.EndS() - sequence.ground_truth.StartS();
  sequence.floor_plan = std::move(plan.grid);
  return sequence;
}

void to_json(nlohmann::json& out, const SimulationOptions& options) {
  out = nlohmann::json{{"generator", kGenerator},
                       {"version", kVersion},
                       {"floor_plan", options.floor_plan},
                       {"path", options.path},
                       {"laser", options.laser},
                       {"range_noise", options.range_noise},
                       {"odometry_noise", options.odometry_noise},
                       {"noise_seed", options.noise_seed}};
}

SimulationOptions SimulationOptionsFromJson(const nlohmann::json& in, const std::string& path) {
  JsonFields fields(in, path);
  const std::string generator = fields.Text("generator", kGenerator);
  if (generator != kGenerator) {
    throw InputError(fields.PathOf("generator") + ": expected \"" + kGenerator + "\", got \"" + generator + "\"");
  }
  const int version = fields.Integer("version", kVersion);
  if (version != kVersion) {
    throw InputError(fields.PathOf("version") + ": this build generates version " + std::to_string(kVersion) +
                     " sequences, got " + std::to_string(version));
  }
  SimulationOptions options;
  if (const nlohmann::json* part = fields.Object("floor_plan")) {
    options.floor_plan = FloorPlanOptionsFromJson(*part, fields.PathOf("floor_plan"));
  }
  if (const nlohmann::json* part = fields.Object("path"))
    options.path = PathOptionsFromJson(*part, fields.PathOf("path"));
  if (const nlohmann::json* part = fields.Object("laser")) {
    options.laser = LaserOptionsFromJson(*part, fields.PathOf("laser"));
  }
  if (const nlohmann::json* part = fields.Object("range_noise")) {
    options.range_noise = RangeNoiseFromJson(*part, fields.PathOf("range_noise"));
  }
  if (const nlohmann::json* part = fields.Object("odometry_noise")) {
    options.odometry_noise = OdometryNoiseFromJson(*part, fields.PathOf("odometry_noise"));
  }
  options.noise_seed = fields.Unsigned("noise_seed", options.noise_seed);
  // Written by SimulateSequence into the specification; accepted so that a recorded
  // specification can be read back as options.
  fields.Unsigned("scan_count", 0);
  fields.Number("duration_s", 0.0);
  fields.Finish();
  return options;
}

}  // namespace slamsweep::evaluator::inline simulation
