#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline adapters {

/// One algorithm of the roster: a driver program slamsweep-slam-<name> (slam/<name>/) built
/// against an upstream that scripts/install-slam.sh installed (recipe scripts/slam/<upstream>.sh).
struct RosterAlgorithm {
  std::string_view name;      ///< the adapter name in a sweep: gmapping, tinyslam, ...
  std::string_view upstream;  ///< the recipe and manifest name: gmapping, slam-constructor, ...
  std::string_view title;     ///< what the report and `slamsweep algorithms` call it
  std::string_view license;   ///< the upstream's licence (the driver links it)
  Seeding seeding;            ///< whether the run's seed reaches a random generator
  /// A file beside the driver that it reads as configuration ("" for none): part of the build identity.
  std::string_view config_file = "";
  /// A folder of upstream configuration files the driver's options include ("" for none): installed as
  /// PREFIX/share/slamsweep/<upstream>/<dir>, in a build under the roster prefix's
  /// <upstream>/share/<upstream>/<dir>. Every file in it is part of the build identity.
  std::string_view upstream_config_dir = "";
  /// The LGPL shared library the driver links ("" for none): beside the installed driver (RUNPATH $ORIGIN), in a
  /// build under the roster prefix's <upstream>/lib. Readable in the sandbox and part of the build identity.
  std::string_view shared_library = "";
};

/// GMapping, tinySLAM, vinySLAM, Hector SLAM and Cartographer, in the paper's order, then slam_toolbox, LaMa's
/// Slam2D and LaMa's PFSlam2D.
std::span<const RosterAlgorithm> Roster();

/// The roster algorithm whose adapter name is `name`, or nullptr.
const RosterAlgorithm* FindRosterAlgorithm(std::string_view name);

/// Where the roster's upstream manifests are (PREFIX/share/slamsweep/slam): $SLAMSWEEP_SLAM_PREFIX, else
/// the installation the running program belongs to, else the build's configured prefix.
std::filesystem::path RosterPrefix();

/// The driver as the worker runs it: slamsweep-slam-<name> in $SLAMSWEEP_SLAM_DRIVER_DIR when set,
/// else beside the helper programs (evaluator/core/installation.h: an installation's lib/slamsweep),
/// else in the build's slam/bin folder; then in PATH. Throws InputError listing where it looked and
/// how to install it when it is nowhere.
std::filesystem::path RosterDriver(const RosterAlgorithm& algorithm);

/// Where the driver finds upstream's configuration files (upstream_config_dir), the same rule the
/// driver follows: the installation's copy, else the upstream's build prefix. Empty when it has none.
std::filesystem::path RosterUpstreamConfigDir(const RosterAlgorithm& algorithm);

/// The shared library the driver loads (shared_library): beside the driver when there, else under the roster
/// prefix. Empty when it has none.
std::filesystem::path RosterSharedLibrary(const RosterAlgorithm& algorithm);

/// What the driver reads besides its input: the installed upstreams (libraries, Cartographer's
/// configuration files), its config_file beside it (Cartographer's Lua options) and its shared library.
std::vector<std::filesystem::path> RosterProgramReads(const RosterAlgorithm& algorithm);

/// The files a run of the driver executes or reads as configuration: the driver, its shared library, its
/// config_file beside it, every file of its upstream_config_dir, and the upstream's install manifest (which
/// names the pinned commit). Throws InputError naming a missing one and how to install it.
std::vector<std::filesystem::path> RosterProgramFiles(const RosterAlgorithm& algorithm);

/// <prefix>/share/slamsweep/slam/<upstream>.json, written by install-slam.sh (upstream, commit,
/// licence, tarball hash, build time).
std::filesystem::path RosterManifestPath(const RosterAlgorithm& algorithm);

/// The manifest read, or nullopt when the upstream is not installed. A manifest that is not JSON
/// is an InputError naming it.
std::optional<nlohmann::json> ReadRosterManifest(const RosterAlgorithm& algorithm);

}  // namespace slamsweep::orchestrator::inline adapters
