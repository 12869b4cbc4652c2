#include "orchestrator/sweep/worker_pool.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "orchestrator/sweep/worker_environment.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

/// A stand-in for `slamsweep worker --serve`: takes run folders from descriptor 3; per run it records its
/// pid and environment, then does what the folder's `do` file says (answer, crash, hang or ignore SIGTERM).
fs::path FakeServingWorker(const fs::path& dir) {
  const fs::path worker = dir / "worker.sh";
  std::ofstream(worker) << R"SH(#!/bin/sh
[ "$1 $2" = "worker --serve" ] || exit 64
while read -r run <&3; do
  echo $$ > "$run/pid"
  printf '%s' "$GLIBC_TUNABLES" > "$run/tunables"
  case "$(cat "$run/do" 2>/dev/null)" in
    crash) kill -KILL $$ ;;
    hang) sleep 600 ;;
    exit2) echo "2 0.01 0.01" >&3 ;;
    *) echo "0 0.01 0.02" >&3 ;;
  esac
done
)SH";
  ::chmod(worker.c_str(), 0755);
  return worker;
}

fs::path RunFolder(const fs::path& dir, const std::string& id, const std::string& action = "") {
  fs::create_directories(dir / id);
  if (!action.empty()) std::ofstream(dir / id / "do") << action;
  return dir / id;
}

RunSpec SpecOf(const std::string& id, double timeout_s = 30) {
  RunSpec run;
  run.run_id = id;
  run.algorithm.timeout_s = timeout_s;
  return run;
}

std::string Read(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Every ending until nothing runs, by run id.
std::map<std::string, WorkerEnding> WaitForAll(WorkerPool& pool) {
  std::map<std::string, WorkerEnding> endings;
  while (pool.Running() > 0) {
    for (WorkerEnding& ending : pool.Wait()) endings[ending.run_id] = ending;
  }
  return endings;
}

TEST(WorkerPoolTest, OneWorkerPerSlotTakesRunAfterRunWithTheWorkersEnvironment) {
  const testing::TempDir dir;
  WorkerPool pool(FakeServingWorker(dir.path()));
  std::set<std::string> pids;
  for (int i = 0; i < 6; ++i) {
    const std::string id = "r" + std::to_string(i);
    pool.Start(SpecOf(id), RunFolder(dir.path(), id));
    const std::vector<WorkerEnding> endings = pool.Wait();
    ASSERT_EQ(endings.size(), 1u);
    EXPECT_EQ(endings[0].run_id, id);
    EXPECT_FALSE(endings[0].interrupted);
    pids.insert(Read(dir / id / "pid"));
    EXPECT_EQ(Read(dir / id / "tunables"), WorkerEnvironment().front().second);
  }
  EXPECT_EQ(pids.size(), 1u) << "one slot, one worker process";
  EXPECT_EQ(pool.WorkersStarted(), 1u);
  // Two at once: a second worker for the second slot.
  pool.Start(SpecOf("a"), RunFolder(dir.path(), "a"));
  pool.Start(SpecOf("b"), RunFolder(dir.path(), "b"));
  EXPECT_EQ(WaitForAll(pool).size(), 2u);
  EXPECT_NE(Read(dir / "a" / "pid"), Read(dir / "b" / "pid"));
  EXPECT_EQ(pool.WorkersStarted(), 2u);
}

TEST(WorkerPoolTest, AWorkerThatDiesLosesOnlyTheRunInHand) {
  const testing::TempDir dir;
  WorkerPool pool(FakeServingWorker(dir.path()));
  pool.Start(SpecOf("crashes"), RunFolder(dir.path(), "crashes", "crash"));
  pool.Start(SpecOf("fine"), RunFolder(dir.path(), "fine"));
  std::map<std::string, WorkerEnding> endings = WaitForAll(pool);
  ASSERT_EQ(endings.size(), 2u);
  EXPECT_THAT(endings["crashes"].reason, HasSubstr("killed by SIGKILL"));
  EXPECT_FALSE(endings["crashes"].interrupted);
  EXPECT_EQ(endings["fine"].reason, "worker: exit code 0");
  // The surviving worker takes the next run; a bad run.json (exit 2) is answered as such.
  pool.Start(SpecOf("after"), RunFolder(dir.path(), "after", "exit2"));
  endings = WaitForAll(pool);
  EXPECT_EQ(endings["after"].reason, "worker: exit code 2");
  EXPECT_EQ(Read(dir / "after" / "pid"), Read(dir / "fine" / "pid"));
  // Two at once again: a new worker in the dead one's slot.
  pool.Start(SpecOf("x"), RunFolder(dir.path(), "x"));
  pool.Start(SpecOf("y"), RunFolder(dir.path(), "y"));
  EXPECT_EQ(WaitForAll(pool).size(), 2u);
  EXPECT_EQ(pool.WorkersStarted(), 3u);
}

TEST(WorkerPoolTest, ARunPastItsTimeoutHasItsWorkerStopped) {
  const testing::TempDir dir;
  WorkerPool pool(FakeServingWorker(dir.path()), 0.2);
  pool.Start(SpecOf("hangs", 0.3), RunFolder(dir.path(), "hangs", "hang"));
  const std::map<std::string, WorkerEnding> endings = WaitForAll(pool);
  ASSERT_EQ(endings.count("hangs"), 1u);
  EXPECT_THAT(endings.at("hangs").reason, HasSubstr("timed out after 0.5 s"));
  EXPECT_FALSE(endings.at("hangs").interrupted);
}

TEST(WorkerPoolTest, StopAndTerminateAllEndRunsAsInterrupted) {
  const testing::TempDir dir;
  WorkerPool pool(FakeServingWorker(dir.path()));
  pool.Start(SpecOf("stopped"), RunFolder(dir.path(), "stopped", "hang"));
  pool.Start(SpecOf("terminated"), RunFolder(dir.path(), "terminated", "hang"));
  pool.Stop("stopped");
  std::vector<WorkerEnding> endings = pool.Wait();
  ASSERT_EQ(endings.size(), 1u);
  EXPECT_EQ(endings[0].run_id, "stopped");
  EXPECT_TRUE(endings[0].interrupted);
  EXPECT_THAT(endings[0].reason, HasSubstr("stopped by the supervisor"));
  endings = pool.TerminateAll();
  ASSERT_EQ(endings.size(), 1u);
  EXPECT_EQ(endings[0].run_id, "terminated");
  EXPECT_TRUE(endings[0].interrupted);
  EXPECT_EQ(pool.Running(), 0u);
}

TEST(WorkerPoolTest, AProgramThatCannotStartIsAnErrorOfStart) {
  const testing::TempDir dir;
  WorkerPool pool(dir / "missing");
  EXPECT_THROW(pool.Start(SpecOf("r"), RunFolder(dir.path(), "r")), std::runtime_error);
}

}  // namespace
}  // namespace slamsweep::orchestrator
