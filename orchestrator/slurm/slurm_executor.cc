#include "orchestrator/slurm/slurm_executor.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <thread>
#include <utility>

#include "orchestrator/process/interruption.h"
#include "orchestrator/process/wake_up.h"
#include "orchestrator/slurm/array_job.h"
#include "orchestrator/slurm/slurm_command.h"
#include "orchestrator/slurm/slurm_states.h"
#include "orchestrator/sweep/local_executor.h"

namespace slamsweep::orchestrator::inline slurm {
namespace {

namespace fs = std::filesystem;

/// Consecutive failed state queries after which the runs of a job are given up.
constexpr int kMaxFailedQueries = 12;
/// Consecutive answers that no longer list a task after which it counts as ended (its record expired).
constexpr int kMaxMissingPolls = 3;
/// How long TerminateAll waits for cancelled tasks to end (Slurm's KillWait is 30 s by default).
constexpr auto kCancelWait = std::chrono::seconds(90);

struct QueuedRun {
  std::string run_id;
  fs::path run_dir;
  double timeout_s = 0;
  std::uint64_t memory_limit_mb = 0;
};

struct SubmittedJob {
  std::string job_id;
  /// Task id -> run id, for tasks whose ending was not returned yet.
  std::map<int, std::string> tasks;
  std::map<int, int> missing_polls;
  /// Tasks ended by Stop(): their CANCELLED state is an interruption, not a failure.
  std::set<int> cancelled_tasks;
  int failed_queries = 0;
};

class SlurmExecutor final : public Executor {
 public:
  explicit SlurmExecutor(SlurmOptions options) : options_(std::move(options)) {
    options_.worker_program = fs::absolute(options_.worker_program);
  }

  void Start(const RunSpec& run, const fs::path& run_dir) override {
    queued_.push_back({run.run_id, fs::absolute(run_dir), run.algorithm.timeout_s, run.algorithm.memory_limit_mb});
  }

  std::vector<WorkerEnding> Wait() override {
    if (!queued_.empty()) Submit();
    for (;;) {
      if (!ready_.empty()) return std::exchange(ready_, {});
      if (TasksLeft() == 0 || Interrupted()) return {};
      for (SubmittedJob& job : jobs_) Poll(job);
      if (!ready_.empty()) return std::exchange(ready_, {});
      // Woken by a signal (the InterruptionGuard keeps them blocked outside this wait, so none is lost
      // between the check above and the sleep) or by another thread's RequestWakeUp().
      SleepUnlessWoken(options_.poll_interval_s);
      if (TakeWakeUpRequest()) return std::exchange(ready_, {});
    }
  }

  void Stop(const std::string& run_id) override {
    for (auto it = queued_.begin(); it != queued_.end(); ++it) {
      if (it->run_id != run_id) continue;
      ready_.push_back({run_id, true, "never submitted to Slurm (stopped by the supervisor)"});
      queued_.erase(it);
      return;
    }
    for (SubmittedJob& job : jobs_) {
      for (const auto& [task_id, task_run_id] : job.tasks) {
        if (task_run_id != run_id) continue;
        // Its final state (CANCELLED) is picked up by the next Poll and reported as interrupted.
        job.cancelled_tasks.insert(task_id);
        RunSlurmCommand({"scancel", job.job_id + "_" + std::to_string(task_id)});
        return;
      }
    }
  }

  std::vector<WorkerEnding> TerminateAll() override {
    cancelled_by_us_ = true;
    std::vector<WorkerEnding> endings = std::exchange(ready_, {});
    for (const QueuedRun& run : std::exchange(queued_, {})) {
      endings.push_back({run.run_id, true, "never submitted to Slurm (the sweep was interrupted)"});
    }
    for (const SubmittedJob& job : jobs_) {
      if (!job.tasks.empty()) RunSlurmCommand({"scancel", job.job_id});
    }
    // Wait until the tasks really ended: a worker still writing must not race the sweep's clean-up.
    const auto give_up = std::chrono::steady_clock::now() + kCancelWait;
    while (TasksLeft() > 0 && std::chrono::steady_clock::now() < give_up) {
      for (SubmittedJob& job : jobs_) Poll(job);
      if (TasksLeft() > 0) std::this_thread::sleep_for(std::chrono::milliseconds(500));
    }
    for (SubmittedJob& job : jobs_) {
      for (const auto& [task_id, run_id] : job.tasks) {
        ready_.push_back(
            {run_id, true,
             "Slurm task " + job.job_id + "_" + std::to_string(task_id) + " still running 90 s after scancel"});
      }
      job.tasks.clear();
    }
    for (WorkerEnding& ending : ready_) endings.push_back(std::move(ending));
    ready_.clear();
    return endings;
  }

  std::size_t Running() const override { return queued_.size() + ready_.size() + TasksLeft(); }

  bool Interrupted() const override { return InterruptionGuard::Interrupted(); }

 private:
  std::size_t TasksLeft() const {
    std::size_t left = 0;
    for (const SubmittedJob& job : jobs_) left += job.tasks.size();
    return left;
  }

  void FailQueued(const std::string& reason) {
    for (const QueuedRun& run : std::exchange(queued_, {})) ready_.push_back({run.run_id, false, reason});
  }

  /// Writes the manifest and the batch script, then submits one array for everything queued.
  void Submit() {
    const fs::path state_dir =
        options_.state_dir.empty() ? queued_.front().run_dir.parent_path().parent_path() / "slurm" : options_.state_dir;
    const std::string name = "array-" + std::to_string(::getpid()) + "-" + std::to_string(submissions_++);
    ArrayJobRequest request;
    request.job_name = "slamsweep";
    request.task_count = queued_.size();
    request.max_parallel = options_.max_parallel;
    request.partition = options_.partition;
    request.extra_args = options_.extra_sbatch_args;
    request.script_path = state_dir / (name + ".sh");
    request.slurm_output_pattern = state_dir / (name + "-%a.out");
    double longest_timeout_s = 0;
    std::uint64_t largest_memory_mb = 0;
    std::string manifest_text;
    for (const QueuedRun& run : queued_) {
      longest_timeout_s = std::max(longest_timeout_s, run.timeout_s);
      largest_memory_mb = std::max(largest_memory_mb, run.memory_limit_mb);
      manifest_text += run.run_dir.string() + "\n";
    }
    request.time_limit_min = TimeLimitMinutes(longest_timeout_s, LocalExecutor::kWorkerOverheadS);
    request.memory_mb = TaskMemoryMb(largest_memory_mb, options_.worker_memory_overhead_mb);
    for (const QueuedRun& run : queued_) {
      if (run.run_dir.string().find('\n') != std::string::npos) {
        return FailQueued("cannot submit to Slurm: a run folder path contains a newline");
      }
    }
    const fs::path manifest = state_dir / (name + ".runs");
    std::error_code error;
    fs::create_directories(state_dir, error);
    {
      std::ofstream(manifest) << manifest_text;
      std::ofstream(request.script_path) << BatchScript(options_.worker_program, manifest);
    }
    if (error || !fs::exists(manifest) || !fs::exists(request.script_path)) {
      return FailQueued("cannot write the Slurm batch script into " + state_dir.string());
    }
    ::chmod(request.script_path.c_str(), 0755);

    const CommandOutput submitted = RunSlurmCommand(SbatchArgv(request));
    const std::int64_t job_id = submitted.ok() ? ParseSbatchJobId(submitted.output) : -1;
    if (job_id < 0) {
      std::string said = submitted.output;
      while (!said.empty() && (said.back() == '\n' || said.back() == ' ')) said.pop_back();
      return FailQueued("sbatch failed (exit code " + std::to_string(submitted.exit_code) + "): " + said);
    }
    SubmittedJob job;
    job.job_id = std::to_string(job_id);
    for (std::size_t i = 0; i < queued_.size(); ++i) job.tasks[static_cast<int>(i)] = queued_[i].run_id;
    queued_.clear();
    jobs_.push_back(std::move(job));
  }

  /// Task states from scontrol (works without accounting); sacct once scontrol forgot the job.
  std::optional<std::vector<SlurmTaskState>> QueryStates(SubmittedJob& job, std::string& problem) {
    const CommandOutput shown = RunSlurmCommand({"scontrol", "show", "job", "-o", job.job_id});
    if (shown.ok()) return ParseScontrolJobs(shown.output);
    const CommandOutput accounted =
        RunSlurmCommand({"sacct", "-j", job.job_id, "--array", "-n", "-P", "-o", "JobID,State,ExitCode"});
    if (accounted.ok()) {
      std::vector<SlurmTaskState> states = ParseSacct(accounted.output);
      if (!states.empty()) return states;
    }
    if (shown.output.find("Invalid job id") != std::string::npos) return std::vector<SlurmTaskState>{};
    problem = shown.output;
    return std::nullopt;
  }

  void Poll(SubmittedJob& job) {
    if (job.tasks.empty()) return;
    std::string problem;
    const std::optional<std::vector<SlurmTaskState>> states = QueryStates(job, problem);
    if (!states) {
      if (++job.failed_queries < kMaxFailedQueries) return;
      while (!problem.empty() && problem.back() == '\n') problem.pop_back();
      EndAll(job, "cannot query Slurm about job " + job.job_id + ": " + problem);
      return;
    }
    job.failed_queries = 0;
    std::map<int, const SlurmTaskState*> by_task;
    for (const SlurmTaskState& state : *states) by_task[state.task_id] = &state;
    for (auto it = job.tasks.begin(); it != job.tasks.end();) {
      const auto found = by_task.find(it->first);
      if (found == by_task.end()) {
        // No accounting and the record expired (or the controller lost the job): the state is gone.
        if (++job.missing_polls[it->first] >= kMaxMissingPolls) {
          ready_.push_back({it->second, cancelled_by_us_ || job.cancelled_tasks.count(it->first) > 0,
                            "Slurm no longer lists task " + job.job_id + "_" + std::to_string(it->first) +
                                " (its record expired; final state unknown)"});
          it = job.tasks.erase(it);
        } else {
          ++it;
        }
        continue;
      }
      job.missing_polls.erase(it->first);
      if (!IsFinalState(found->second->state)) {
        ++it;
        continue;
      }
      const SlurmTaskEnding ending =
          EndingForState(*found->second, cancelled_by_us_ || job.cancelled_tasks.count(it->first) > 0);
      ready_.push_back({it->second, ending.interrupted, ending.reason});
      it = job.tasks.erase(it);
    }
  }

  void EndAll(SubmittedJob& job, const std::string& reason) {
    for (const auto& [task_id, run_id] : job.tasks) ready_.push_back({run_id, cancelled_by_us_, reason});
    job.tasks.clear();
  }

  SlurmOptions options_;
  std::vector<QueuedRun> queued_;
  std::vector<SubmittedJob> jobs_;
  std::vector<WorkerEnding> ready_;
  std::size_t submissions_ = 0;
  bool cancelled_by_us_ = false;
};

}  // namespace

std::unique_ptr<Executor> MakeSlurmExecutor(const SlurmOptions& options) {
  return std::make_unique<SlurmExecutor>(options);
}

}  // namespace slamsweep::orchestrator::inline slurm
