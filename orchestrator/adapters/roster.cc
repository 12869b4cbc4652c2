#include "orchestrator/adapters/roster.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <fstream>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/core/installation.h"
#include "orchestrator/config/program_path.h"

namespace slamsweep::orchestrator::inline adapters {

namespace fs = std::filesystem;

namespace {

constexpr std::array kRoster = {
    RosterAlgorithm{"gmapping", "gmapping", "GMapping (openslam_gmapping)", "BSD", Seeding::kSeeded},
    RosterAlgorithm{"tinyslam", "slam-constructor", "tinySLAM (slam-constructor)", "MIT", Seeding::kSeeded},
    RosterAlgorithm{"vinyslam", "slam-constructor", "vinySLAM (slam-constructor)", "MIT", Seeding::kSeeded},
    RosterAlgorithm{"hector", "hector", "Hector SLAM (hector_slam_lib)", "BSD", Seeding::kDeterministic},
    RosterAlgorithm{"cartographer", "cartographer", "Cartographer", "Apache-2.0", Seeding::kDeterministic,
                    "slamsweep-slam-cartographer.lua", "configuration_files"},
    // Beyond the paper: slam_toolbox's Karto and LaMa, each linked as the LGPL shared library its licence asks
    // for (lib/slamsweep beside the driver).
    RosterAlgorithm{"slam-toolbox", "slam-toolbox", "slam_toolbox (Karto Mapper, Ceres solver)",
                    "LGPL-3.0 (Karto) and LGPL-2.1 (Ceres solver plugin), as the shared library "
                    "libslam_toolbox_karto.so",
                    Seeding::kDeterministic, "", "", "libslam_toolbox_karto.so"},
    RosterAlgorithm{"lama", "lama", "LaMa Slam2D (iris_lama)",
                    "BSD-3-Clause; libiris_lama.so, a shared library, compiles Eigen's Amd.h (LGPL-2.1)",
                    Seeding::kDeterministic, "", "", "libiris_lama.so"},
    RosterAlgorithm{"lama-pf", "lama", "LaMa PFSlam2D (iris_lama)",
                    "BSD-3-Clause; libiris_lama.so, a shared library, compiles Eigen's Amd.h (LGPL-2.1)",
                    Seeding::kSeeded, "", "", "libiris_lama.so"},
};

}  // namespace

std::span<const RosterAlgorithm> Roster() { return kRoster; }

const RosterAlgorithm* FindRosterAlgorithm(std::string_view name) {
  for (const RosterAlgorithm& algorithm : kRoster) {
    if (algorithm.name == name) return &algorithm;
  }
  return nullptr;
}

fs::path RosterPrefix() {
  const char* configured = std::getenv("SLAMSWEEP_SLAM_PREFIX");
  if (configured != nullptr && *configured != '\0') return configured;
  // An installation keeps the manifests in PREFIX/share/slamsweep/slam.
  if (const auto installed = evaluator::FindInstalledData("slam"))
    return installed->parent_path().parent_path().parent_path();
  return SLAMSWEEP_DEFAULT_SLAM_PREFIX;
}

fs::path RosterDriver(const RosterAlgorithm& algorithm) {
  const std::string program = "slamsweep-slam-" + std::string(algorithm.name);
  const char* configured = std::getenv("SLAMSWEEP_SLAM_DRIVER_DIR");
  // $SLAMSWEEP_SLAM_DRIVER_DIR alone, else beside the helpers (an installation's PREFIX/lib/slamsweep),
  // else where this build put the drivers; PATH last.
  std::vector<fs::path> places;
  if (configured != nullptr && *configured != '\0') {
    places.emplace_back(configured);
  } else {
    places = evaluator::LibexecSearchDirs();
    places.emplace_back(SLAMSWEEP_DEFAULT_SLAM_DRIVER_DIR);
  }
  std::string looked;
  for (const fs::path& place : places) {
    if (fs::is_regular_file(place / program)) return place / program;
    looked += place.string() + ", ";
  }
  try {
    return ResolveProgram(program, fs::current_path());
  } catch (const evaluator::InputError&) {
    throw evaluator::InputError("algorithm.adapter " + std::string(algorithm.name) + ": " + program +
                                " is not built (looked in " + looked +
                                "and PATH); install it with scripts/install-slam.sh " +
                                std::string(algorithm.upstream) + " && scripts/build.sh");
  }
}

fs::path RosterUpstreamConfigDir(const RosterAlgorithm& algorithm) {
  if (algorithm.upstream_config_dir.empty()) return {};
  const std::string upstream(algorithm.upstream);
  const std::string dir(algorithm.upstream_config_dir);
  if (const auto installed = evaluator::FindInstalledData(upstream + "/" + dir)) return *installed;
  return RosterPrefix() / upstream / "share" / upstream / dir;
}

fs::path RosterSharedLibrary(const RosterAlgorithm& algorithm) {
  if (algorithm.shared_library.empty()) return {};
  const std::string library(algorithm.shared_library);
  const fs::path beside = RosterDriver(algorithm).parent_path() / library;
  if (fs::is_regular_file(beside)) return beside;
  return RosterPrefix() / std::string(algorithm.upstream) / "lib" / library;
}

std::vector<fs::path> RosterProgramReads(const RosterAlgorithm& algorithm) {
  std::vector<fs::path> reads = {fs::absolute(RosterPrefix()).lexically_normal()};
  // The driver's configuration beside it (Cartographer's Lua options), found from the driver's own path.
  if (!algorithm.config_file.empty()) reads.push_back(RosterDriver(algorithm).parent_path() / algorithm.config_file);
  // An installation's copy of upstream's files (slam-constructor's properties, Cartographer's Lua files).
  if (const auto installed = evaluator::FindInstalledData(algorithm.upstream)) reads.push_back(*installed);
  // Upstream's configuration files, wherever the installation keeps them.
  if (const fs::path upstream = RosterUpstreamConfigDir(algorithm); !upstream.empty()) {
    reads.push_back(fs::absolute(upstream).lexically_normal());
  }
  // The library an installed driver loads from beside itself, where the sandbox shows nothing but the driver.
  if (const fs::path library = RosterSharedLibrary(algorithm); !library.empty()) {
    reads.push_back(fs::absolute(library).lexically_normal());
  }
  return reads;
}

std::vector<fs::path> RosterProgramFiles(const RosterAlgorithm& algorithm) {
  const fs::path driver = RosterDriver(algorithm);
  std::vector<fs::path> files = {driver};
  if (const fs::path library = RosterSharedLibrary(algorithm); !library.empty()) {
    if (!fs::is_regular_file(library)) {
      throw evaluator::InputError(
          "algorithm.adapter " + std::string(algorithm.name) + ": " + library.string() +
          " missing (the upstream's shared library the driver links): scripts/install-slam.sh " +
          std::string(algorithm.upstream) + " && scripts/build.sh");
    }
    files.push_back(library);
  }
  if (!algorithm.config_file.empty()) {
    const fs::path config = driver.parent_path() / algorithm.config_file;
    if (!fs::is_regular_file(config)) {
      throw evaluator::InputError("algorithm.adapter " + std::string(algorithm.name) + ": " + config.string() +
                                  " missing (the driver's configuration, copied beside it by scripts/build.sh)");
    }
    files.push_back(config);
  }
  if (!algorithm.upstream_config_dir.empty()) {
    const fs::path folder = RosterUpstreamConfigDir(algorithm);
    std::vector<fs::path> upstream_files;
    std::error_code error;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
      if (entry.is_regular_file()) upstream_files.push_back(entry.path());
    }
    if (error || upstream_files.empty()) {
      throw evaluator::InputError("algorithm.adapter " + std::string(algorithm.name) + ": " + folder.string() +
                                  " missing or empty (upstream's configuration files): scripts/install-slam.sh " +
                                  std::string(algorithm.upstream));
    }
    std::sort(upstream_files.begin(), upstream_files.end());
    files.insert(files.end(), upstream_files.begin(), upstream_files.end());
  }
  const fs::path manifest = RosterManifestPath(algorithm);
  if (!fs::is_regular_file(manifest)) {
    throw evaluator::InputError("algorithm.adapter " + std::string(algorithm.name) + ": " + manifest.string() +
                                " missing: install the upstream with scripts/install-slam.sh " +
                                std::string(algorithm.upstream));
  }
  files.push_back(manifest);
  return files;
}

fs::path RosterManifestPath(const RosterAlgorithm& algorithm) {
  return RosterPrefix() / "share" / "slamsweep" / "slam" / (std::string(algorithm.upstream) + ".json");
}

std::optional<nlohmann::json> ReadRosterManifest(const RosterAlgorithm& algorithm) {
  const fs::path path = RosterManifestPath(algorithm);
  std::ifstream in(path);
  if (!in) return std::nullopt;
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& error) {
    throw evaluator::InputError(evaluator::Located(path, 0, std::string("not a roster manifest: ") + error.what()));
  }
}

}  // namespace slamsweep::orchestrator::inline adapters
