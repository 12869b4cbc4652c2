#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "orchestrator/matrix/run_spec.h"

namespace slamsweep::orchestrator {

/// One algorithm of the paper's roster: a driver program slamsweep-slam-<name> (slam/<name>/) built
/// against an upstream that scripts/install-slam.sh installed (recipe scripts/slam/<upstream>.sh).
struct RosterAlgorithm {
  std::string_view name;      ///< the adapter name in a sweep: gmapping, tinyslam, ...
  std::string_view upstream;  ///< the recipe and manifest name: gmapping, slam-constructor, ...
  std::string_view title;     ///< what the report and `slamsweep algorithms` call it
  std::string_view license;   ///< the upstream's licence (the driver links it)
  Seeding seeding;            ///< whether the run's seed reaches a random generator
};

/// GMapping, tinySLAM, vinySLAM, Hector SLAM and Cartographer, in the paper's order.
std::span<const RosterAlgorithm> Roster();

/// The roster algorithm whose adapter name is `name`, or nullptr.
const RosterAlgorithm* FindRosterAlgorithm(std::string_view name);

/// Where the roster's upstream builds are: $SLAMSWEEP_SLAM_PREFIX, else the build's configured prefix.
std::filesystem::path RosterPrefix();

/// The driver as the worker runs it: slamsweep-slam-<name> in the build's slam/bin folder
/// ($SLAMSWEEP_SLAM_DRIVER_DIR overrides it), else in PATH. Throws InputError saying how to install
/// it when it is in neither.
std::filesystem::path RosterDriver(const RosterAlgorithm& algorithm);

/// What the driver reads besides its input: the installed upstreams (libraries, Cartographer's
/// configuration files) and, for Cartographer, the driver's Lua options in the source tree.
std::vector<std::filesystem::path> RosterProgramReads(const RosterAlgorithm& algorithm);

/// <prefix>/share/slamsweep/slam/<upstream>.json, written by install-slam.sh (upstream, commit,
/// licence, tarball hash, build time).
std::filesystem::path RosterManifestPath(const RosterAlgorithm& algorithm);

/// The manifest read, or nullopt when the upstream is not installed. A manifest that is not JSON
/// is an InputError naming it.
std::optional<nlohmann::json> ReadRosterManifest(const RosterAlgorithm& algorithm);

}  // namespace slamsweep::orchestrator
