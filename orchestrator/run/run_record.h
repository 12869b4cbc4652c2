#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "orchestrator/run/flat_metric.h"
#include "orchestrator/run/run_flags.h"
#include "orchestrator/run/run_status.h"

namespace slamsweep::orchestrator::inline run {

/// File names from result.json's `outputs`, relative to the run folder; empty when absent.
struct RunOutputs {
  std::string map;
  std::string trajectory;
  std::string reference;
  std::string vector_map;
  std::string log;
  std::vector<std::string> stages;
  /// Every stage map as one animated PNG.
  std::string stage_animation;
};

/// One run of a sweep, as read from its folder (run.json and result.json of runs/<id>/, report/model/load_runs.h)
/// or from the results database (ResultsStore::Runs): the one record the store's outputs, the report and the
/// metric validity study read. Every string is untrusted input: pages escape it, file names are derived with
/// SafeFileName.
struct RunRecord {
  std::string run_id;         ///< the folder name (what exists on disk)
  std::filesystem::path dir;  ///< absolute run folder (read from a folder; empty from the database)
  std::string run_dir;        ///< relative to the output directory ("runs/<run-id>"; from the database)
  std::string algorithm;      ///< "?" when unknown
  std::string sequence;       ///< "?" when unknown
  std::string noise;
  /// run.json's group.parameters ("k=v;...", "" for none): with algorithm, sequence and noise, the
  /// comparison group. `parameter_values` holds them as JSON for labels that show what varies.
  std::string parameters;
  nlohmann::json parameter_values = nlohmann::json::object();
  /// run.json's group.odometry ("recorded", "reference"; "" for a run planned before the mode): runs
  /// of different modes never share a row.
  std::string odometry;
  /// The program got the reference as odometry (result.json when measured, else run.json).
  bool odometry_is_reference = false;
  /// The run's marks (RunFlagsOf run.json and result.json): a flagged run is shown, never ranked.
  RunFlags flags;
  /// run.json's seeding: "seeded", "deterministic", "unseeded" ("" when not recorded).
  std::string seeding;
  /// run.json's sweep name.
  std::string sweep;
  int iteration = 0;
  RunStatus status = RunStatus::kUnfinished;
  std::string failure_kind;
  std::string reason;
  std::optional<int> exit_code;
  std::optional<int> signal;
  std::optional<double> wall_s;
  std::optional<double> cpu_s;
  std::optional<double> peak_rss_kb;
  std::string started_at;
  std::string finished_at;
  std::vector<std::string> command;
  RunOutputs outputs;
  /// In the order the worker listed them. Read from a folder, a metric without a value is left out; the
  /// database keeps it, valueless.
  std::vector<FlatMetric> metrics;
  /// result.json's reference_floor: the reference itself scored by the relations metric, exactly as
  /// the run's estimate (empty without reference or relations).
  std::vector<FlatMetric> reference_floor;
  /// What is kept of result.json's metric_details: per metric its "specification" and its top-level
  /// numbers and texts, and of segment_rpe the mean drift and rotation per length. Nested details (alignment
  /// matrices, map details, per-length statistics) stay in result.json: a sweep of 10,000 runs is not held in
  /// memory twice over.
  nlohmann::json metric_details = nlohmann::json::object();
  nlohmann::json run_spec = nlohmann::json::object();  ///< run.json as recorded (the resolved configuration)
  /// Scans per second of the log the program got (ScanRateOfResult); absent for runs recorded before the worker
  /// counted them. The report takes the densest of several logs of one physical run.
  std::optional<double> scan_rate_hz;
  /// result.json's sequence.scan_spacing block as recorded (null when absent): how far apart the input's scans were.
  nlohmann::json scan_spacing;
  std::vector<std::string> warnings;

  /// From the database: result.json as the store keeps it (ResultsStore::RecordRun), the id of the sweep that
  /// recorded the run, and the digest of the whole result.json (flags left out) that tells recordings apart.
  nlohmann::json result = nlohmann::json::object();
  std::int64_t sweep_id = 0;
  std::uint64_t result_digest = 0;

  /// The value of a flat metric, if the run has it with a value.
  std::optional<double> Metric(std::string_view metric, std::string_view statistic) const;
  /// The unit of a flat metric ("" if absent).
  std::string MetricUnit(std::string_view metric, std::string_view statistic) const;
};

/// (scans - 1) / span_s of result.json's "sequence" record; absent when it has neither or the span is not positive.
std::optional<double> ScanRateOfResult(const nlohmann::json& result);

/// The record's fields that result.json holds as plain values (failure_kind, reason, exit_code, signal, wall_s,
/// cpu_s, peak_rss_kb, started_at, finished_at, command, warnings, the scan rate), read leniently: a missing value, or
/// one of another type than the worker writes, is left empty. The store reads its records' result.json this way.
void ReadResultFields(const nlohmann::json& result, RunRecord& run);

}  // namespace slamsweep::orchestrator::inline run
