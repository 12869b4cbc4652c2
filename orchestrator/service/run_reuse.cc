#include "orchestrator/service/run_reuse.h"

#include <spdlog/spdlog.h>

#include "orchestrator/run/run_folder.h"
#include "orchestrator/sweep/sweep_runner.h"

namespace slamsweep::orchestrator::service {

std::optional<nlohmann::json> ReusableResult(const RunSpec& run, const std::filesystem::path& source_result_dir) {
  const std::filesystem::path folder = RunFolder(source_result_dir, run.run_id);
  StoredResult stored = ReadRunResult(folder);
  const std::optional<nlohmann::json> spec = ReadRunSpecJson(folder);
  if (!stored.result || !spec || stored.result->value("run_id", "") != run.run_id) return std::nullopt;
  if (spec->value("run_id", "") != run.run_id) return std::nullopt;
  SweepSettings strict;  // no --rerun failed, no --reuse-stale: only an ok run of the same build counts
  bool stale = false;
  const std::optional<RunStatus> status = StatusOfResultJson(*stored.result);
  if (status != RunStatus::kOk || !RecordedRunIsReusable(run, status, *spec, strict, stale)) return std::nullopt;
  const auto evaluation = spec->find("evaluation");
  if (evaluation == spec->end() || *evaluation != ToJson(run).at("evaluation")) return std::nullopt;
  return std::move(stored.result);
}

void LinkRunFolder(const RunSpec& run, const std::filesystem::path& source_result_dir,
                   const std::filesystem::path& target_result_dir) {
  namespace fs = std::filesystem;
  const fs::path from = RunFolder(source_result_dir, run.run_id);
  const fs::path to = RunFolder(target_result_dir, run.run_id);
  RemovePartialRun(to);
  try {
    fs::create_directories(to);
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(from)) {
      const fs::path target = to / fs::relative(entry.path(), from);
      if (entry.is_symlink()) {
        fs::copy_symlink(entry.path(), target);  // as the program left it; never followed
      } else if (entry.is_directory()) {
        fs::create_directories(target);
      } else if (entry.is_regular_file()) {
        std::error_code link_error;
        fs::create_hard_link(entry.path(), target, link_error);
        if (link_error) fs::copy_file(entry.path(), target);
      }
    }
    // A fresh file (temporary + rename), so the source sweep's run.json stays as it was.
    WriteJsonAtomically(to / "run.json", ToJson(run));
  } catch (...) {
    RemovePartialRun(to);
    throw;
  }
}

bool ReuseIdenticalRun(SweepTable& sweeps, SweepEntry& entry, std::size_t index, ServiceMetrics& metrics) {
  RunEntry& run = entry.runs[index];
  for (const std::int64_t source_id : sweeps.SweepsWithOkRun(run.view.run_id, entry.sweep.id)) {
    const std::optional<std::filesystem::path> source_dir = sweeps.ResultDir(source_id);
    if (!source_dir) continue;
    try {
      const std::optional<nlohmann::json> result = ReusableResult(run.spec, *source_dir);
      if (!result) continue;
      LinkRunFolder(run.spec, *source_dir, entry.sweep.result_dir);
      entry.store->RecordRun(entry.store_sweep_id, ToJson(run.spec), *result,
                             std::filesystem::path("runs") / run.view.run_id);
      std::optional<double> wall_s;
      if (result->contains("wall_s") && (*result)["wall_s"].is_number()) wall_s = (*result)["wall_s"].get<double>();
      sweeps.SetRunState(entry, index, QueuedRunState::kReused, false, wall_s, "", source_id);
      metrics.RunFinished(QueuedRunState::kReused, 0.0, false);
      spdlog::info("sweep {}: {} reused from sweep {}", entry.sweep.id, run.view.run_id, source_id);
      return true;
    } catch (const std::exception& error) {
      spdlog::warn("sweep {}: {} not reused from sweep {}: {}", entry.sweep.id, run.view.run_id, source_id,
                   error.what());
    }
  }
  return false;
}

}  // namespace slamsweep::orchestrator::service
