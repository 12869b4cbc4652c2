#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace slamsweep::orchestrator::inline history {

/// The identity of a series across nights: algorithm (with its parameters) x sequence x noise x odometry mode x
/// metric x statistic (and the unit its values carry): a comparison group and one of its metrics.
struct SeriesKey {
  /// AlgorithmLabel: the name, with "[k=v;...]" when the run has parameters (so every parameter setting of a
  /// parameter sweep is a series of its own).
  std::string algorithm;
  std::string sequence;
  std::string noise;
  /// "recorded" or "reference" (OdometryModeOfRunJson); "unknown" or "mixed" for series recorded before the
  /// history kept the mode (series_odometry.h), which are never compared.
  std::string odometry;
  std::string metric;
  std::string statistic;
  std::string unit;
};

/// Whether two keys name the same series (the unit follows from the metric).
bool SameSeries(const SeriesKey& a, const SeriesKey& b);

/// "<algorithm> / <sequence> / <noise> / <odometry> odometry: <metric>.<statistic>", for messages and tables.
std::string SeriesName(const SeriesKey& key);

/// One series of a sweep: the values of every ok run (one per iteration, in iteration order) — the
/// samples a regression test compares.
struct SampleSeries : SeriesKey {
  /// Finite values only; a run that reported null for this statistic is left out.
  std::vector<double> values;
};

/// The run counts of one comparison group (algorithm with parameters x sequence x noise x odometry mode).
struct CellCounts {
  /// AlgorithmLabel, as SeriesKey::algorithm.
  std::string algorithm;
  std::string sequence;
  std::string noise;
  /// As SeriesKey::odometry.
  std::string odometry;
  std::int64_t ok_runs = 0;
  std::int64_t failed_runs = 0;
};

/// One sweep as the history keeps it (a "night").
struct Night {
  /// Row id in the history database; 0 when the night was read from a result directory and not recorded.
  std::int64_t id = 0;
  std::string label;
  /// Absolute, normalised path of the sweep's output directory.
  std::filesystem::path result_dir;
  /// The last sweep id of the result directory's store: with result_dir, what makes a night unique.
  std::int64_t sweep_id = 0;
  std::string sweep_name;
  /// ISO 8601 UTC of the earliest sweep in the result directory.
  std::string started_at;
  /// RESULT_DIR/report/index.html (it may not exist: the sweep may have run with --no-report).
  std::filesystem::path report_index;
  /// Ordered by algorithm, sequence, noise, odometry, metric, statistic.
  std::vector<SampleSeries> series;
  std::vector<CellCounts> cells;
};

/// Reads a sweep's output directory (RESULT_DIR/results.sqlite, orchestrator/DESIGN.md) into a Night labelled
/// `label` (empty: the sweep's start date-time). Throws InputError naming the file when the directory has no
/// readable results database or no sweep in it.
Night ReadNight(const std::filesystem::path& result_dir, const std::string& label);

/// The series of `night` with this key (SameSeries), or null.
const SampleSeries* FindSeries(const Night& night, const SeriesKey& key);

}  // namespace slamsweep::orchestrator::inline history
