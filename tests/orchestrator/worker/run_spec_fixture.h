#pragma once

// Run specifications for adapter and worker tests: a short simulated sequence (exact ground
// truth, generated in-process, no shared data needed) and fake SLAM programs as shell scripts.

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "orchestrator/run/run_json.h"

namespace slamsweep::orchestrator::testing {

/// A simulated sequence of `scans` scans (the catalog's simulated-floor entry, cut).
inline RunSpec SimulatedRun(const std::string& adapter, std::size_t scans = 60) {
  RunSpec spec;
  spec.run_id = "test-run";
  spec.sweep = "test";
  spec.algorithm.name = adapter;
  spec.algorithm.adapter = adapter;
  spec.algorithm.timeout_s = 60;
  spec.sequence.entry.name = "simulated-floor";
  spec.sequence.entry.format = "simulated";
  spec.sequence.entry.ground_truth = evaluator::GroundTruthKind::kExact;
  spec.sequence.entry.simulation = {{"floor_plan", {{"seed", 1}}}, {"noise_seed", 1}};
  spec.sequence.max_scans = scans;
  spec.seed = 7;
  spec.evaluation.stages = 4;
  return spec;
}

/// Writes an executable `#!/bin/sh` script.
inline std::filesystem::path WriteScript(const std::filesystem::path& path, const std::string& body) {
  std::ofstream(path) << "#!/bin/sh\n" << body << "\n";
  ::chmod(path.c_str(), 0755);
  return path;
}

/// Writes run.json of `spec` into `run_dir` (created).
inline void WriteRunJson(const std::filesystem::path& run_dir, const RunSpec& spec) {
  std::filesystem::create_directories(run_dir);
  std::ofstream(run_dir / "run.json") << ToJson(spec).dump(2);
}

inline nlohmann::json ReadJson(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

inline std::string ReadText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace slamsweep::orchestrator::testing
