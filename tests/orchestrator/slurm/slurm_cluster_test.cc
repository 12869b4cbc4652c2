// The Slurm executor against a real one-node Slurm on localhost (jobs/slurm/local-cluster.sh):
// a small sweep through RunSweep as one job array, compared with the same runs on the local
// executor. Odometry runs are deterministic (seeded noise), so their metrics must be identical;
// fake programs that exit 3 or die of SIGSEGV must be recorded with those reasons, as locally.
// Skipped (failed under CI=true) when Slurm, munge or root rights are missing.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <pthread.h>
#include <signal.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "orchestrator/run/run_spec.h"
#include "orchestrator/process/interruption.h"
#include "orchestrator/slurm/slurm_command.h"
#include "orchestrator/slurm/slurm_executor.h"
#include "orchestrator/sweep/local_executor.h"
#include "orchestrator/sweep/status.h"
#include "orchestrator/sweep/sweep_runner.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const fs::path kCluster = fs::path(SLAMSWEEP_SOURCE_DIR) / "jobs" / "slurm" / "local-cluster.sh";

/// Why a local cluster cannot run here, or empty.
std::string MissingForCluster() {
  std::string missing;
  for (const char* program : {"/usr/sbin/munged", "/usr/sbin/slurmctld", "/usr/sbin/slurmd", "/usr/bin/sbatch",
                              "/usr/bin/scontrol", "/usr/bin/scancel"}) {
    if (!fs::exists(program)) missing += std::string(missing.empty() ? "" : ", ") + program;
  }
  if (!missing.empty()) return "missing " + missing + " (Debian packages slurm-wlm and munge)";
  if (::geteuid() != 0) return "the local Slurm cluster needs root (slurmd runs the jobs)";
  return "";
}

nlohmann::json ReadJson(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

/// A run on the catalog's simulated-floor sequence, cut to 40 scans.
RunSpec FloorRun(const std::string& run_id, const std::string& adapter, int iteration) {
  RunSpec spec;
  spec.run_id = run_id;
  spec.sweep = "slurm-test";
  spec.algorithm.name = run_id.substr(0, run_id.find('-'));
  spec.algorithm.adapter = adapter;
  spec.algorithm.timeout_s = 60;
  spec.sequence.entry.name = "simulated-floor";
  spec.sequence.entry.format = "simulated";
  spec.sequence.entry.ground_truth = evaluator::GroundTruthKind::kExact;
  spec.sequence.entry.simulation = {{"floor_plan", {{"seed", 1}}}, {"noise_seed", 1}};
  spec.sequence.max_scans = 40;
  spec.iteration = iteration;
  spec.seed = 1000 + static_cast<std::uint64_t>(iteration);
  spec.evaluation.stages = 4;
  spec.evaluation.rpe_delta_m = 0.2;
  return spec;
}

RunSpec FakeProgramRun(const std::string& run_id, const fs::path& program) {
  RunSpec spec = FloorRun(run_id, "command", 0);
  CommandDeclaration declaration;
  declaration.argv = {program.string(), "{output_dir}"};
  declaration.input_format = "tum";
  declaration.trajectory = DeclaredOutput{"trajectory.tum", "tum"};
  spec.algorithm.command = declaration;
  return spec;
}

fs::path WriteScript(const fs::path& path, const std::string& body) {
  std::ofstream(path) << "#!/bin/sh\n" << body << "\n";
  ::chmod(path.c_str(), 0755);
  return path;
}

class SlurmClusterTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (const std::string missing = MissingForCluster(); !missing.empty()) {
      if (slamsweep::testing::RunningInCi()) FAIL() << "CI=true but no local Slurm cluster possible: " << missing;
      GTEST_SKIP() << "no local Slurm cluster: " << missing;
    }
    // A port of our own, so that a second test process (ctest -j) or a cluster someone left running
    // does not answer in our place.
    const int port = 20000 + 2 * static_cast<int>(::getpid() % 10000);
    ::setenv("SLURM_LOCAL_PORT", std::to_string(port).c_str(), 1);
    ::setenv("SLURM_CONF", (state_ / "slurm.conf").c_str(), 1);
    const CommandOutput started = RunSlurmCommand({kCluster.string(), "start", state_.path().string()}, 90);
    started_ = true;
    ASSERT_TRUE(started.ok()) << "local-cluster.sh start failed:\n" << started.output;
  }

  void TearDown() override {
    if (!started_) return;
    const CommandOutput stopped = RunSlurmCommand({kCluster.string(), "stop", state_.path().string()}, 90);
    EXPECT_TRUE(stopped.ok()) << stopped.output;
  }

  SweepOutcome Sweep(const std::vector<RunSpec>& runs, const fs::path& out, Executor& executor) {
    SweepSettings settings;
    settings.name = "slurm-test";
    settings.output_dir = out;
    settings.jobs = runs.size();
    std::ostringstream log;
    const std::unique_ptr<Status> status = MakeStatus(log, false, runs.size());
    return RunSweep(runs, settings, executor, *status);
  }

  slamsweep::testing::TempDir state_;
  slamsweep::testing::TempDir work_;
  bool started_ = false;
};

std::map<std::string, nlohmann::json> RunsById(const fs::path& summary) {
  std::map<std::string, nlohmann::json> runs;
  const nlohmann::json whole = ReadJson(summary);  // kept alive: a temporary would dangle in the loop
  for (const nlohmann::json& run : whole["runs"]) runs[run["run_id"].get<std::string>()] = run;
  return runs;
}

TEST_F(SlurmClusterTest, AJobArrayGivesTheSameResultsAsTheLocalExecutor) {
  const fs::path exit3 = WriteScript(work_ / "exit3.sh", "echo 'giving up' >&2\nexit 3");
  const fs::path segv = WriteScript(work_ / "segv.sh", "kill -SEGV $$");
  std::vector<RunSpec> runs = {FloorRun("odometry-clean-0", "odometry", 0), FloorRun("odometry-noisy-0", "odometry", 0),
                               FloorRun("odometry-noisy-1", "odometry", 1), FakeProgramRun("exit3-0", exit3),
                               FakeProgramRun("segv-0", segv)};
  for (RunSpec& run : runs) {
    if (run.run_id.find("noisy") != std::string::npos) {
      run.noise.name = "noisy";
      run.noise.odometry = evaluator::OdometryNoise{0.01, 0.0, 0.01, 0.0, 0.0, 0.0};
    }
  }

  SlurmOptions options;
  options.worker_program = SLAMSWEEP_BINARY;
  options.poll_interval_s = 0.5;
  const std::unique_ptr<Executor> slurm = MakeSlurmExecutor(options);
  const SweepOutcome on_slurm = Sweep(runs, work_ / "slurm", *slurm);
  EXPECT_EQ(on_slurm.ok, 3u);
  EXPECT_EQ(on_slurm.failed, 2u);
  EXPECT_FALSE(on_slurm.interrupted);

  // It really went through Slurm: one array script, and the controller knows the finished tasks.
  std::size_t scripts = 0;
  for (const auto& entry : fs::directory_iterator(work_ / "slurm" / "slurm"))
    scripts += entry.path().extension() == ".sh";
  EXPECT_EQ(scripts, 1u);
  const CommandOutput queue = RunSlurmCommand({"squeue", "-h", "-t", "all", "-r", "-o", "%K %T"});
  ASSERT_TRUE(queue.ok()) << queue.output;
  EXPECT_EQ(std::count(queue.output.begin(), queue.output.end(), '\n'), 5) << queue.output;

  LocalExecutor local(SLAMSWEEP_BINARY);
  const SweepOutcome on_local = Sweep(runs, work_ / "local", local);
  EXPECT_EQ(on_local.ok, 3u);

  const auto slurm_runs = RunsById(work_ / "slurm" / "summary.json");
  const auto local_runs = RunsById(work_ / "local" / "summary.json");
  ASSERT_EQ(slurm_runs.size(), runs.size());
  for (const RunSpec& run : runs) {
    const nlohmann::json& a = slurm_runs.at(run.run_id);
    const nlohmann::json& b = local_runs.at(run.run_id);
    EXPECT_EQ(a["status"], b["status"]) << run.run_id;
    EXPECT_EQ(a["failure_kind"], b["failure_kind"]) << run.run_id;
    EXPECT_EQ(a["metrics"], b["metrics"]) << run.run_id << ": deterministic runs must score identically";
    EXPECT_TRUE(fs::exists(work_ / "slurm" / "runs" / run.run_id / "worker.log")) << run.run_id;
  }
  EXPECT_EQ(slurm_runs.at("odometry-clean-0")["status"], "ok");
  EXPECT_GT(slurm_runs.at("odometry-noisy-1")["metrics"]["ape_trans"]["rmse"].get<double>(), 0.0);
  EXPECT_NE(slurm_runs.at("odometry-noisy-0")["metrics"]["ape_trans"]["rmse"],
            slurm_runs.at("odometry-noisy-1")["metrics"]["ape_trans"]["rmse"])
      << "different seeds, different noise";
  EXPECT_EQ(slurm_runs.at("exit3-0")["failure_kind"], "exit_code");
  EXPECT_EQ(slurm_runs.at("exit3-0")["exit_code"], 3);
  EXPECT_EQ(slurm_runs.at("segv-0")["failure_kind"], "signal");
  EXPECT_THAT(slurm_runs.at("segv-0")["reason"].get<std::string>(), HasSubstr("SIGSEGV"));
}

TEST_F(SlurmClusterTest, AWorkerThatCannotRunIsRecordedWithSlurmsStateAndTheSweepGoesOn) {
  // A "worker" that fails before writing result.json: the run record must carry Slurm's verdict.
  const fs::path broken = WriteScript(work_ / "broken-worker.sh", "exit 7");
  SlurmOptions options;
  options.worker_program = broken;
  options.poll_interval_s = 0.5;
  const std::unique_ptr<Executor> slurm = MakeSlurmExecutor(options);
  const SweepOutcome outcome = Sweep({FloorRun("odometry-clean-0", "odometry", 0)}, work_ / "broken", *slurm);
  EXPECT_EQ(outcome.failed, 1u);
  const auto runs = RunsById(work_ / "broken" / "summary.json");
  EXPECT_THAT(runs.at("odometry-clean-0")["reason"].get<std::string>(), HasSubstr("Slurm FAILED: worker exit code 7"));
}

TEST_F(SlurmClusterTest, ARejectedSubmissionFailsTheRunsNotTheSweep) {
  SlurmOptions options;
  options.worker_program = SLAMSWEEP_BINARY;
  options.partition = "no-such-partition";
  const std::unique_ptr<Executor> slurm = MakeSlurmExecutor(options);
  const SweepOutcome outcome = Sweep({FloorRun("odometry-clean-0", "odometry", 0)}, work_ / "rejected", *slurm);
  EXPECT_EQ(outcome.failed, 1u);
  const auto runs = RunsById(work_ / "rejected" / "summary.json");
  const std::string reason = runs.at("odometry-clean-0")["reason"].get<std::string>();
  EXPECT_THAT(reason, HasSubstr("sbatch failed"));
  EXPECT_THAT(reason, HasSubstr("partition"));
}

TEST_F(SlurmClusterTest, AnInterruptedSweepCancelsItsJobAndLeavesNoHalfRuns) {
  const fs::path sleeper = WriteScript(work_ / "sleep.sh", "sleep 120");
  SlurmOptions options;
  options.worker_program = SLAMSWEEP_BINARY;
  options.poll_interval_s = 0.5;
  const std::unique_ptr<Executor> slurm = MakeSlurmExecutor(options);
  SweepOutcome outcome;
  const auto began = std::chrono::steady_clock::now();
  {
    InterruptionGuard guard;
    const pthread_t sweeping = ::pthread_self();
    // Ctrl-C once the job is in Slurm's queue (a fixed delay raced the submission on a loaded
    // machine); the signal stays pending until the executor waits, as in slamsweep.
    std::thread interrupter([sweeping] {
      const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
      while (std::chrono::steady_clock::now() < give_up) {
        const CommandOutput queue = RunSlurmCommand({"squeue", "-h", "-o", "%T"});
        if (queue.ok() && (queue.output.find("RUNNING") != std::string::npos)) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
      }
      ::pthread_kill(sweeping, SIGINT);
    });
    outcome = Sweep({FakeProgramRun("sleeper-0", sleeper)}, work_ / "interrupted", *slurm);
    interrupter.join();
  }
  EXPECT_TRUE(outcome.interrupted);
  EXPECT_EQ(outcome.ExitCode(), 130);
  EXPECT_LT(std::chrono::steady_clock::now() - began, std::chrono::seconds(60)) << "scancel, not the 120 s sleep";
  EXPECT_FALSE(fs::exists(work_ / "interrupted" / "runs" / "sleeper-0" / "result.json"));
  const CommandOutput queue = RunSlurmCommand({"squeue", "-h", "-t", "all", "-r", "-o", "%T"});
  ASSERT_TRUE(queue.ok()) << queue.output;
  EXPECT_THAT(queue.output, HasSubstr("CANCELLED"));
}

}  // namespace
}  // namespace slamsweep::orchestrator
