#include "orchestrator/service/sweep_lifecycle.h"

#include <set>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "orchestrator/matrix/run_id.h"
#include "orchestrator/sweep/sweep_steps.h"

namespace slamsweep::orchestrator::service {
namespace {

/// The results store's status of a sweep that ended in `state`, as `slamsweep run` records its sweeps: a
/// cancelled sweep is interrupted.
SweepStatus StoreSweepStatus(QueuedSweepState state) {
  if (state == QueuedSweepState::kCancelled) return SweepStatus::kInterrupted;
  return state == QueuedSweepState::kFailed ? SweepStatus::kFailed : SweepStatus::kOk;
}

}  // namespace

bool ActivateSweep(SweepTable& sweeps, SweepEntry& entry, const std::filesystem::path& data_dir) {
  SweepSettings settings;
  settings.name = entry.sweep.name;
  settings.output_dir = entry.sweep.result_dir;
  settings.config_path = entry.sweep.config_name;
  settings.config_sha = fmt::format("{:016x}", Fnv1a64(entry.sweep.config_text));
  settings.command_line =
      fmt::format("slamsweep submit {} (sweep {} of the service in {}, by {})", entry.sweep.config_name, entry.sweep.id,
                  data_dir.string(), entry.sweep.submitter);
  try {
    entry.lock = std::make_unique<OutputLock>(settings.output_dir);
    entry.store.emplace(ResultsStore::Open(settings.output_dir / "results.sqlite"));
    entry.store_sweep_id = entry.store->BeginSweep(SweepInfoFor(settings));
    std::vector<RunSpec> unfinished;
    for (const RunEntry& run : entry.runs) {
      if (IsUnfinished(run.view.state)) unfinished.push_back(run.spec);
    }
    SweepOutcome ignored;
    const std::vector<const RunSpec*> to_do =
        RunsStillToDo(unfinished, settings, *entry.store, entry.store_sweep_id, ignored);
    std::set<std::string> to_do_ids;
    for (const RunSpec* run : to_do) to_do_ids.insert(run->run_id);
    for (std::size_t i = 0; i < entry.runs.size(); ++i) {
      RunEntry& run = entry.runs[i];
      if (!IsUnfinished(run.view.state)) continue;
      if (to_do_ids.count(run.view.run_id) > 0) {
        entry.pending.push_back(i);
        continue;
      }
      const std::optional<RunRecord> stored = entry.store->FindRun(run.view.run_id);
      const QueuedRunState state =
          stored && stored->status == RunStatus::kOk ? QueuedRunState::kOk : QueuedRunState::kFailed;
      sweeps.SetRunState(entry, i, state, false, stored ? stored->wall_s : std::nullopt,
                         stored ? stored->result.value("reason", "") : "");
    }
  } catch (const std::exception& error) {
    entry.lock.reset();
    entry.store.reset();
    FailSweep(sweeps, entry,
              fmt::format("cannot open the result directory {}: {}", settings.output_dir.string(), error.what()));
    return false;
  }
  sweeps.MarkStarted(entry);
  return true;
}

void FinishSweep(SweepTable& sweeps, SweepEntry& entry, QueuedSweepState state, const std::string& message) {
  std::set<std::string> matrix_ids;
  std::size_t ran = 0;
  for (const RunEntry& run : entry.runs) {
    if (run.view.state != QueuedRunState::kCancelled) matrix_ids.insert(run.view.run_id);
    ran += run.view.state == QueuedRunState::kOk || run.view.state == QueuedRunState::kFailed ? 1 : 0;
  }
  QueuedSweepState final_state = state;
  try {
    const std::size_t failed = WriteSweepOutputs(*entry.store, matrix_ids, entry.sweep.result_dir);
    if (final_state != QueuedSweepState::kCancelled) {
      final_state = failed > 0 ? QueuedSweepState::kFailed : QueuedSweepState::kOk;
    }
    entry.store->FinishSweep(entry.store_sweep_id, StoreSweepStatus(final_state), static_cast<std::int64_t>(ran));
  } catch (const std::exception& error) {
    entry.store.reset();
    entry.lock.reset();
    FailSweep(sweeps, entry,
              fmt::format("cannot write the results into {}: {}", entry.sweep.result_dir.string(), error.what()));
    return;
  }
  entry.store.reset();
  entry.lock.reset();
  sweeps.RecordEnded(entry, final_state, message);
  spdlog::info("sweep {} '{}' finished: {}", entry.sweep.id, entry.sweep.name, ToString(final_state));
  sweeps.ShowEnded(entry, final_state, message, ReportState::kWriting);
}

void FailSweep(SweepTable& sweeps, SweepEntry& entry, const std::string& message) {
  spdlog::error("sweep {}: {}", entry.sweep.id, message);
  for (std::size_t i = 0; i < entry.runs.size(); ++i) {
    if (entry.runs[i].view.state == QueuedRunState::kQueued) {
      sweeps.SetRunState(entry, i, QueuedRunState::kCancelled, false, std::nullopt, message);
    }
  }
  entry.pending.clear();
  sweeps.RecordEnded(entry, QueuedSweepState::kFailed, message);
  sweeps.ShowEnded(entry, QueuedSweepState::kFailed, message, ReportState::kFailed);
}

}  // namespace slamsweep::orchestrator::service
