#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "orchestrator/history/history_schema.h"
#include "orchestrator/history/night.h"
#include "orchestrator/store/sqlite_db.h"

namespace slamsweep::orchestrator::inline history {

/// A night without its samples (the history's table of contents).
struct NightEntry {
  std::int64_t id = 0;
  std::string label;
  std::filesystem::path result_dir;
  std::int64_t sweep_id = 0;
  std::string sweep_name;
  std::string started_at;
  std::string recorded_at;
  std::filesystem::path report_index;
};

/// One night's value of one series, for history plots: the samples and their summary.
struct HistoryPoint {
  NightEntry night;
  std::vector<double> values;
  std::int64_t failed_runs = 0;
};

/// The history database (its own SQLite file, e.g. /var/lib/slamsweep/history.sqlite): one row per recorded
/// sweep ("night") with the iteration samples of every algorithm x sequence x noise x odometry mode x metric x
/// statistic, so
/// that nights can be plotted and compared long after their output directories are gone.
class HistoryStore {
 public:
  /// Opens `file`, creating it (and its folder) when missing, migrating an older schema (history_schema.h). Throws
  /// InputError naming the file when it is not a slamsweep history database (e.g. a results.sqlite), is corrupt,
  /// or has a newer schema version.
  static HistoryStore Open(const std::filesystem::path& file);
  /// As Open, but a missing file is an InputError (for commands that only read).
  static HistoryStore OpenExisting(const std::filesystem::path& file);

  const std::filesystem::path& file() const { return db_.file(); }

  /// Appends `night` and returns its id, or returns the id of the night already recorded for the same result
  /// directory and sweep id (recording twice is a no-op). Throws InputError when another night has the label.
  struct RecordOutcome {
    std::int64_t id = 0;
    bool inserted = false;
  };
  RecordOutcome Record(const Night& night);

  /// Every night, in the order recorded.
  std::vector<NightEntry> Nights() const;
  /// The night with this label, or none.
  std::optional<NightEntry> FindByLabel(const std::string& label) const;
  /// The night recorded for this result directory (absolute, normalised) and sweep id, or none.
  std::optional<NightEntry> FindByKey(const std::filesystem::path& result_dir, std::int64_t sweep_id) const;
  /// Every distinct series of every night, ordered by algorithm, sequence, noise, odometry, metric, statistic
  /// (unit: the latest night's).
  std::vector<SeriesKey> SeriesKeys() const;
  /// A whole night with its samples and counts. Throws InputError for an unknown id.
  Night Load(std::int64_t night_id) const;
  /// One series across all nights in recorded order (nights without it are left out).
  std::vector<HistoryPoint> Series(const SeriesKey& key) const;

 private:
  explicit HistoryStore(SqliteDb db) : db_(std::move(db)) {}
  static HistoryStore OpenImpl(const std::filesystem::path& file, bool create);
  void InitializeSchema();
  std::vector<NightEntry> QueryNights(const std::string& where, const std::string& text, std::int64_t number) const;

  SqliteDb db_;
};

/// The night `--previous` compares `current` with: the last night recorded before it (when `current` is recorded,
/// else the last night recorded) that has a series in one of `current`'s odometry modes (a night in the other mode
/// would leave every series "not comparable"); none when there is no such night.
std::optional<NightEntry> PreviousNight(const HistoryStore& store, const Night& current);

}  // namespace slamsweep::orchestrator::inline history
