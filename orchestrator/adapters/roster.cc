#include "orchestrator/adapters/roster.h"

#include <array>
#include <cstdlib>
#include <fstream>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/core/installation.h"
#include "orchestrator/config/program_path.h"

namespace slamsweep::orchestrator {

namespace fs = std::filesystem;

namespace {

constexpr std::array kRoster = {
    RosterAlgorithm{"gmapping", "gmapping", "GMapping (openslam_gmapping)", "BSD", Seeding::kSeeded},
    RosterAlgorithm{"tinyslam", "slam-constructor", "tinySLAM (slam-constructor)", "MIT", Seeding::kSeeded},
    RosterAlgorithm{"vinyslam", "slam-constructor", "vinySLAM (slam-constructor)", "MIT", Seeding::kSeeded},
    RosterAlgorithm{"hector", "hector", "Hector SLAM (hector_slam_lib)", "BSD", Seeding::kDeterministic},
    RosterAlgorithm{"cartographer", "cartographer", "Cartographer", "Apache-2.0", Seeding::kDeterministic,
                    "slamsweep-slam-cartographer.lua"},
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
  if (const auto installed = evaluator::FindInstalledData("slam")) return installed->parent_path().parent_path().parent_path();
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
    throw evaluator::InputError("algorithm.adapter " + std::string(algorithm.name) + ": " + program + " is not built (looked in " +
                                looked + "and PATH); install it with scripts/install-slam.sh " +
                                std::string(algorithm.upstream) + " && scripts/build.sh");
  }
}

std::vector<fs::path> RosterProgramReads(const RosterAlgorithm& algorithm) {
  std::vector<fs::path> reads = {fs::absolute(RosterPrefix()).lexically_normal()};
  // The driver's configuration beside it (Cartographer's Lua options), found from /proc/self/exe.
  if (!algorithm.config_file.empty()) reads.push_back(RosterDriver(algorithm).parent_path() / algorithm.config_file);
  return reads;
}

std::vector<fs::path> RosterProgramFiles(const RosterAlgorithm& algorithm) {
  const fs::path driver = RosterDriver(algorithm);
  std::vector<fs::path> files = {driver};
  if (!algorithm.config_file.empty()) {
    const fs::path config = driver.parent_path() / algorithm.config_file;
    if (!fs::is_regular_file(config)) {
      throw evaluator::InputError("algorithm.adapter " + std::string(algorithm.name) + ": " + config.string() +
                                  " missing (the driver's configuration, copied beside it by scripts/build.sh)");
    }
    files.push_back(config);
  }
  const fs::path manifest = RosterManifestPath(algorithm);
  if (!fs::is_regular_file(manifest)) {
    throw evaluator::InputError("algorithm.adapter " + std::string(algorithm.name) + ": " + manifest.string() +
                                " missing: install the upstream with scripts/install-slam.sh " + std::string(algorithm.upstream));
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

}  // namespace slamsweep::orchestrator
