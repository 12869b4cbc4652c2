#pragma once

#include <string>
#include <utility>
#include <vector>

namespace slamsweep::orchestrator::inline adapters {

/// What `slamsweep algorithms` says about one adapter.
struct AlgorithmInfo {
  std::string adapter;  ///< the name a sweep's algorithm.adapter uses
  std::string title;
  bool installed = false;
  /// Version or commit when installed; how to install it when not.
  std::string status;
  std::string license;
  std::string seeding;  ///< SeedingName: seeded, deterministic, unseeded, or "per command"
  /// Parameters with their defaults, upstream names; empty value = no default shown.
  std::vector<std::pair<std::string, std::string>> parameters;
  /// How other parameters are named (MRPT: any Section.key of the template).
  std::string parameter_note;
  /// Where slamsweep's own defaults for the adapter were chosen and where they were checked since
  /// ("" when the adapter takes upstream's defaults as they are): a sweep that scores the sequence
  /// they were tuned on should know it.
  std::string defaults_note;
};

/// Every adapter in the order a user meets them: the roster, MRPT's programs, the odometry baseline,
/// the command adapter. Probes what is installed (drivers, manifests, MRPT programs, the Debian
/// package version) without running any SLAM.
std::vector<AlgorithmInfo> DescribeAlgorithms();

}  // namespace slamsweep::orchestrator::inline adapters
