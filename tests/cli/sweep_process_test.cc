// The real `slamsweep run` as Jenkins and people start it: signals, SIGKILL and re-run, two
// orchestrators on one directory. Fake SLAM programs (shell scripts declared through the command
// adapter) make runs fast or slow on demand.
#include <signal.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/child_process.h"
#include "tests/support/shared_data.h"

namespace slamsweep {
namespace {

using ::testing::HasSubstr;
using testing::WaitExit;
using Clock = std::chrono::steady_clock;

std::string ReadAll(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// A sweep folder with a fake SLAM program: `fast` runs copy the reference trajectory as their
/// estimate at once; `slow` runs do the same but first sleep while the file control/slow exists
/// (control/ is what the program declares it reads). Each run notes its start in raw/invocation.txt.
class SweepProcessTest : public ::testing::Test {
 protected:
  void SetUp() override {
    program_ = testing::WriteFile(dir_ / "fake_slam.sh",
                                  "#!/bin/sh\n"
                                  "echo \"$4\" >> \"$2/invocation.txt\"\n"
                                  "if [ \"$4\" = slow ] && [ -e \"$3/slow\" ]; then sleep 120; fi\n"
                                  "cp \"$1\" \"$2/traj.tum\"\n");
    std::filesystem::permissions(program_, std::filesystem::perms::owner_all | std::filesystem::perms::group_read |
                                               std::filesystem::perms::group_exec |
                                               std::filesystem::perms::others_read |
                                               std::filesystem::perms::others_exec);
    std::filesystem::create_directories(dir_ / "control");
    std::string algorithms;
    for (const std::string name : {"fast", "slow"}) {
      algorithms += "  - name: " + name + "\n    adapter: command\n    timeout_s: 300\n    command:\n" +
                    "      argv: [" + program_.string() + ", \"{input}\", \"{output_dir}\", " +
                    (dir_ / "control").string() + ", " + name +
                    "]\n      input_format: tum\n      trajectory: {path: traj.tum, format: tum}\n" +
                    "      read_only: [" + (dir_ / "control").string() + "]\n";
    }
    config_ =
        testing::WriteFile(dir_ / "sweep.yaml",
                           "name: process-test\noutput: out\niterations: 2\nseed: 1\nworkers: 2\n"
                           "evaluation: {stages: 4}\n"
                           "algorithms:\n" +
                               algorithms + "sequences:\n  - {catalog: simulated-floor, name: floor, max_scans: 40}\n");
    testing::WriteFile(dir_ / "control" / "slow", "");
  }

  /// Starts `slamsweep run` with stdout/stderr to files; returns its pid.
  pid_t Start(const std::string& tag) {
    const std::string out = (dir_ / (tag + ".out")).string();
    const pid_t pid = fork();
    if (pid == 0) {
      const int fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      dup2(fd, 1);
      dup2(fd, 2);
      execl(SLAMSWEEP_BINARY, SLAMSWEEP_BINARY, "run", config_.c_str(), "--no-report", static_cast<char*>(nullptr));
      _exit(127);
    }
    return pid;
  }

  /// Waits until both fast runs have results and both slow programs are running.
  bool WaitUntilFastDoneAndSlowRunning(std::chrono::seconds limit) {
    const auto deadline = Clock::now() + limit;
    while (Clock::now() < deadline) {
      std::size_t fast_results = 0;
      std::size_t slow_running = 0;
      if (std::filesystem::exists(dir_ / "out" / "runs")) {
        for (const auto& entry : std::filesystem::directory_iterator(dir_ / "out" / "runs")) {
          const std::string name = entry.path().filename().string();
          if (name.rfind("fast-", 0) == 0 && std::filesystem::exists(entry.path() / "result.json")) ++fast_results;
          if (name.rfind("slow-", 0) == 0 && std::filesystem::exists(entry.path() / "raw" / "invocation.txt"))
            ++slow_running;
        }
      }
      if (fast_results == 2 && slow_running >= 2) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return false;
  }

  nlohmann::json Summary() { return nlohmann::json::parse(ReadAll(dir_ / "out" / "summary.json")); }

  testing::TempDir dir_;
  std::filesystem::path program_;
  std::filesystem::path config_;
};

TEST_F(SweepProcessTest, SigintEndsWith130KeepsFinishedRunsAndRemovesInterruptedOnes) {
  const pid_t pid = Start("first");
  ASSERT_TRUE(WaitUntilFastDoneAndSlowRunning(std::chrono::seconds(120))) << ReadAll(dir_ / "first.out");
  kill(pid, SIGINT);
  EXPECT_EQ(WaitExit(pid, std::chrono::seconds(60)), 130) << ReadAll(dir_ / "first.out");
  const nlohmann::json summary = Summary();
  ASSERT_EQ(summary["runs"].size(), 2u);
  for (const auto& run : summary["runs"]) EXPECT_EQ(run["status"], "ok") << run.dump();
  for (const auto& entry : std::filesystem::directory_iterator(dir_ / "out" / "runs")) {
    EXPECT_EQ(entry.path().filename().string().rfind("slow-", 0), std::string::npos)
        << "interrupted run left behind: " << entry.path();
  }
}

TEST_F(SweepProcessTest, SigkillThenRunAgainLosesNothingAndRepeatsNoFinishedRun) {
  const pid_t pid = Start("first");
  ASSERT_TRUE(WaitUntilFastDoneAndSlowRunning(std::chrono::seconds(120))) << ReadAll(dir_ / "first.out");
  // The finished runs' results as they are now: a repeated run would write new ones.
  std::map<std::string, std::string> finished;
  for (const auto& entry : std::filesystem::directory_iterator(dir_ / "out" / "runs")) {
    if (std::filesystem::exists(entry.path() / "result.json")) {
      finished[entry.path().filename().string()] = ReadAll(entry.path() / "result.json");
    }
  }
  ASSERT_EQ(finished.size(), 2u);
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  std::filesystem::remove(dir_ / "control" / "slow");
  // The killed orchestrator's workers stop with it (parent-death signal); give them a moment.
  std::this_thread::sleep_for(std::chrono::seconds(1));
  const pid_t again = Start("second");
  EXPECT_EQ(WaitExit(again, std::chrono::seconds(180)), 0) << ReadAll(dir_ / "second.out");
  for (const auto& [run, result] : finished) {
    EXPECT_EQ(ReadAll(dir_ / "out" / "runs" / run / "result.json"), result) << "a finished run was repeated: " << run;
  }
  // The killed slow runs started afresh (their folders emptied) and ran once more each.
  std::size_t slow_runs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir_ / "out" / "runs")) {
    if (entry.path().filename().string().rfind("slow-", 0) != 0) continue;
    ++slow_runs;
    EXPECT_EQ(ReadAll(entry.path() / "raw" / "invocation.txt"), "slow\n") << entry.path();
  }
  EXPECT_EQ(slow_runs, 2u);
  const nlohmann::json summary = Summary();
  ASSERT_EQ(summary["runs"].size(), 4u);
  for (const auto& run : summary["runs"]) EXPECT_EQ(run["status"], "ok") << run.dump();
}

TEST_F(SweepProcessTest, ASecondOrchestratorOnTheSameDirectoryIsRefused) {
  const pid_t pid = Start("first");
  ASSERT_TRUE(WaitUntilFastDoneAndSlowRunning(std::chrono::seconds(120))) << ReadAll(dir_ / "first.out");
  const pid_t second = Start("second");
  EXPECT_EQ(WaitExit(second, std::chrono::seconds(60)), 2);
  EXPECT_THAT(ReadAll(dir_ / "second.out"), HasSubstr("in use by another slamsweep"));
  kill(pid, SIGTERM);
  EXPECT_EQ(WaitExit(pid, std::chrono::seconds(60)), 130);
  EXPECT_EQ(Summary()["runs"].size(), 2u) << "the refused orchestrator must not have touched the results";
}

}  // namespace
}  // namespace slamsweep
