#include "orchestrator/sweep/sweep_runner.h"

#include <fstream>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/store/results_store.h"
#include "orchestrator/run/run_folder.h"
#include "orchestrator/sweep/output_lock.h"
#include "tests/orchestrator/sweep/fake_executor.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

using fakes::FakeExecutor;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

std::vector<RunSpec> Matrix(int count) {
  std::vector<RunSpec> runs;
  for (int i = 0; i < count; ++i) {
    RunSpec run;
    run.run_id = "algo-seq-clean-i" + std::to_string(i) + "-0000000" + std::to_string(i);
    run.sweep = "test";
    run.algorithm.name = i % 2 == 0 ? "fast" : "slow";
    run.algorithm.adapter = "odometry";
    run.sequence.entry.name = "seq";
    run.sequence.entry.format = "simulated";
    run.iteration = i;
    run.seed = static_cast<std::uint64_t>(i);
    runs.push_back(run);
  }
  return runs;
}

/// Captures what the sweep tells the user.
class RecordingStatus final : public Status {
 public:
  void Planned(std::size_t to_run, std::size_t done) override { lines.push_back(fmt(to_run, done)); }
  void Started(const std::string&) override {}
  void Finished(const FinishedRun& run) override { finished.push_back(run); }
  void Message(const std::string& text) override { lines.push_back(text); }
  void Done() override {}
  static std::string fmt(std::size_t a, std::size_t b) {
    return std::to_string(a) + " to run, " + std::to_string(b) + " done";
  }
  std::vector<std::string> lines;
  std::vector<FinishedRun> finished;
};

SweepSettings Settings(const std::filesystem::path& out, std::size_t jobs = 2) {
  SweepSettings settings;
  settings.name = "test";
  settings.output_dir = out;
  settings.jobs = jobs;
  return settings;
}

nlohmann::json ReadJson(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return nlohmann::json::parse(text.str());
}

TEST(SweepRunner, RecordsEveryRunAndWritesSummaryAndJUnit) {
  slamsweep::testing::TempDir dir;
  const auto runs = Matrix(5);
  FakeExecutor executor([](const RunSpec& run) { return run.iteration == 3 ? "failed" : "ok"; });
  RecordingStatus status;
  const SweepOutcome outcome = RunSweep(runs, Settings(dir.path()), executor, status);
  EXPECT_EQ(outcome.ok, 4u);
  EXPECT_EQ(outcome.failed, 1u);
  EXPECT_EQ(outcome.ExitCode(), 1);
  EXPECT_LE(executor.max_running, 2u);
  EXPECT_EQ(executor.started.size(), 5u);
  const nlohmann::json summary = ReadJson(dir.path() / "summary.json");
  ASSERT_EQ(summary["runs"].size(), 5u);
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "junit.xml"));
  for (const RunSpec& run : runs) {
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "runs" / run.run_id / "run.json")) << run.run_id;
  }
}

TEST(SweepRunner, ASecondSweepSkipsFinishedRunsAndRerunFailedRetriesOnlyThose) {
  slamsweep::testing::TempDir dir;
  const auto runs = Matrix(4);
  RecordingStatus status;
  FakeExecutor first([](const RunSpec& run) { return run.iteration == 2 ? "failed" : "ok"; });
  RunSweep(runs, Settings(dir.path()), first, status);

  FakeExecutor again([](const RunSpec&) { return "ok"; });
  const SweepOutcome repeated = RunSweep(runs, Settings(dir.path()), again, status);
  EXPECT_TRUE(again.started.empty());
  EXPECT_EQ(repeated.already_done, 4u);
  EXPECT_EQ(repeated.ExitCode(), 1) << "the failed run of the first sweep still fails the matrix";

  SweepSettings rerun = Settings(dir.path());
  rerun.rerun_failed = true;
  FakeExecutor retry([](const RunSpec&) { return "ok"; });
  const SweepOutcome retried = RunSweep(runs, rerun, retry, status);
  EXPECT_THAT(retry.started, ElementsAre(runs[2].run_id));
  EXPECT_EQ(retried.ExitCode(), 0);
}

// Runs scored under other evaluation options (say other segment lengths) would sit in one group with
// the new ones but carry other numbers: a rerun redoes them, unless --reuse-stale.
TEST(SweepRunner, ARunScoredUnderOtherEvaluationOptionsIsRunAgain) {
  slamsweep::testing::TempDir dir;
  std::vector<RunSpec> runs = Matrix(2);
  RecordingStatus status;
  FakeExecutor first([](const RunSpec&) { return "ok"; });
  RunSweep(runs, Settings(dir.path()), first, status);

  runs[1].evaluation.rpe_segments_m = std::vector<double>{5.0, 10.0};
  FakeExecutor again([](const RunSpec&) { return "ok"; });
  const SweepOutcome repeated = RunSweep(runs, Settings(dir.path()), again, status);
  EXPECT_THAT(again.started, ElementsAre(runs[1].run_id));
  EXPECT_EQ(repeated.stale, 1u);
  EXPECT_EQ(repeated.already_done, 1u);

  runs[1].evaluation.rpe_segments_m = std::vector<double>{20.0};
  SweepSettings reuse = Settings(dir.path());
  reuse.reuse_stale = true;
  FakeExecutor kept([](const RunSpec&) { return "ok"; });
  const SweepOutcome reused = RunSweep(runs, reuse, kept, status);
  EXPECT_TRUE(kept.started.empty());
  EXPECT_EQ(reused.stale, 1u);
  // The reused run is marked stale in its folder and its store row; the fresh one is not.
  ResultsStore store = ResultsStore::Open(dir.path() / "results.sqlite");
  EXPECT_EQ(store.FindRun(runs[1].run_id)->flags, RunFlags{RunFlag::kStale});
  EXPECT_TRUE(store.FindRun(runs[0].run_id)->flags.empty());
  const nlohmann::json result = ReadJsonFile(dir.path() / "runs" / runs[1].run_id / "result.json");
  EXPECT_EQ(result.at("flags"), nlohmann::json::array({"stale"}));
}

// The reference map is scoring too (not part of the run id): naming another one makes the map scores
// of the finished runs stale, so they are redone.
TEST(SweepRunner, ARunScoredAgainstAnotherReferenceMapIsRunAgain) {
  slamsweep::testing::TempDir dir;
  std::vector<RunSpec> runs = Matrix(2);
  RecordingStatus status;
  FakeExecutor first([](const RunSpec&) { return "ok"; });
  RunSweep(runs, Settings(dir.path()), first, status);

  runs[0].sequence.entry.reference_map_path = "/maps/intel.yaml";
  FakeExecutor again([](const RunSpec&) { return "ok"; });
  const SweepOutcome repeated = RunSweep(runs, Settings(dir.path()), again, status);
  EXPECT_THAT(again.started, ElementsAre(runs[0].run_id));
  EXPECT_EQ(repeated.stale, 1u);

  FakeExecutor same([](const RunSpec&) { return "ok"; });
  const SweepOutcome unchanged = RunSweep(runs, Settings(dir.path()), same, status);
  EXPECT_TRUE(same.started.empty());
  EXPECT_EQ(unchanged.stale, 0u);
}

TEST(SweepRunner, AdoptsAResultTheStoreNeverSawAndRedoesAHalfWrittenRun) {
  slamsweep::testing::TempDir dir;
  const auto runs = Matrix(3);
  RecordingStatus status;
  FakeExecutor first([](const RunSpec&) { return "ok"; });
  RunSweep(runs, Settings(dir.path()), first, status);
  // As if the orchestrator died after the workers wrote result.json but before the store commit:
  // a fresh store; and run 1 as if it was killed midway (its result gone).
  std::filesystem::remove(dir.path() / "results.sqlite");
  std::filesystem::remove(dir.path() / "runs" / runs[1].run_id / "result.json");
  FakeExecutor second([](const RunSpec&) { return "ok"; });
  const SweepOutcome outcome = RunSweep(runs, Settings(dir.path()), second, status);
  EXPECT_THAT(second.started, ElementsAre(runs[1].run_id));
  EXPECT_EQ(outcome.already_done, 2u);
  EXPECT_EQ(ReadJson(dir.path() / "summary.json")["runs"].size(), 3u);
}

TEST(SweepRunner, AWorkerThatLeavesNoResultIsAFailedRunWithItsReason) {
  slamsweep::testing::TempDir dir;
  FakeExecutor executor([](const RunSpec&) { return "no-result"; });
  RecordingStatus status;
  const SweepOutcome outcome = RunSweep(Matrix(1), Settings(dir.path()), executor, status);
  EXPECT_EQ(outcome.failed, 1u);
  ASSERT_EQ(status.finished.size(), 1u);
  EXPECT_THAT(status.finished[0].reason, HasSubstr("SIGKILL"));
  const nlohmann::json result = ReadJson(dir.path() / "runs" / Matrix(1)[0].run_id / "result.json");
  EXPECT_EQ(result["status"], "failed");
}

TEST(SweepRunner, FailureBudgetStopsStartingRuns) {
  slamsweep::testing::TempDir dir;
  SweepSettings settings = Settings(dir.path(), 1);
  settings.failure_budget = 1;
  FakeExecutor executor([](const RunSpec& run) { return run.iteration == 0 ? "failed" : "ok"; });
  RecordingStatus status;
  const SweepOutcome outcome = RunSweep(Matrix(4), settings, executor, status);
  EXPECT_EQ(executor.started.size(), 1u);
  EXPECT_EQ(outcome.not_started, 3u);
  EXPECT_EQ(outcome.ExitCode(), 1);
  EXPECT_THAT(status.lines.back(), HasSubstr("failure budget"));
}

TEST(SweepRunner, InterruptionKeepsFinishedRunsRemovesTheRunningOnesAndExits130) {
  slamsweep::testing::TempDir dir;
  const auto runs = Matrix(4);
  // jobs = 1: runs 0 and 1 finish, run 2 is running when the interruption arrives.
  FakeExecutor executor([](const RunSpec& run) { return run.iteration < 2 ? "ok" : "interrupt"; });
  RecordingStatus status;
  const SweepOutcome outcome = RunSweep(runs, Settings(dir.path(), 1), executor, status);
  EXPECT_TRUE(outcome.interrupted);
  EXPECT_EQ(outcome.ExitCode(), 130);
  EXPECT_EQ(outcome.ok, 2u);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "runs" / executor.started.back()))
      << "the interrupted run's partial folder must be gone";
  const nlohmann::json summary = ReadJson(dir.path() / "summary.json");
  EXPECT_EQ(summary["runs"].size(), 2u);
  // Started again, only the two unfinished runs run.
  FakeExecutor resume([](const RunSpec&) { return "ok"; });
  const SweepOutcome resumed = RunSweep(runs, Settings(dir.path(), 1), resume, status);
  EXPECT_EQ(resume.started.size(), 2u);
  EXPECT_EQ(resumed.ExitCode(), 0);
}

TEST(SweepRunner, RefusesAnOutputDirectoryAnotherSweepHolds) {
  slamsweep::testing::TempDir dir;
  OutputLock holder(dir.path());
  FakeExecutor executor([](const RunSpec&) { return "ok"; });
  RecordingStatus status;
  try {
    RunSweep(Matrix(1), Settings(dir.path()), executor, status);
    FAIL() << "expected the lock to be refused";
  } catch (const evaluator::InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("in use by another slamsweep"));
  }
  EXPECT_TRUE(executor.started.empty());
}

TEST(SweepRunner, HostileRunIdsCannotLeaveTheOutputFolder) {
  slamsweep::testing::TempDir dir;
  auto runs = Matrix(1);
  runs[0].run_id = "../../escaped";
  FakeExecutor executor([](const RunSpec&) { return "ok"; });
  RecordingStatus status;
  EXPECT_THROW(RunSweep(runs, Settings(dir.path()), executor, status), evaluator::InputError);
  EXPECT_FALSE(std::filesystem::exists(dir.path().parent_path().parent_path() / "escaped"));
}

TEST(LongestExpectedFirst, UnknownFirstThenLongestKnownStableForTies) {
  const auto runs = Matrix(4);  // fast, slow, fast, slow
  std::vector<const RunSpec*> pointers;
  for (const RunSpec& run : runs) pointers.push_back(&run);
  const auto ordered = LongestExpectedFirst(pointers, {{"fast\tseq", 1.0}, {"slow\tseq", 9.0}});
  ASSERT_EQ(ordered.size(), 4u);
  EXPECT_EQ(ordered[0], &runs[1]);
  EXPECT_EQ(ordered[1], &runs[3]);
  EXPECT_EQ(ordered[2], &runs[0]);
  EXPECT_EQ(ordered[3], &runs[2]);
  RunSpec unknown = runs[0];
  unknown.algorithm.name = "new";
  pointers.push_back(&unknown);
  EXPECT_EQ(LongestExpectedFirst(pointers, {{"fast\tseq", 1.0}, {"slow\tseq", 9.0}})[0], &unknown);
}

TEST(EstimateRemaining, UsesThroughputSoFar) {
  EXPECT_EQ(EstimateRemaining(0, 10, 2, std::chrono::seconds(5)), "");
  EXPECT_EQ(EstimateRemaining(5, 10, 2, std::chrono::seconds(50)), "50s");
  EXPECT_EQ(EstimateRemaining(1, 11, 2, std::chrono::seconds(30)), "5m00s");
  EXPECT_EQ(EstimateRemaining(10, 10, 2, std::chrono::seconds(50)), "");
}

TEST(Status, PlainLinesCarryTimestampsCountsAndFailureReasons) {
  std::ostringstream out;
  auto status = MakeStatus(out, /*smart=*/false, 2);
  status->Planned(2, 1);
  status->Started("a");
  status->Finished({"a", true, "", 2.0});
  status->Started("b");
  status->Finished({"b", false, "timeout: timed out after 1 s", 1.0});
  status->Done();
  const std::string text = out.str();
  EXPECT_THAT(text, HasSubstr("2 runs to do, 1 already done"));
  EXPECT_THAT(text, HasSubstr("[1/2] 0 running, 0 failed"));
  EXPECT_THAT(text, HasSubstr("FAILED b (timeout: timed out after 1 s)"));
  EXPECT_THAT(text, ::testing::ContainsRegex("^[0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9:]{8}Z "));
  EXPECT_EQ(text.find('\r'), std::string::npos) << "CI logs get no carriage returns";
}

TEST(Status, LiveLineRedrawsInPlace) {
  std::ostringstream out;
  auto status = MakeStatus(out, /*smart=*/true, 2);
  status->Planned(1, 0);
  status->Started("a");
  status->Finished({"a", false, "signal: killed by SIGSEGV", 1.0});
  status->Done();
  EXPECT_THAT(out.str(), HasSubstr("\r\x1b[K"));
  EXPECT_THAT(out.str(), HasSubstr("FAILED a: signal: killed by SIGSEGV\n"));
}

}  // namespace
}  // namespace slamsweep::orchestrator
