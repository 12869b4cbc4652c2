// Crash and concurrency behaviour of results.sqlite, with real processes (fork), because that is what
// the guarantees are about: a killed orchestrator and several writers on one output folder.
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "orchestrator/store/results_store.h"
#include "orchestrator/store/sqlite_db.h"
#include "tests/orchestrator/store/store_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

using testing::MakeOkResult;
using testing::MakeSpec;

// Runs `body` in a child process; returns the child's exit status (or 128 + signal).
template <typename Body>
pid_t Spawn(Body body) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    int code = 0;
    try {
      code = body();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "child failed: %s\n", e.what());
      code = 3;
    }
    ::_exit(code);
  }
  return pid;
}

int Wait(pid_t pid) {
  int status = 0;
  if (::waitpid(pid, &status, 0) != pid) return -1;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + WTERMSIG(status);
}

TEST(ResultsStoreProcessesTest, ProcessDyingInsideRecordRunLeavesTheOldRun) {
  slamsweep::testing::TempDir dir;
  const auto file = dir / "results.sqlite";
  {
    ResultsStore store = ResultsStore::Open(file);
    store.RecordRun(1, MakeSpec("r1"), MakeOkResult("r1", 3.0, 0.12), "runs/r1");
  }
  const pid_t child = Spawn([&] {
    ResultsStore store = ResultsStore::Open(file);
    // Dies after the run row was replaced and before the metrics were: no destructor, no rollback.
    store.SetMidTransactionHookForTesting([] { ::_exit(42); });
    auto second = MakeOkResult("r1", 99.0, 7.0);
    second["metrics"] = nlohmann::json::array();
    store.RecordRun(1, MakeSpec("r1"), second, "runs/r1");
    return 0;
  });
  ASSERT_EQ(Wait(child), 42);
  ResultsStore store = ResultsStore::Open(file);
  const auto run = store.FindRun("r1");
  ASSERT_TRUE(run.has_value());
  EXPECT_EQ(run->wall_s, 3.0);
  ASSERT_EQ(run->metrics.size(), 3u);
  EXPECT_EQ(run->metrics[0].value, 0.12);
  // And the store is writable again: the dead process's lock went with it.
  store.RecordRun(1, MakeSpec("r2"), MakeOkResult("r2"), "runs/r2");
  EXPECT_EQ(store.Runs().size(), 2u);
}

TEST(ResultsStoreProcessesTest, ProcessKilledBeforeItsFirstRecordLeavesNoHalfRun) {
  slamsweep::testing::TempDir dir;
  const auto file = dir / "results.sqlite";
  { ResultsStore::Open(file); }
  const pid_t child = Spawn([&] {
    ResultsStore store = ResultsStore::Open(file);
    store.SetMidTransactionHookForTesting([] { ::kill(::getpid(), SIGKILL); });
    store.RecordRun(1, MakeSpec("new"), MakeOkResult("new"), "runs/new");
    return 0;
  });
  ASSERT_EQ(Wait(child), 128 + SIGKILL);
  ResultsStore store = ResultsStore::Open(file);
  EXPECT_EQ(store.StatusOf("new"), std::nullopt);
  SqliteDb db = SqliteDb::Open(file, false);
  auto count = db.Prepare("SELECT count(*) FROM metrics");
  ASSERT_TRUE(count.Step());
  EXPECT_EQ(count.Int64(0), 0);
}

TEST(ResultsStoreProcessesTest, ProcessesCreatingOneStoreAtOnceAllOpenIt) {
  // Switching a new file to WAL takes an exclusive lock; two openers that both hold a read lock
  // deadlock, and SQLite answers one of them "busy" at once instead of waiting.
  for (int round = 0; round < 40; ++round) {
    slamsweep::testing::TempDir dir;
    const auto file = dir / "results.sqlite";
    const auto opener = [&file] {
      ResultsStore::Open(file);
      return 0;
    };
    const pid_t a = Spawn(opener);
    const pid_t b = Spawn(opener);
    const pid_t c = Spawn(opener);
    ASSERT_EQ(Wait(a), 0) << "round " << round;
    ASSERT_EQ(Wait(b), 0) << "round " << round;
    ASSERT_EQ(Wait(c), 0) << "round " << round;
  }
}

TEST(ResultsStoreProcessesTest, TwoProcessesRecordingAtOnceLoseNothing) {
  slamsweep::testing::TempDir dir;
  const auto file = dir / "results.sqlite";
  constexpr int kRunsPerProcess = 200;
  const auto writer = [&](const std::string& prefix) {
    return [&file, prefix] {
      ResultsStore store = ResultsStore::Open(file);
      SweepInfo info;
      info.name = prefix;
      const std::int64_t sweep = store.BeginSweep(info);
      for (int i = 0; i < kRunsPerProcess; ++i) {
        const std::string id = prefix + "-" + std::to_string(i);
        store.RecordRun(sweep, MakeSpec(id, prefix, "intel", i), MakeOkResult(id, 1.0 + i), "runs/" + id);
        // Readers interleave with writers in a real sweep (skip checks); they must not disturb them.
        if (!store.StatusOf(id).has_value()) return 4;
      }
      store.FinishSweep(sweep, SweepStatus::kOk, kRunsPerProcess);
      return 0;
    };
  };
  // Both children also race to create the schema.
  const pid_t a = Spawn(writer("a"));
  const pid_t b = Spawn(writer("b"));
  EXPECT_EQ(Wait(a), 0);
  EXPECT_EQ(Wait(b), 0);
  ResultsStore store = ResultsStore::Open(file);
  const auto runs = store.Runs();
  EXPECT_EQ(runs.size(), 2u * kRunsPerProcess);
  std::size_t metrics = 0;
  for (const RunRecord& run : runs) metrics += run.metrics.size();
  EXPECT_EQ(metrics, 3u * 2u * kRunsPerProcess);
  EXPECT_EQ(store.Sweeps().size(), 2u);
  // wall_s of process a: 1..200; the median of an even count is the mean of the middle two, (100 + 101) / 2.
  EXPECT_DOUBLE_EQ(store.TypicalWallSeconds().at(TypicalWallKey("a", "intel")), 100.5);
}

}  // namespace
}  // namespace slamsweep::orchestrator
