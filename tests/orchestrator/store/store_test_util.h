#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace slamsweep::orchestrator::testing {

/// A run.json as DESIGN.md shows it, reduced to what the store reads.
inline nlohmann::json MakeSpec(const std::string& run_id, const std::string& algorithm = "icp-slam",
                               const std::string& sequence = "intel", int iteration = 0) {
  return {
      {"run_id", run_id},
      {"sweep", "test"},
      {"algorithm", {{"name", algorithm}, {"adapter", "mrpt-icp-slam"}, {"parameters", {{"ICP.maxIterations", 80}}}}},
      {"sequence", {{"name", sequence}, {"format", "carmen"}, {"ground_truth", "relations"}}},
      {"noise", {{"name", "clean"}, {"odometry", nullptr}, {"range", nullptr}}},
      {"iteration", iteration},
      {"seed", 123456789},
      {"thresholds", nlohmann::json::array()}};
}

/// An ok result.json with two APE statistics and one paper-map metric.
inline nlohmann::json MakeOkResult(const std::string& run_id, double wall_s = 3.0, double ape_rmse = 0.12,
                                   const std::string& finished_at = "2026-11-22T05:00:03Z") {
  return {{"run_id", run_id},
          {"status", "ok"},
          {"failure_kind", nullptr},
          {"reason", ""},
          {"exit_code", 0},
          {"signal", nullptr},
          {"wall_s", wall_s},
          {"cpu_s", 2.5},
          {"peak_rss_kb", 81234},
          {"started_at", "2026-11-22T05:00:00Z"},
          {"finished_at", finished_at},
          {"outputs", {{"map", "map.yaml"}, {"trajectory", "trajectory.tum"}, {"log", "log.txt"}}},
          {"metrics",
           {{{"metric", "ape_trans"}, {"statistic", "rmse"}, {"value", ape_rmse}, {"unit", "m"}},
            {{"metric", "ape_trans"}, {"statistic", "mean"}, {"value", 0.1}, {"unit", "m"}},
            {{"metric", "corners"}, {"statistic", "value"}, {"value", 17}, {"unit", "count"}}}},
          {"metric_details", {{"ape_trans", {{"align", "se2"}, {"t_max_diff_s", 0.01}}}}},
          {"warnings", nlohmann::json::array()}};
}

/// A failed result.json (the program was killed).
inline nlohmann::json MakeFailedResult(const std::string& run_id, const std::string& reason = "killed by SIGSEGV") {
  return {{"run_id", run_id},
          {"status", "failed"},
          {"failure_kind", "signal"},
          {"reason", reason},
          {"exit_code", nullptr},
          {"signal", 11},
          {"wall_s", 1.5},
          {"cpu_s", 1.0},
          {"peak_rss_kb", 1000},
          {"started_at", "2026-11-22T05:00:00Z"},
          {"finished_at", "2026-11-22T05:00:02Z"},
          {"outputs", {{"log", "log.txt"}}},
          {"metrics", nlohmann::json::array()},
          {"metric_details", nlohmann::json::object()},
          {"warnings", nlohmann::json::array()}};
}

}  // namespace slamsweep::orchestrator::testing
