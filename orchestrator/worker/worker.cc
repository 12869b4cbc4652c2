#include "orchestrator/worker/worker.h"

#include <signal.h>
#include <sys/prctl.h>

#include <fmt/format.h>

#include <chrono>
#include <exception>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>

#include "evaluator/core/input_error.h"
#include "orchestrator/adapters/adapter.h"
#include "orchestrator/run/run_failure.h"
#include "orchestrator/adapters/run_inputs.h"
#include "orchestrator/input_cache/prepared_sequence_cache.h"
#include "orchestrator/adapters/run_paths.h"
#include "orchestrator/run/run_json.h"
#include "orchestrator/phase_times/phase_times.h"
#include "orchestrator/process/interruption.h"
#include "orchestrator/process/process_set.h"
#include "orchestrator/reference_map/reference_map.h"
#include "orchestrator/process/outcome_reason.h"
#include "orchestrator/sandbox/pids_cgroup.h"
#include "orchestrator/sandbox/proc_choice.h"
#include "orchestrator/sandbox/sandbox_availability.h"
#include "orchestrator/worker/program_sandbox.h"
#include "orchestrator/worker/raw_folder.h"
#include "orchestrator/worker/run_metrics.h"
#include "orchestrator/worker/run_outputs.h"
#include "orchestrator/worker/run_result.h"

namespace slamsweep::orchestrator::inline worker {

namespace ev = slamsweep::evaluator;
namespace fs = std::filesystem;

namespace {

constexpr std::uint64_t kLogCapBytes = 8ull << 20;

/// The run's specification; InputError naming run.json (and the field) when it cannot be used.
RunSpec ReadRunSpec(const RunPaths& paths) {
  std::ifstream in(paths.RunJson(), std::ios::binary);
  if (!in) throw ev::InputError(paths.RunJson().string() + ": cannot read the run's specification");
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& error) {
    throw ev::InputError(paths.RunJson().string() + ": not JSON (" + error.what() + ")");
  }
  try {
    return RunSpecFromJson(json);
  } catch (const ev::InputError& error) {
    // RunSpecFromJson names the file "run.json"; the full path says which run.
    std::string message = error.what();
    if (message.starts_with("run.json: ")) message.erase(0, std::string("run.json: ").size());
    throw ev::InputError(paths.RunJson().string() + ": " + message);
  } catch (const nlohmann::json::exception& error) {
    throw ev::InputError(paths.RunJson().string() + ": " + error.what());
  }
}

/// Everything in the run folder but run.json and worker.log: what an earlier attempt left would
/// otherwise be taken for this attempt's output (a stale map when the program now writes none).
/// worker.log is this worker's own stdout/stderr, held open by the supervisor that started it.
void RemoveAllButRunJson(const RunPaths& paths) {
  std::error_code error;
  for (fs::directory_iterator it(paths.root, error), end; !error && it != end; it.increment(error)) {
    const fs::path name = it->path().filename();
    if (name == paths.RunJson().filename() || name == "worker.log") continue;
    std::error_code ignored;
    fs::remove_all(it->path(), ignored);
  }
}

/// A termination request that arrived while signals were blocked (InterruptionGuard takes them only
/// while waiting for the program) counts as well: the worker must not commit a result after it.
bool InterruptionRequested() {
  if (InterruptionGuard::Interrupted()) return true;
  sigset_t pending;
  sigemptyset(&pending);
  if (sigpending(&pending) != 0) return false;
  return sigismember(&pending, SIGINT) == 1 || sigismember(&pending, SIGTERM) == 1 ||
         sigismember(&pending, SIGHUP) == 1;
}

void WriteCommandTxt(const RunPaths& paths, const std::vector<std::string>& argv) {
  std::ofstream out(paths.CommandTxt(), std::ios::binary | std::ios::trunc);
  for (const std::string& argument : argv) out << argument << "\n";
  if (!out) throw std::runtime_error(paths.CommandTxt().string() + ": cannot write");
}

/// Records how the program ended; returns false when the run cannot go on.
bool RecordProcessOutcome(const ProcessOutcome& outcome, RunResult& result) {
  result.wall_s = outcome.wall_s;
  result.cpu_s = outcome.cpu_s;
  result.peak_rss_kb = outcome.peak_rss_kb;
  if (outcome.exit_code >= 0) result.exit_code = outcome.exit_code;
  if (outcome.signal > 0) result.signal = outcome.signal;
  if (outcome.log_truncated) result.warnings.push_back("log.txt truncated: the middle of the output was left out");
  switch (outcome.ending) {
    case ProcessEnding::kExited:
      if (outcome.exit_code != 0) result.Fail(FailureKind::kExitCode, outcome.reason);
      break;
    case ProcessEnding::kSignaled:
      result.Fail(FailureKind::kSignal, outcome.reason);
      break;
    case ProcessEnding::kTimedOut:
      result.Fail(FailureKind::kTimeout, outcome.reason);
      break;
    case ProcessEnding::kMemoryLimit:
      result.Fail(FailureKind::kMemoryLimit, outcome.reason);
      break;
    case ProcessEnding::kProcessLimit:
      result.Fail(FailureKind::kProcessLimit, outcome.reason);
      break;
    case ProcessEnding::kInterrupted:
      result.Fail(FailureKind::kInterrupted, outcome.reason);
      break;
    case ProcessEnding::kFailedToStart:
      // The configuration names a program this machine cannot run.
      result.Fail(FailureKind::kInputError, outcome.reason);
      break;
  }
  return result.ok();
}

/// "the program cannot be isolated here (...)": a failed run, unless the sweep allows unisolated runs.
void RequireIsolationOrAllowed(const RunSpec& spec, const std::string& why) {
  if (spec.allow_unisolated) return;
  throw RunFailure(FailureKind::kNotIsolated,
                   "the program cannot be isolated here (" + why +
                       "); --allow-unisolated runs it without a sandbox, its result marked unisolated");
}

/// result.json's "sandbox": how the program was isolated.
nlohmann::json SandboxRecord(const SandboxSpec& sandbox, const SandboxProcChoice& proc) {
  nlohmann::json record = {{"isolated", true},
                           {"proc", proc.fresh_proc ? "own" : "none"},
                           {"nested_user_namespaces", proc.fresh_proc ? "refused by bubblewrap" : "refused by seccomp"},
                           {"user", sandbox.user ? "nobody" : "the worker's, in a user namespace of its own"},
                           {"process_limit_by", sandbox.pids_cgroup_procs.empty() ? "RLIMIT_NPROC" : "pids cgroup"},
                           {"network", sandbox.network}};
  if (!proc.fresh_proc) record["why"] = proc.why;
  return record;
}

/// Runs the program in its sandbox (or, where none can be made and the sweep allows it, without one)
/// and checks what it left in raw/. Returns false when the run cannot go on.
bool RunProgram(const RunSpec& spec, const RunPaths& paths, const Adapter& adapter, ProcessSpec& process,
                RunResult& result) {
  const SandboxPrograms& programs = FindSandboxPrograms();
  std::string unisolated = programs.missing;
  std::optional<ProcessOutcome> outcome;
  // Root counts the sandbox's processes in a pids cgroup of its own where it can make one.
  std::unique_ptr<PidsCgroup> cgroup;
  std::string no_cgroup;
  if (unisolated.empty() && ::geteuid() == 0) cgroup = PidsCgroup::Create(spec.algorithm.process_limit, no_cgroup);
  if (unisolated.empty()) {
    const SandboxProcChoice& proc = ChosenSandboxProc(programs.bwrap);
    process.sandbox = ProgramSandbox(spec, paths, adapter.ProgramReads(spec), process.argv.front(), programs,
                                     cgroup ? cgroup->ProcsFile() : fs::path(), proc.fresh_proc);
    result.sandbox = SandboxRecord(*process.sandbox, proc);
    if (!proc.fresh_proc) {
      result.warnings.push_back("the program's sandbox had no /proc (" + proc.why +
                                "); it was isolated as fully "
                                "otherwise, nested user namespaces refused by a seccomp filter");
    }
    outcome = RunProcess(process);
    if (outcome->sandbox_failed) unisolated = outcome->reason;
  }
  if (cgroup && outcome && !outcome->sandbox_failed && outcome->ending != ProcessEnding::kProcessLimit) {
    // Exact, where the sampling of the running sandbox may miss a program that gave up at once.
    if (const std::uint64_t refused = cgroup->Refusals(); refused > 0) {
      result.Fail(FailureKind::kProcessLimit,
                  fmt::format("{}: {} fork{} refused", ProcessLimitReason(spec.algorithm.process_limit), refused,
                              refused == 1 ? "" : "s"));
    }
  }
  if (!unisolated.empty()) {
    RequireIsolationOrAllowed(spec, unisolated);
    process.sandbox.reset();
    result.sandbox = {{"isolated", false}, {"why", unisolated}};
    result.flags.Set(RunFlag::kUnisolated);
    result.warnings.push_back(
        "unisolated: the program ran without a sandbox and could read every file this machine "
        "lets slamsweep read, the reference included (" +
        unisolated + ")");
    outcome = RunProcess(process);
  }
  const std::uint64_t disk_limit_bytes = spec.algorithm.disk_limit_mb << 20;
  if (process.sandbox && outcome->ending == ProcessEnding::kSignaled && outcome->signal == SIGXFSZ) {
    // RLIMIT_FSIZE's signal: the program wrote a file of disk_limit_mb.
    result.Fail(FailureKind::kDiskLimit, fmt::format("a file reached the disk limit of {} MB (disk_limit_mb): {}",
                                                     spec.algorithm.disk_limit_mb, outcome->reason));
  }
  if (!RecordProcessOutcome(*outcome, result)) return false;
  // Before anything in raw/ is read: no link may lead the worker out of it, no FIFO block it.
  const RawFolderCheck raw = CheckRawFolder(paths.RawDir(), process.sandbox ? disk_limit_bytes : 0);
  for (const std::string& removed : raw.removed) {
    result.warnings.push_back("removed " + removed + " that the program left: outputs are plain files");
  }
  if (!raw.file_at_limit.empty()) {
    result.Fail(FailureKind::kDiskLimit, fmt::format("{} reached the disk limit of {} MB (disk_limit_mb)",
                                                     raw.file_at_limit, spec.algorithm.disk_limit_mb));
    return false;
  }
  if (process.sandbox && raw.total_bytes > disk_limit_bytes) {
    result.Fail(FailureKind::kDiskLimit,
                fmt::format("raw/ holds {:.0f} MB, more than the disk limit of {} MB "
                            "(disk_limit_mb)",
                            static_cast<double>(raw.total_bytes) / (1 << 20), spec.algorithm.disk_limit_mb));
    return false;
  }
  return true;
}

/// Everything between a readable run.json and result.json. Failures of the run are thrown
/// (RunFailure, InputError) or recorded in `result`; the caller turns the rest into "internal".
void ExecuteRun(const RunSpec& spec, const RunPaths& paths, RunResult& result) {
  const std::unique_ptr<Adapter> adapter = MakeAdapter(spec.algorithm.adapter);
  std::optional<PhaseTimer> phase(std::in_place, "inputs");
  const RunInputs inputs = PrepareRunInputs(spec, PreparedInputCacheDir(paths.root));
  result.warnings.insert(result.warnings.end(), inputs.warnings.begin(), inputs.warnings.end());
  result.noise = inputs.noise_record;
  result.sequence = inputs.sequence_record;
  result.odometry_is_reference = inputs.odometry_is_reference;
  result.flags.Set(RunFlag::kOdometryIsReference, inputs.odometry_is_reference);
  if (inputs.odometry_is_reference) result.warnings.push_back(std::string(kOdometryIsReferenceWarning));
  // The adapter gets the robot's part only; inputs.truth stays here until the program has exited.
  phase.emplace("prepare");
  const PreparedRun prepared = adapter->Prepare(spec, inputs.robot, paths);
  result.command = prepared.argv;
  WriteCommandTxt(paths, prepared.argv);

  if (!prepared.argv.empty()) {
    ProcessSpec process;
    process.argv = prepared.argv;
    process.working_dir = paths.ProgramWorkingDir();
    // SLAMSWEEP_* variables name slamsweep's data folders (the datasets, whose logs hold the
    // reference): none of them is the program's business.
    process.removed_env_prefixes = {"SLAMSWEEP_"};
    process.log_path = paths.Log();
    process.log_cap_bytes = kLogCapBytes;
    process.timeout_s = spec.algorithm.timeout_s;
    process.memory_limit_mb = spec.algorithm.memory_limit_mb;
    phase.emplace("program");
    if (!RunProgram(spec, paths, *adapter, process, result)) return;
  }
  if (InterruptionRequested()) return;

  phase.emplace("collect");
  const auto collect_start = std::chrono::steady_clock::now();
  CollectedOutputs collected = adapter->Collect(spec, inputs.robot, paths);
  if (prepared.argv.empty()) {
    // No program: the baseline's "run" is rendering its map.
    result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - collect_start).count();
  }
  result.warnings.insert(result.warnings.end(), collected.warnings.begin(), collected.warnings.end());
  if (collected.map_rendered_from_trajectory) {
    result.warnings.push_back("map rendered from the trajectory and the scans (the program writes no map)");
  }
  const ev::Trajectory* reference = inputs.truth.reference ? &*inputs.truth.reference : nullptr;
  // The map-versus-reference scores count the cells of the map file the run folder keeps (as it reads back).
  phase.emplace("outputs");
  std::optional<ev::OccupancyGrid> written_map(std::in_place);
  try {
    result.outputs = WriteRunOutputs(paths, collected, reference, &*written_map);
  } catch (const ev::InputError& error) {
    throw RunFailure(FailureKind::kCorruptOutput, std::string("cannot convert the outputs: ") + error.what());
  }

  MetricInputs metric_inputs;
  metric_inputs.map = &collected.map;
  metric_inputs.written_map = &*written_map;
  metric_inputs.estimate = collected.trajectory ? &*collected.trajectory : nullptr;
  metric_inputs.reference = reference;
  metric_inputs.relations = inputs.truth.relations ? &*inputs.truth.relations : nullptr;
  metric_inputs.relations_outside_log = inputs.truth.relations_outside_log;
  metric_inputs.odometry =
      inputs.robot.odometry_readings.empty() ? &inputs.robot.odometry : &inputs.robot.odometry_readings;
  // The reference map is truth: read or rendered only now, after the program has exited, and
  // never into the run folder (orchestrator/reference_map: the catalog's file, or the clean scans
  // at the reference poses, cached per sequence beside runs/).
  phase.emplace("reference_map");
  std::optional<ReferenceMap> reference_map;
  try {
    reference_map = LoadReferenceMap(spec, reference != nullptr, ReferenceMapCacheDir(paths.root));
  } catch (const ev::InputError& error) {
    result.warnings.push_back(std::string("map_compare: no reference map: ") + error.what());
  }
  if (reference_map) {
    metric_inputs.reference_map = &reference_map->grid;
    metric_inputs.reference_map_record = reference_map->ToJson();
    if (!reference_map->cache_problem.empty()) {
      result.warnings.push_back("reference map not cached: " + reference_map->cache_problem);
    }
  }
  phase.emplace("metrics");
  result.metrics = ComputeRunMetrics(spec.evaluation, metric_inputs);
  RequireCoverage(spec.evaluation, result.metrics);
  phase.emplace("segments_csv");
  if (result.metrics.segment_errors) {
    // The report's boxplots need every segment; the metrics themselves are already in result.json.
    try {
      ev::WriteSegmentErrorsCsv(*result.metrics.segment_errors, paths.SegmentErrorsCsv());
      result.outputs["rpe_segments"] = paths.SegmentErrorsCsv().filename().string();
    } catch (const ev::InputError& error) {
      result.warnings.push_back(std::string("segment_rpe: ") + error.what());
    }
  }
}

}  // namespace

int RunWorker(const fs::path& run_dir) {
  // The supervisor's death must not leave a worker (and its SLAM program) running on.
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  const InterruptionGuard guard;

  std::error_code error;
  fs::path root = fs::absolute(run_dir, error).lexically_normal();
  if (root.filename().empty()) root = root.parent_path();  // "runs/r1/" -> "runs/r1"
  const RunPaths paths{root};
  RunSpec spec;
  try {
    spec = ReadRunSpec(paths);
  } catch (const std::exception& failure) {
    std::cerr << "slamsweep worker: " << failure.what() << "\n";
    return kWorkerBadRunJson;
  }

  {
    const PhaseTimer phase("clean");
    RemoveAllButRunJson(paths);
  }
  RunResult result;
  result.run_id = spec.run_id;
  result.started_at = NowIso8601Utc();
  try {
    ExecuteRun(spec, paths, result);
  } catch (const RunFailure& failure) {
    result.Fail(failure.kind(), failure.what());
  } catch (const ev::InputError& failure) {
    result.Fail(FailureKind::kInputError, failure.what());
  } catch (const std::exception& failure) {
    result.Fail(FailureKind::kInternal, std::string("worker error: ") + failure.what());
  } catch (...) {
    result.Fail(FailureKind::kInternal, "worker error: unknown exception");
  }

  if (InterruptionRequested() || result.failure_kind == FailureKind::kInterrupted) {
    // No result.json: the run is not done, and the next sweep starts it afresh.
    RemoveAllButRunJson(paths);
    return kWorkerInterrupted;
  }
  if (!result.ok()) result.metrics.metrics.clear();
  // A failed run's log is what a person reads first.
  if (!result.outputs.contains("log") && fs::is_regular_file(paths.Log(), error)) result.outputs["log"] = "log.txt";
  result.finished_at = NowIso8601Utc();
  try {
    const PhaseTimer phase("result");
    WriteJsonFileAtomically(paths.ResultJson(), ToJson(result));
  } catch (const std::exception& failure) {
    std::cerr << "slamsweep worker: " << failure.what() << "\n";
    return kWorkerBadRunJson;
  }
  FlushPhaseTimes("worker");
  return kWorkerWroteResult;
}

}  // namespace slamsweep::orchestrator::inline worker
