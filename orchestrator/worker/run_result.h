#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "orchestrator/run/run_failure.h"
#include "orchestrator/run/run_flags.h"
#include "orchestrator/worker/run_metrics.h"

namespace slamsweep::orchestrator::inline worker {

/// result.json of one run (orchestrator/DESIGN.md): the commit point of the run.
struct RunResult {
  std::string run_id;
  /// Empty when the run succeeded.
  std::optional<FailureKind> failure_kind;
  std::string reason;
  std::optional<int> exit_code;
  std::optional<int> signal;
  double wall_s = 0.0;
  double cpu_s = 0.0;
  /// Absent when no program ran (the odometry baseline): the worker's own memory is not the program's.
  std::optional<std::int64_t> peak_rss_kb;
  std::string started_at;
  std::string finished_at;
  std::vector<std::string> command;
  nlohmann::json outputs = nlohmann::json::object();
  RunMetrics metrics;
  std::vector<std::string> warnings;
  /// The noise applied to the program's input and its seeds (RunInputs::noise_record).
  nlohmann::json noise;
  /// What the sequence is like (RunInputs::sequence_record): "stamps" when the reader records them.
  nlohmann::json sequence = nlohmann::json::object();
  /// The program's odometry was the reference (RunInputs::odometry_is_reference); absent when the
  /// inputs were never prepared.
  std::optional<bool> odometry_is_reference;
  /// How the program was isolated (worker.cc: "isolated", "proc", "user", "process_limit_by", "network",
  /// "why" when the sandbox differs from the full one or is absent); null when no program ran.
  nlohmann::json sandbox;
  /// Marks the worker measured (odometry = reference, unisolated); the orchestrator may add "stale" later.
  RunFlags flags;

  bool ok() const { return !failure_kind; }
  /// Marks the run failed (the first failure wins: later ones are consequences).
  void Fail(FailureKind kind, std::string why);
};

/// Exactly DESIGN.md's fields: status "ok"/"failed", failure_kind null or its name, etc.
nlohmann::json ToJson(const RunResult& result);

/// UTC time of `seconds_since_epoch` as "2026-11-22T05:00:00Z".
std::string Iso8601Utc(std::int64_t seconds_since_epoch);
/// Now, as Iso8601Utc.
std::string NowIso8601Utc();

/// Writes `value` to `file` through `file`.tmp, fsync and rename, so that a reader sees no file
/// or the whole file. Throws std::runtime_error naming the file when any step fails.
void WriteJsonFileAtomically(const std::filesystem::path& file, const nlohmann::json& value);

}  // namespace slamsweep::orchestrator::inline worker
