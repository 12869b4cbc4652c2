#include "slam/slam_toolbox/slam_toolbox_options.h"

#include <algorithm>
#include <array>

#include "evaluator/core/input_error.h"

namespace slamsweep::slam::slam_toolbox_driver {
namespace {

using evaluator::InputError;

// config/mapper_params_offline.yaml's Mapper parameters with the file's values, and the Mapper setter the node
// (slam_mapper.cpp) hands each one to. Karto's own defaults differ in 15 of them (minimum_travel_distance 0.2,
// scan_buffer_size 70, link_match_minimum_response_fine 0.8, use_response_expansion false, ...): the driver sets
// every one, so none of Karto's is used.
struct Flag {
  const char* name;
  bool fallback;
  void (karto::Mapper::*set)(bool);
};
struct Count {
  const char* name;
  int fallback;
  void (karto::Mapper::*set)(int);
  int minimum;
};
struct Real {
  const char* name;
  double fallback;
  void (karto::Mapper::*set)(double);
  bool positive;  ///< the node refuses a value <= 0 (it falls back to its default there; the driver says so)
};

constexpr std::array kFlags = {
    Flag{"use_scan_matching", true, &karto::Mapper::setParamUseScanMatching},
    Flag{"use_scan_barycenter", true, &karto::Mapper::setParamUseScanBarycenter},
    Flag{"do_loop_closing", true, &karto::Mapper::setParamDoLoopClosing},
    Flag{"use_response_expansion", true, &karto::Mapper::setParamUseResponseExpansion},
};
constexpr std::array kCounts = {
    Count{"scan_buffer_size", 10, &karto::Mapper::setParamScanBufferSize, 1},
    Count{"loop_match_minimum_chain_size", 10, &karto::Mapper::setParamLoopMatchMinimumChainSize, 1},
};
constexpr std::array kReals = {
    Real{"minimum_travel_distance", 0.5, &karto::Mapper::setParamMinimumTravelDistance, false},
    Real{"minimum_travel_heading", 0.5, &karto::Mapper::setParamMinimumTravelHeading, false},
    Real{"scan_buffer_maximum_scan_distance", 10.0, &karto::Mapper::setParamScanBufferMaximumScanDistance, true},
    Real{"link_match_minimum_response_fine", 0.1, &karto::Mapper::setParamLinkMatchMinimumResponseFine, false},
    Real{"link_scan_maximum_distance", 1.5, &karto::Mapper::setParamLinkScanMaximumDistance, false},
    Real{"loop_search_maximum_distance", 3.0, &karto::Mapper::setParamLoopSearchMaximumDistance, false},
    Real{"loop_match_maximum_variance_coarse", 3.0, &karto::Mapper::setParamLoopMatchMaximumVarianceCoarse, false},
    Real{"loop_match_minimum_response_coarse", 0.35, &karto::Mapper::setParamLoopMatchMinimumResponseCoarse, false},
    Real{"loop_match_minimum_response_fine", 0.45, &karto::Mapper::setParamLoopMatchMinimumResponseFine, false},
    Real{"correlation_search_space_dimension", 0.5, &karto::Mapper::setParamCorrelationSearchSpaceDimension, true},
    Real{"correlation_search_space_resolution", 0.01, &karto::Mapper::setParamCorrelationSearchSpaceResolution, true},
    Real{"correlation_search_space_smear_deviation", 0.1, &karto::Mapper::setParamCorrelationSearchSpaceSmearDeviation,
         true},
    Real{"loop_search_space_dimension", 8.0, &karto::Mapper::setParamLoopSearchSpaceDimension, true},
    Real{"loop_search_space_resolution", 0.05, &karto::Mapper::setParamLoopSearchSpaceResolution, true},
    Real{"loop_search_space_smear_deviation", 0.03, &karto::Mapper::setParamLoopSearchSpaceSmearDeviation, true},
    Real{"distance_variance_penalty", 0.5, &karto::Mapper::setParamDistanceVariancePenalty, false},
    Real{"angle_variance_penalty", 1.0, &karto::Mapper::setParamAngleVariancePenalty, false},
    Real{"fine_search_angle_offset", 0.00349, &karto::Mapper::setParamFineSearchAngleOffset, false},
    Real{"coarse_search_angle_offset", 0.349, &karto::Mapper::setParamCoarseSearchAngleOffset, false},
    Real{"coarse_angle_resolution", 0.0349, &karto::Mapper::setParamCoarseAngleResolution, false},
    Real{"minimum_angle_penalty", 0.9, &karto::Mapper::setParamMinimumAnglePenalty, false},
    Real{"minimum_distance_penalty", 0.5, &karto::Mapper::setParamMinimumDistancePenalty, false},
};

/// The solver's string parameters: the file's value and the names the solver knows (it silently takes its
/// default for any other; the driver refuses it instead).
struct Choice {
  const char* name;
  const char* fallback;
  std::vector<std::string> accepted;
};

const std::vector<Choice>& SolverChoices() {
  static const std::vector<Choice> choices = {
      {"ceres_linear_solver",
       "SPARSE_NORMAL_CHOLESKY",
       {"SPARSE_NORMAL_CHOLESKY", "SPARSE_SCHUR", "ITERATIVE_SCHUR", "CGNR"}},
      {"ceres_preconditioner", "SCHUR_JACOBI", {"JACOBI", "IDENTITY", "SCHUR_JACOBI"}},
      {"ceres_trust_strategy", "LEVENBERG_MARQUARDT", {"LEVENBERG_MARQUARDT", "DOGLEG"}},
      {"ceres_dogleg_type", "TRADITIONAL_DOGLEG", {"TRADITIONAL_DOGLEG", "SUBSPACE_DOGLEG"}},
      {"ceres_loss_function", "None", {"None", "HuberLoss", "CauchyLoss"}},
  };
  return choices;
}

std::string Joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

SlamToolboxOptions ReadSlamToolboxOptions(Parameters& parameters) {
  SlamToolboxOptions o;
  for (const Flag& flag : kFlags) {
    const bool value = parameters.Flag(flag.name, flag.fallback);
    o.mapper_settings.push_back([set = flag.set, value](karto::Mapper& mapper) { (mapper.*set)(value); });
  }
  for (const Count& count : kCounts) {
    const int value = parameters.Integer(count.name, count.fallback);
    if (value < count.minimum) {
      throw InputError("parameter " + std::string(count.name) + ": expected at least " + std::to_string(count.minimum) +
                       ", got " + std::to_string(value));
    }
    o.mapper_settings.push_back([set = count.set, value](karto::Mapper& mapper) { (mapper.*set)(value); });
  }
  for (const Real& real : kReals) {
    const double value = parameters.Real(real.name, real.fallback);
    if (real.positive && !(value > 0)) throw InputError("parameter " + std::string(real.name) + ": expected > 0");
    o.mapper_settings.push_back([set = real.set, value](karto::Mapper& mapper) { (mapper.*set)(value); });
    if (std::string_view(real.name) == "minimum_travel_distance") o.minimum_travel_distance = value;
  }
  o.minimum_time_interval_s = parameters.Real("minimum_time_interval", o.minimum_time_interval_s);
  o.throttle_scans = parameters.Integer("throttle_scans", o.throttle_scans);
  if (o.throttle_scans < 1) throw InputError("parameter throttle_scans: expected at least 1");
  o.max_laser_range_m = parameters.Real("max_laser_range", o.max_laser_range_m);
  o.resolution_m = parameters.Real("resolution", o.resolution_m);
  if (!(o.resolution_m > 0)) throw InputError("parameter resolution: expected a cell size > 0");
  for (const Choice& choice : SolverChoices()) {
    const std::string value = parameters.Text(choice.name, choice.fallback);
    if (std::find(choice.accepted.begin(), choice.accepted.end(), value) == choice.accepted.end()) {
      throw InputError("parameter " + std::string(choice.name) + ": expected one of " + Joined(choice.accepted) +
                       ", got '" + value + "'");
    }
    o.solver_parameters[choice.name] = value;
  }
  return o;
}

}  // namespace slamsweep::slam::slam_toolbox_driver
