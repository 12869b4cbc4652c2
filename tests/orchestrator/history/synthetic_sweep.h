#pragma once

// Synthetic sweep output directories for history and regression tests: results.sqlite filled through
// ResultsStore, plus run.json / result.json per run and summary.json (orchestrator/DESIGN.md). No SLAM program runs.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "orchestrator/store/results_store.h"
#include "orchestrator/store/summary_json.h"
#include "orchestrator/store/validity_table.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator::testing {

/// One synthetic sweep: `iterations` runs of one algorithm on one sequence with noise setting `noise`. The
/// APE rmse of a run is odometry_sigma * 10 * exp(N(0, 0.15)) — a drift proportional to the odometry noise, with
/// run-to-run scatter — and the corner count 40 + round(N(0, 2)) (integers, so ties).
struct SyntheticSweep {
  std::string name = "nightly";
  std::string algorithm = "icp-slam";
  std::string sequence = "intel";
  std::string noise = "noisy";
  double odometry_sigma = 0.01;
  int iterations = 10;
  std::uint32_t seed = 1;
  std::string started_at = "2026-11-20T02:00:00Z";
  /// Iterations (0-based) whose run failed.
  std::vector<int> failed_iterations;
  /// run.json's group.odometry, as the planner writes it; empty: a run.json from before the odometry mode
  /// existed (no group.odometry).
  std::string odometry = "recorded";
  /// run.json's sequence.ground_truth ("corrected_poses": a corrected log, where the odometry mode applies).
  std::string ground_truth = "relations";
  /// run.json's algorithm.parameters (a parameter sweep's setting).
  nlohmann::json parameters = nlohmann::json::object();
};

/// "k=v;..." as the planner writes group.parameters (names sorted, numbers as JSON writes them).
inline std::string SyntheticParametersText(const nlohmann::json& parameters) {
  std::string text;
  for (const auto& [name, value] : parameters.items()) {
    if (!text.empty()) text += ';';
    text += name + "=" + (value.is_string() ? value.get<std::string>() : value.dump());
  }
  return text;
}

inline nlohmann::json SyntheticSpec(const SyntheticSweep& sweep, const std::string& run_id, int iteration) {
  nlohmann::json spec = {
      {"run_id", run_id},
      {"sweep", sweep.name},
      {"algorithm", {{"name", sweep.algorithm}, {"adapter", "mrpt-icp-slam"}, {"parameters", sweep.parameters}}},
      {"sequence", {{"name", sweep.sequence}, {"format", "carmen"}, {"ground_truth", sweep.ground_truth}}},
      {"noise", {{"name", sweep.noise}, {"odometry", {{"alpha1", sweep.odometry_sigma}}}, {"range", nullptr}}},
      {"iteration", iteration},
      {"seed", sweep.seed * 1000 + static_cast<std::uint32_t>(iteration)},
      {"thresholds", nlohmann::json::array()}};
  // A run.json from before the mode existed has a group without "odometry".
  spec["group"] = {{"sequence", sweep.sequence},
                   {"algorithm", sweep.algorithm},
                   {"parameters", SyntheticParametersText(sweep.parameters)},
                   {"noise", sweep.noise}};
  if (!sweep.odometry.empty()) spec["group"]["odometry"] = sweep.odometry;
  return spec;
}

/// Writes the sweep into `dir` (created) and returns the APE rmse samples of its ok runs.
inline std::vector<double> WriteSyntheticSweep(const std::filesystem::path& dir, const SyntheticSweep& sweep) {
  std::filesystem::create_directories(dir / "runs");
  ResultsStore store = ResultsStore::Open(dir / "results.sqlite");
  SweepInfo info;
  info.name = sweep.name;
  info.started_at = sweep.started_at;
  info.config_sha = "synthetic";
  const std::int64_t sweep_id = store.BeginSweep(info);
  std::mt19937 random(sweep.seed);
  std::normal_distribution<double> scatter(0.0, 0.15);
  std::normal_distribution<double> corner_noise(0.0, 2.0);
  std::vector<double> ape;
  for (int i = 0; i < sweep.iterations; ++i) {
    const std::string run_id = sweep.algorithm + "-" + sweep.sequence + "-" + sweep.noise + "-" + sweep.odometry +
                               SyntheticParametersText(sweep.parameters) + "-i" + std::to_string(i) + "-" +
                               std::to_string(sweep.seed);
    const nlohmann::json spec = SyntheticSpec(sweep, run_id, i);
    nlohmann::json result = {{"run_id", run_id},
                             {"status", "ok"},
                             {"failure_kind", nullptr},
                             {"reason", ""},
                             {"exit_code", 0},
                             {"signal", nullptr},
                             {"wall_s", 2.0},
                             {"cpu_s", 1.9},
                             {"peak_rss_kb", 50000},
                             {"started_at", sweep.started_at},
                             {"finished_at", sweep.started_at},
                             {"outputs", nlohmann::json::object()},
                             {"metrics", nlohmann::json::array()},
                             {"metric_details", nlohmann::json::object()},
                             {"warnings", nlohmann::json::array()}};
    const double rmse_m = sweep.odometry_sigma * 10.0 * std::exp(scatter(random));
    const double corners = 40.0 + std::round(corner_noise(random));
    const bool failed =
        std::find(sweep.failed_iterations.begin(), sweep.failed_iterations.end(), i) != sweep.failed_iterations.end();
    if (failed) {
      result["status"] = "failed";
      result["failure_kind"] = "timeout";
      result["reason"] = "timed out after 60 s";
    } else {
      ape.push_back(rmse_m);
      result["metrics"] = {{{"metric", "ape_trans"}, {"statistic", "rmse"}, {"value", rmse_m}, {"unit", "m"}},
                           {{"metric", "ape_trans"}, {"statistic", "mean"}, {"value", rmse_m * 0.9}, {"unit", "m"}},
                           {{"metric", "corners"}, {"statistic", "value"}, {"value", corners}, {"unit", "count"}}};
    }
    const std::filesystem::path run_dir = dir / "runs" / run_id;
    std::filesystem::create_directories(run_dir);
    slamsweep::testing::WriteFile(run_dir / "run.json", spec.dump(2));
    slamsweep::testing::WriteFile(run_dir / "result.json", result.dump(2));
    store.RecordRun(sweep_id, spec, result, "runs/" + run_id);
  }
  store.FinishSweep(sweep_id, sweep.failed_iterations.empty() ? SweepStatus::kOk : SweepStatus::kFailed,
                    sweep.iterations);
  const std::vector<RunRecord> runs = store.Runs();
  WriteSummaryJson(runs, ValidityStudyOf(runs), dir / "summary.json");
  return ape;
}

}  // namespace slamsweep::orchestrator::testing
