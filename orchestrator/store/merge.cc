#include "orchestrator/store/merge.h"

#include <map>
#include <optional>
#include <set>
#include <system_error>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/phase_times/phase_times.h"
#include "orchestrator/store/group_summary.h"
#include "orchestrator/store/result_files.h"
#include "orchestrator/store/results_store.h"

namespace slamsweep::orchestrator::inline store {
namespace {

namespace fs = std::filesystem;
using evaluator::InputError;

constexpr const char* kStoreName = "results.sqlite";

// Run ids are built from [A-Za-z0-9_.-] (DESIGN.md); anything else could point outside out/runs/.
bool IsSafeRunId(const std::string& run_id) {
  if (run_id.empty() || run_id == "." || run_id == "..") return false;
  for (const char c : run_id) {
    const bool allowed =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.' || c == '-';
    if (!allowed) return false;
  }
  return true;
}

bool IsSafeRelative(const fs::path& path) {
  if (path.empty() || path.is_absolute()) return false;
  for (const fs::path& part : path) {
    if (part == "..") return false;
  }
  return true;
}

void Check(const std::error_code& error, const std::string& doing) {
  if (error) throw InputError(fmt::format("{}: {}", doing, error.message()));
}

// Hard links share the bytes of immutable run outputs between shards and the merge (files in a run folder are
// only ever replaced by rename, never rewritten in place); a copy is the fallback across file systems.
void LinkOrCopyTree(const fs::path& from, const fs::path& to) {
  std::error_code error;
  fs::create_directories(to, error);
  Check(error, fmt::format("{}: cannot create folder", to.string()));
  for (fs::recursive_directory_iterator it(from, error), end; it != end; it.increment(error)) {
    Check(error, fmt::format("{}: cannot list folder", from.string()));
    // The iterator names every entry as `from` / its relative path: no need to resolve either on disk.
    const fs::path target = to / it->path().lexically_relative(from);
    if (it->is_symlink()) {
      fs::copy_symlink(it->path(), target, error);
    } else if (it->is_directory()) {
      fs::create_directories(target, error);
    } else {
      fs::create_hard_link(it->path(), target, error);
      if (error) {
        error.clear();
        fs::copy_file(it->path(), target, fs::copy_options::overwrite_existing, error);
      }
    }
    Check(error, fmt::format("{}: cannot copy to {}", it->path().string(), target.string()));
  }
  Check(error, fmt::format("{}: cannot list folder", from.string()));
}

// Builds the folder beside its final place and renames it in, so out/runs/<id> is never half there.
void PlaceRunFolder(const fs::path& from, const fs::path& to) {
  const fs::path staging = to.parent_path() / fmt::format(".{}.merging", to.filename().string());
  std::error_code error;
  fs::remove_all(staging, error);
  LinkOrCopyTree(from, staging);
  fs::remove_all(to, error);
  Check(error, fmt::format("{}: cannot replace folder", to.string()));
  fs::rename(staging, to, error);
  Check(error, fmt::format("{}: cannot move into place", to.string()));
}

class Merger {
 public:
  Merger(const fs::path& out, MergeReport& report)
      : out_(out),
        store_(ResultsStore::Open(out / kStoreName)),
        report_(report),
        recorded_(store_.RecordedIdentities()) {}

  void MergeInput(const fs::path& input) {
    ResultsStore in = ResultsStore::OpenExisting(input / kStoreName);
    std::map<std::int64_t, std::int64_t> sweep_ids;
    for (const StoredSweep& sweep : in.Sweeps()) sweep_ids[sweep.id] = store_.ImportSweep(sweep);
    // One commit per input: every run folder is in place before the index that lists it is committed.
    store_.BeginBatch();
    for (const RunRecord& run : in.Runs()) MergeRun(input, run, sweep_ids[run.sweep_id]);
    store_.CommitBatch();
  }

  void WriteReports() {
    const PhaseTimer phase("summary");
    const std::vector<RunRecord> runs = store_.Runs();
    // Shards built apart, or a rerun under a new build: their runs must never share a mean.
    std::set<std::string> split;
    for (const GroupSummary& group : SummarizeGroups(runs)) {
      if (group.build_split) {
        split.insert(fmt::format("{} on {} ({})", AlgorithmLabel(group.group.algorithm, group.group.parameters),
                                 group.group.sequence, group.group.noise));
      }
    }
    if (!split.empty()) {
      report_.warnings.push_back(fmt::format(
          "{} comparison group(s) hold runs computed by different builds (slamsweep revision or program digests): "
          "kept apart as separate groups marked build_split: {}",
          split.size(), fmt::join(split, "; ")));
    }
    WriteResultFiles(runs, out_);
  }

 private:
  void MergeRun(const fs::path& input, const RunRecord& run, std::int64_t sweep_id) {
    if (!IsSafeRunId(run.run_id)) {
      report_.warnings.push_back(fmt::format("{}: run id \"{}\" is not a slamsweep run id; skipped",
                                             (input / kStoreName).string(), run.run_id));
      return;
    }
    std::string run_dir = run.run_dir;
    if (!IsSafeRelative(run_dir)) {
      const std::string fallback = "runs/" + run.run_id;
      report_.warnings.push_back(fmt::format("{}: run {}: run_dir \"{}\" is not inside the output folder; using {}",
                                             (input / kStoreName).string(), run.run_id, run_dir, fallback));
      run_dir = fallback;
    }
    const auto found = recorded_.find(run.run_id);
    if (found == recorded_.end()) {
      Take(input, run, run_dir, sweep_id);
      ++report_.runs_added;
      return;
    }
    // A copy: taking the incoming run below replaces the entry.
    const ResultsStore::RecordedIdentity existing = found->second;
    if (existing.result_digest == run.result_digest && existing.flags == run.flags) {
      ++report_.duplicates;
      // The store may know the run while its folder was lost (an interrupted earlier merge).
      if (!fs::exists(out_ / existing.run_dir) && fs::exists(input / run_dir)) {
        PlaceRunFolder(input / run_dir, out_ / existing.run_dir);
      }
      return;
    }
    const std::string kept_from = Origin(run.run_id);
    const bool incoming_newer = run.finished_at > existing.finished_at;
    if (incoming_newer) Take(input, run, run_dir, sweep_id);
    report_.conflicts.push_back(fmt::format(
        "run {}: different results in {} (finished_at {}) and {} (finished_at {}); kept the newer one from {}",
        run.run_id, kept_from, existing.finished_at.empty() ? "unknown" : existing.finished_at, input.string(),
        run.finished_at.empty() ? "unknown" : run.finished_at, incoming_newer ? input.string() : kept_from));
  }

  void Take(const fs::path& input, const RunRecord& run, const std::string& run_dir, std::int64_t sweep_id) {
    if (fs::exists(input / run_dir)) {
      PlaceRunFolder(input / run_dir, out_ / run_dir);
    } else {
      report_.warnings.push_back(
          fmt::format("run {}: folder {} is missing; recorded without it", run.run_id, (input / run_dir).string()));
    }
    // The folder first, then the index: a recorded run always has its files.
    store_.ImportRun(sweep_id, run, run_dir);
    recorded_[run.run_id] = {run.result_digest, run.flags, run.finished_at, run_dir};
    origin_[run.run_id] = input.string();
  }

  std::string Origin(const std::string& run_id) const {
    const auto it = origin_.find(run_id);
    return it != origin_.end() ? it->second : out_.string();
  }

  fs::path out_;
  ResultsStore store_;
  MergeReport& report_;
  /// Every run the merged store holds, kept up to date as runs are taken.
  std::map<std::string, ResultsStore::RecordedIdentity> recorded_;
  std::map<std::string, std::string> origin_;
};

}  // namespace

MergeReport MergeResultDirs(const std::vector<fs::path>& inputs, const fs::path& out) {
  // Every input is checked before out is touched, so a typo in the last path leaves nothing half merged.
  for (const fs::path& input : inputs) {
    if (!fs::is_regular_file(input / kStoreName)) {
      throw InputError(fmt::format("{}: missing; expected a slamsweep output directory holding {}",
                                   (input / kStoreName).string(), kStoreName));
    }
    std::error_code error;
    if (fs::equivalent(input, out, error)) {
      throw InputError(
          fmt::format("{}: is the merge output itself; give a different output directory", input.string()));
    }
  }
  std::error_code error;
  fs::create_directories(out / "runs", error);
  Check(error, fmt::format("{}: cannot create folder", (out / "runs").string()));
  MergeReport report;
  Merger merger(out, report);
  {
    const PhaseTimer phase("merge_runs");
    for (const fs::path& input : inputs) merger.MergeInput(input);
  }
  merger.WriteReports();
  FlushPhaseTimes("merge");
  return report;
}

}  // namespace slamsweep::orchestrator::inline store
