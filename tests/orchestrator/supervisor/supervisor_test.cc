#include "orchestrator/supervisor/supervisor.h"

#include <map>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/orchestrator/sweep/fake_executor.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

using fakes::FakeExecutor;
using ::testing::ElementsAre;
using ::testing::IsEmpty;

/// Hands out a fixed list of runs in order and records what the supervisor tells it.
class ListSource final : public RunSource {
 public:
  ListSource(const std::filesystem::path& root, int count) : root_(root) {
    for (int i = 0; i < count; ++i) {
      RunSpec run;
      run.run_id = "run" + std::to_string(i);
      runs_.push_back(run);
    }
  }

  std::optional<RunStart> Next() override {
    if (next_ == runs_.size()) return std::nullopt;
    const RunSpec& run = runs_[next_++];
    std::filesystem::create_directories(root_ / run.run_id);
    return RunStart{&run, root_ / run.run_id};
  }
  void Started(const RunStart& start) override { started.push_back(start.run->run_id); }
  void Ended(const WorkerEnding& ending) override { ended[ending.run_id] = ending.interrupted; }
  void Draining() override { ++draining; }
  void Terminating(std::size_t running) override { terminating.push_back(running); }
  void EndTurn() override { ++turns; }

  std::vector<std::string> started;
  /// Run id -> whether its ending was an interruption.
  std::map<std::string, bool> ended;
  int draining = 0;
  std::vector<std::size_t> terminating;
  int turns = 0;

 private:
  std::filesystem::path root_;
  std::vector<RunSpec> runs_;
  std::size_t next_ = 0;
};

TEST(Supervisor, StartsAtMostJobsAtOnceInTheSourcesOrder) {
  slamsweep::testing::TempDir dir;
  FakeExecutor executor([](const RunSpec&) { return "ok"; });
  ListSource source(dir.path(), 5);
  Supervisor(executor, {.jobs = 2}).Run(source);
  EXPECT_EQ(executor.max_running, 2u);
  EXPECT_THAT(executor.started, ElementsAre("run0", "run1", "run2", "run3", "run4"));
  EXPECT_EQ(source.started, executor.started);
  EXPECT_EQ(executor.Running(), 0u);
  EXPECT_EQ(source.draining, 0);
  EXPECT_THAT(source.terminating, IsEmpty());
}

TEST(Supervisor, HandsEveryEndingBack) {
  slamsweep::testing::TempDir dir;
  FakeExecutor executor([](const RunSpec& run) { return run.run_id == "run1" ? "failed" : "no-result"; });
  ListSource source(dir.path(), 3);
  Supervisor(executor, {.jobs = 3}).Run(source);
  EXPECT_EQ(source.ended, (std::map<std::string, bool>{{"run0", false}, {"run1", false}, {"run2", false}}));
}

TEST(Supervisor, EndsAfterOneTurnWhenTheSourceHasNothing) {
  slamsweep::testing::TempDir dir;
  FakeExecutor executor([](const RunSpec&) { return "ok"; });
  ListSource source(dir.path(), 0);
  Supervisor(executor, {.jobs = 2}).Run(source);
  EXPECT_THAT(executor.started, IsEmpty());
  EXPECT_EQ(source.turns, 1);
}

TEST(Supervisor, WithoutGraceAnInterruptionTerminatesTheRunningRunsAtOnce) {
  slamsweep::testing::TempDir dir;
  // run0 ends, run1 is running when the interruption arrives; run2 and run3 never start.
  FakeExecutor executor([](const RunSpec& run) { return run.run_id == "run1" ? "interrupt" : "ok"; });
  ListSource source(dir.path(), 4);
  Supervisor(executor, {.jobs = 2, .drain_grace_s = 0.0}).Run(source);
  EXPECT_THAT(executor.started, ElementsAre("run0", "run1"));
  EXPECT_EQ(source.draining, 1);
  EXPECT_THAT(source.terminating, ElementsAre(1u));
  EXPECT_EQ(source.ended, (std::map<std::string, bool>{{"run0", false}, {"run1", true}}));
}

TEST(Supervisor, WithGraceRunsThatEndInTimeEndByThemselves) {
  slamsweep::testing::TempDir dir;
  // run1 is running when the interruption arrives and ends at the next wait, within the grace.
  int waits_of_run1 = 0;
  FakeExecutor executor([&](const RunSpec& run) {
    if (run.run_id != "run1") return "ok";
    return ++waits_of_run1 == 1 ? "interrupt" : "ok";
  });
  ListSource source(dir.path(), 4);
  Supervisor(executor, {.jobs = 2, .drain_grace_s = 60.0}).Run(source);
  EXPECT_THAT(executor.started, ElementsAre("run0", "run1"));
  EXPECT_EQ(source.draining, 1);
  EXPECT_THAT(source.terminating, IsEmpty());
  EXPECT_EQ(source.ended, (std::map<std::string, bool>{{"run0", false}, {"run1", false}}));
}

TEST(Supervisor, WithGraceRunsLeftWhenItIsOverAreTerminated) {
  slamsweep::testing::TempDir dir;
  FakeExecutor executor([](const RunSpec&) { return "interrupt"; });
  ListSource source(dir.path(), 1);
  Supervisor(executor, {.jobs = 1, .drain_grace_s = 0.3}).Run(source);
  EXPECT_EQ(source.draining, 1);
  EXPECT_THAT(source.terminating, ElementsAre(1u));
  EXPECT_EQ(source.ended, (std::map<std::string, bool>{{"run0", true}}));
}

/// Never runs dry; asks for a drain itself once three runs ended (as the service's Drain() does).
class DrainingSource final : public RunSource {
 public:
  explicit DrainingSource(const std::filesystem::path& root) : root_(root) {}

  std::optional<RunStart> Next() override {
    run_ = RunSpec();
    run_.run_id = "run" + std::to_string(started.size());
    std::filesystem::create_directories(root_ / run_.run_id);
    return RunStart{&run_, root_ / run_.run_id};
  }
  void Started(const RunStart& start) override { started.push_back(start.run->run_id); }
  void Ended(const WorkerEnding& ending) override { ended.push_back(ending.run_id); }
  bool AwaitsMore() const override { return true; }
  bool DrainRequested() const override { return ended.size() >= 3; }

  std::vector<std::string> started;
  std::vector<std::string> ended;

 private:
  std::filesystem::path root_;
  RunSpec run_;
};

TEST(Supervisor, ASourceThatNeverRunsDryEndsByItsDrainRequest) {
  slamsweep::testing::TempDir dir;
  FakeExecutor executor([](const RunSpec&) { return "ok"; });
  DrainingSource source(dir.path());
  Supervisor(executor, {.jobs = 1, .drain_grace_s = 60.0}).Run(source);
  EXPECT_THAT(source.started, ElementsAre("run0", "run1", "run2"));
  EXPECT_THAT(source.ended, ElementsAre("run0", "run1", "run2"));
}

}  // namespace
}  // namespace slamsweep::orchestrator
