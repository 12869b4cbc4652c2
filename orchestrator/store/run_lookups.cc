#include "orchestrator/store/run_lookups.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "orchestrator/store/runs_table.h"

namespace slamsweep::orchestrator::inline store {
namespace {

// Median as evo and numpy define it: the mean of the middle two for an even count.
double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

std::map<std::string, RecordedRunIdentity> ReadRecordedIdentities(const SqliteDb& db) {
  std::map<std::string, RecordedRunIdentity> identities;
  auto select = db.Prepare("SELECT run_id, result_digest, flags, finished_at, run_dir FROM runs");
  while (select.Step()) {
    RecordedRunIdentity& identity = identities[select.Text(0)];
    identity.result_digest = static_cast<std::uint64_t>(select.Int64(1));
    identity.flags = RunFlagsFromText(select.TextOrEmpty(2), db.file().string() + ": runs.flags");
    identity.finished_at = select.TextOrEmpty(3);
    identity.run_dir = select.TextOrEmpty(4);
  }
  return identities;
}

std::optional<RunStatus> ReadRunStatus(const SqliteDb& db, const std::string& run_id) {
  auto select = db.Prepare("SELECT status FROM runs WHERE run_id = ?");
  select.Bind(1, run_id);
  if (!select.Step()) return std::nullopt;
  return StoredRunStatus(db.file(), run_id, select.Text(0));
}

bool AddToRunFlags(SqliteDb& db, const std::string& run_id, const RunFlags& added) {
  SqliteTransaction transaction(db);
  auto select = db.Prepare("SELECT flags FROM runs WHERE run_id = ?");
  select.Bind(1, run_id);
  if (!select.Step()) return false;
  RunFlags flags = RunFlagsFromText(select.TextOrEmpty(0), db.file().string() + ": runs.flags");
  flags |= added;
  auto update = db.Prepare("UPDATE runs SET flags = ? WHERE run_id = ?");
  update.Bind(1, RunFlagsText(flags)).Bind(2, run_id);
  update.Run();
  transaction.Commit();
  return true;
}

std::map<std::string, double> ReadTypicalWallSeconds(const SqliteDb& db) {
  auto select = db.Prepare("SELECT algorithm, sequence, wall_s FROM runs WHERE status = ? AND wall_s IS NOT NULL");
  select.Bind(1, RunStatusName(RunStatus::kOk));
  std::map<std::string, std::vector<double>> walls;
  while (select.Step()) {
    walls[TypicalWallKey(select.TextOrEmpty(0), select.TextOrEmpty(1))].push_back(select.Double(2));
  }
  std::map<std::string, double> typical;
  for (auto& [key, values] : walls) typical.emplace(key, Median(std::move(values)));
  return typical;
}

std::string TypicalWallKey(const std::string& algorithm, const std::string& sequence) {
  return algorithm + "\t" + sequence;
}

}  // namespace slamsweep::orchestrator::inline store
