#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/core/laser_scan.h"
#include "evaluator/core/occupancy_grid.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/noise/odometry_noise.h"
#include "evaluator/noise/range_noise.h"
#include "evaluator/simulation/floor_plan.h"
#include "evaluator/simulation/laser_simulator.h"
#include "evaluator/simulation/path_generator.h"

namespace slamsweep::evaluator::inline simulation {

/// Everything that defines a simulated sequence. The floor plan has its own seed (the layout
/// stays the same across noise iterations); noise_seed drives the range and odometry noise
/// through separate streams (DeriveSeed(noise_seed, 0) and DeriveSeed(noise_seed, 1)).
/// The default odometry noise applies per pose step (10 Hz by default) and drifts the
/// default tour (about 110 m) by metres, enough to give a SLAM algorithm real work.
struct SimulationOptions {
  FloorPlanOptions floor_plan;
  PathOptions path;
  LaserOptions laser;
  RangeNoise range_noise{0.01, 0.0, 0.0};
  OdometryNoise odometry_noise{0.005, 0.0002, 0.005, 0.0002, 0.0, 0.0};
  std::uint64_t noise_seed = 1;
};

/// A sequence with exact ground truth: one scan per ground-truth pose (same stamps), taken
/// from that pose in the floor plan and then made noisy; odometry is the ground truth with
/// odometry noise. `specification` records every option and seed, enough to regenerate it.
struct SimulatedSequence {
  std::vector<LaserScan> scans;
  Trajectory ground_truth;
  Trajectory odometry;
  nlohmann::json specification;
  /// The map the scans were simulated in: the true map for map metrics.
  OccupancyGrid floor_plan;
};

/// Deterministic: the same options give the same sequence bit for bit (on one C library; the
/// floor plan and the path are the same on any machine). Throws InputError for invalid options.
SimulatedSequence SimulateSequence(const SimulationOptions& options);

/// {"generator": "slamsweep.simulation", "version": 1, "floor_plan": ..., "path": ...,
///  "laser": ..., "range_noise": ..., "odometry_noise": ..., "noise_seed": ...}
void to_json(nlohmann::json& out, const SimulationOptions& options);
/// Reads what to_json writes (generator and version must match when present); strict, so a
/// misspelt option is an InputError naming it.
SimulationOptions SimulationOptionsFromJson(const nlohmann::json& in, const std::string& path = "simulation");

}  // namespace slamsweep::evaluator::inline simulation
