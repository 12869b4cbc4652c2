#include "orchestrator/adapters/roster.h"

#include <array>
#include <cstdlib>
#include <fstream>

#include "evaluator/core/input_error.h"
#include "orchestrator/config/program_path.h"

namespace slamsweep::orchestrator {

namespace fs = std::filesystem;

namespace {

constexpr std::array kRoster = {
    RosterAlgorithm{"gmapping", "gmapping", "GMapping (openslam_gmapping)", "BSD", Seeding::kSeeded},
    RosterAlgorithm{"tinyslam", "slam-constructor", "tinySLAM (slam-constructor)", "MIT", Seeding::kSeeded},
    RosterAlgorithm{"vinyslam", "slam-constructor", "vinySLAM (slam-constructor)", "MIT", Seeding::kSeeded},
    RosterAlgorithm{"hector", "hector", "Hector SLAM (hector_slam_lib)", "BSD", Seeding::kDeterministic},
    RosterAlgorithm{"cartographer", "cartographer", "Cartographer", "Apache-2.0", Seeding::kDeterministic},
};

fs::path FromEnvironment(const char* variable, const char* fallback) {
  const char* value = std::getenv(variable);
  return (value != nullptr && *value != '\0') ? fs::path(value) : fs::path(fallback);
}

}  // namespace

std::span<const RosterAlgorithm> Roster() { return kRoster; }

const RosterAlgorithm* FindRosterAlgorithm(std::string_view name) {
  for (const RosterAlgorithm& algorithm : kRoster) {
    if (algorithm.name == name) return &algorithm;
  }
  return nullptr;
}

fs::path RosterPrefix() { return FromEnvironment("SLAMSWEEP_SLAM_PREFIX", SLAMSWEEP_DEFAULT_SLAM_PREFIX); }

fs::path RosterDriver(const RosterAlgorithm& algorithm) {
  const std::string program = "slamsweep-slam-" + std::string(algorithm.name);
  const fs::path built = FromEnvironment("SLAMSWEEP_SLAM_DRIVER_DIR", SLAMSWEEP_DEFAULT_SLAM_DRIVER_DIR) / program;
  if (fs::is_regular_file(built)) return built;
  try {
    return ResolveProgram(program, fs::current_path());
  } catch (const evaluator::InputError&) {
    throw evaluator::InputError("algorithm.adapter " + std::string(algorithm.name) + ": " + program + " is not built (looked in " +
                                built.parent_path().string() + " and PATH); install it with scripts/install-slam.sh " +
                                std::string(algorithm.upstream) + " && scripts/build.sh");
  }
}

std::vector<fs::path> RosterProgramReads(const RosterAlgorithm& algorithm) {
  std::vector<fs::path> reads = {fs::absolute(RosterPrefix()).lexically_normal()};
  if (algorithm.upstream == "cartographer") reads.emplace_back(SLAMSWEEP_CARTOGRAPHER_LUA_DIR);
  return reads;
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
