#include "orchestrator/process/process_set.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <string>

#include "tests/orchestrator/process/process_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

using ::slamsweep::testing::TempDir;
using ::testing::HasSubstr;
using testing::ProcessGone;
using testing::ReadAll;
using testing::ReadPidFile;
using testing::Sh;
using ::testing::StartsWith;

TEST(RunProcessTest, ExitCodes) {
  const ProcessOutcome failed = RunProcess(Sh("exit 3"));
  EXPECT_EQ(failed.ending, ProcessEnding::kExited);
  EXPECT_EQ(failed.exit_code, 3);
  EXPECT_EQ(failed.signal, 0);
  EXPECT_EQ(failed.reason, "exit code 3");
  EXPECT_FALSE(failed.ok());

  const ProcessOutcome fine = RunProcess(Sh("exit 0"));
  EXPECT_TRUE(fine.ok());
  EXPECT_EQ(fine.reason, "exit code 0");
}

TEST(RunProcessTest, StdoutAndStderrGoToOneLog) {
  TempDir dir;
  const ProcessOutcome outcome = RunProcess(Sh("echo out; echo err >&2; echo out2", dir / "log.txt"));
  ASSERT_TRUE(outcome.ok()) << outcome.reason;
  EXPECT_EQ(ReadAll(dir / "log.txt"), "out\nerr\nout2\n");
  EXPECT_EQ(outcome.log_bytes_written, 13u);
  EXPECT_FALSE(outcome.log_truncated);
}

TEST(RunProcessTest, AbsurdLimitsAreHarmless) {
  ProcessSpec spec = Sh("exit 0");
  spec.timeout_s = 1e300;
  spec.grace_s = -1;
  spec.log_cap_bytes = 1;
  EXPECT_TRUE(RunProcess(spec).ok());
}

TEST(RunProcessTest, SegfaultIsSignaled) {
  const ProcessOutcome outcome = RunProcess(Sh("kill -SEGV $$"));
  EXPECT_EQ(outcome.ending, ProcessEnding::kSignaled);
  EXPECT_EQ(outcome.signal, SIGSEGV);
  EXPECT_EQ(outcome.exit_code, -1);
  EXPECT_THAT(outcome.reason, HasSubstr("SIGSEGV"));
}

TEST(RunProcessTest, TimeoutEndsTheWholeGroup) {
  TempDir dir;
  // The grandchild ignores SIGTERM, so only the group SIGKILL after the leader's end removes it.
  ProcessSpec spec = Sh("(trap '' TERM; exec sleep 30) & echo $! > " + (dir / "pid").string() + "; sleep 30");
  spec.timeout_s = 0.5;
  spec.grace_s = 3;
  const ProcessOutcome outcome = RunProcess(spec);
  EXPECT_EQ(outcome.ending, ProcessEnding::kTimedOut);
  EXPECT_EQ(outcome.signal, SIGTERM);
  EXPECT_EQ(outcome.reason, "timed out after 0.5 s (SIGTERM)");
  EXPECT_GE(outcome.wall_s, 0.5);
  EXPECT_LT(outcome.wall_s, 3.0);  // the leader obeyed TERM: no grace period spent
  const pid_t grandchild = ReadPidFile(dir / "pid");
  ASSERT_GT(grandchild, 0);
  EXPECT_TRUE(ProcessGone(grandchild));
}

TEST(RunProcessTest, ChildIgnoringTermIsKilledAfterGrace) {
  ProcessSpec spec = Sh("trap '' TERM; sleep 30");
  spec.timeout_s = 0.3;
  spec.grace_s = 0.5;
  const ProcessOutcome outcome = RunProcess(spec);
  EXPECT_EQ(outcome.ending, ProcessEnding::kTimedOut);
  EXPECT_EQ(outcome.signal, SIGKILL);
  EXPECT_EQ(outcome.reason, "timed out after 0.3 s (SIGTERM, then SIGKILL after 0.5 s grace)");
  EXPECT_GE(outcome.wall_s, 0.8);
  EXPECT_LT(outcome.wall_s, 5.0);
}

TEST(RunProcessTest, OutputFloodIsCappedKeepingHeadAndTail) {
  TempDir dir;
  ProcessSpec spec = Sh("yes | head -c 200000000; echo END", dir / "log.txt");
  spec.log_cap_bytes = 1 << 20;
  const ProcessOutcome outcome = RunProcess(spec);
  // head exits 0 only if its output was read to the end: nothing got SIGPIPE.
  ASSERT_TRUE(outcome.ok()) << outcome.reason;
  const std::string log = ReadAll(dir / "log.txt");
  EXPECT_LE(log.size(), 1u << 20);
  EXPECT_EQ(outcome.log_bytes_written, log.size());
  EXPECT_TRUE(outcome.log_truncated);
  EXPECT_THAT(log, StartsWith("y\ny\ny\n"));
  EXPECT_EQ(log.substr(log.size() - 10), "y\ny\ny\nEND\n");
  std::smatch marker;
  ASSERT_TRUE(std::regex_search(log, marker, std::regex("\n\\.\\.\\. ([0-9]+) bytes omitted \\.\\.\\.\n")));
  // What is kept plus what was omitted is everything the child wrote.
  const std::uint64_t omitted = std::stoull(marker[1].str());
  EXPECT_EQ(log.size() - marker.length(0) + omitted, 200000000u + 4u);
}

TEST(RunProcessTest, MissingProgramFailsToStartNamingIt) {
  TempDir dir;
  ProcessSpec spec;
  spec.argv = {"slamsweep-no-such-program-xyz", "--flag"};
  spec.log_path = dir / "log.txt";
  const ProcessOutcome outcome = RunProcess(spec);
  EXPECT_EQ(outcome.ending, ProcessEnding::kFailedToStart);
  EXPECT_THAT(outcome.reason, StartsWith("cannot start 'slamsweep-no-such-program-xyz': No such file"));
  EXPECT_THAT(ReadAll(dir / "log.txt"), HasSubstr("slamsweep-no-such-program-xyz"));

  spec.argv = {"/nonexistent/slam"};
  EXPECT_EQ(RunProcess(spec).reason, "cannot start '/nonexistent/slam': No such file or directory");
}

TEST(RunProcessTest, NonExecutableFileFailsToStart) {
  TempDir dir;
  const auto script = ::slamsweep::testing::WriteFile(dir / "script.sh", "#!/bin/sh\nexit 0\n");
  ::chmod(script.c_str(), 0644);
  ProcessSpec spec;
  spec.argv = {script.string()};
  const ProcessOutcome outcome = RunProcess(spec);
  EXPECT_EQ(outcome.ending, ProcessEnding::kFailedToStart);
  EXPECT_THAT(outcome.reason, HasSubstr("Permission denied"));
}

TEST(RunProcessTest, BadWorkingDirectoryOrLogFailToStart) {
  ProcessSpec spec = Sh("exit 0");
  spec.working_dir = "/nonexistent-dir";
  ProcessOutcome outcome = RunProcess(spec);
  EXPECT_EQ(outcome.ending, ProcessEnding::kFailedToStart);
  EXPECT_THAT(outcome.reason, HasSubstr("'/nonexistent-dir'"));

  spec = Sh("exit 0", "/nonexistent-dir/log.txt");
  outcome = RunProcess(spec);
  EXPECT_EQ(outcome.ending, ProcessEnding::kFailedToStart);
  EXPECT_THAT(outcome.reason, HasSubstr("/nonexistent-dir/log.txt"));

  spec.argv.clear();
  EXPECT_EQ(RunProcess(spec).ending, ProcessEnding::kFailedToStart);
}

TEST(RunProcessTest, MemoryLimitOnTheGroup) {
  if (::access("/usr/bin/python3", X_OK) != 0) SLAMSWEEP_SKIP_OR_FAIL_IN_CI("/usr/bin/python3 is needed");
  ProcessSpec spec;
  // bytes * n writes every page, so the 300 MB are resident, not just reserved.
  spec.argv = {"/usr/bin/python3", "-c", "import time\nb = b'x' * (300 << 20)\ntime.sleep(20)"};
  spec.memory_limit_mb = 100;
  spec.timeout_s = 30;
  const ProcessOutcome outcome = RunProcess(spec);
  EXPECT_EQ(outcome.ending, ProcessEnding::kMemoryLimit);
  EXPECT_EQ(outcome.signal, SIGKILL);
  EXPECT_THAT(outcome.reason, HasSubstr("above the 100 MB limit"));
  EXPECT_LT(outcome.wall_s, 10.0);
}

TEST(RunProcessTest, StdinIsDevNull) {
  ProcessSpec spec;
  spec.argv = {"cat"};  // looked up in PATH
  spec.timeout_s = 10;
  const ProcessOutcome outcome = RunProcess(spec);
  EXPECT_TRUE(outcome.ok()) << outcome.reason;
  EXPECT_LT(outcome.wall_s, 5.0);
}

// The child's environment is the supervisor's minus the removed prefixes, with the spec's variables set over
// it (the last setting of a name wins). Under AddressSanitizer, names longer than an existing entry also
// check that the lookup reads no entry past its end.
TEST(RunProcessTest, EnvironmentRemovesPrefixesAndReplacesVariables) {
  TempDir dir;
  ::setenv("SLAMSWEEP_TEST_KEPT", "kept", 1);
  ::setenv("SLAMSWEEP_TEST_SECRET_TOKEN", "secret", 1);
  ::setenv("SLAMSWEEP_TEST_REPLACED", "old", 1);
  ProcessSpec spec = Sh("env | grep '^SLAMSWEEP_TEST_' | sort", dir / "log.txt");
  spec.removed_env_prefixes = {"SLAMSWEEP_TEST_SECRET"};
  spec.extra_env = {{"SLAMSWEEP_TEST_REPLACED", "first"},
                    {"SLAMSWEEP_TEST_A_NAME_LONGER_THAN_ANY_ENTRY_OF_THE_ENVIRONMENT", "x"},
                    {"SLAMSWEEP_TEST_REPLACED", "new"}};
  const ProcessOutcome outcome = RunProcess(spec);
  ::unsetenv("SLAMSWEEP_TEST_KEPT");
  ::unsetenv("SLAMSWEEP_TEST_SECRET_TOKEN");
  ::unsetenv("SLAMSWEEP_TEST_REPLACED");
  ASSERT_TRUE(outcome.ok()) << outcome.reason;
  EXPECT_EQ(ReadAll(dir / "log.txt"),
            "SLAMSWEEP_TEST_A_NAME_LONGER_THAN_ANY_ENTRY_OF_THE_ENVIRONMENT=x\nSLAMSWEEP_TEST_KEPT=kept\n"
            "SLAMSWEEP_TEST_REPLACED=new\n");
}

TEST(RunProcessTest, EnvironmentAndWorkingDirectory) {
  TempDir dir;
  ProcessSpec spec = Sh("echo \"$SLAMSWEEP_TEST_VAR\"; pwd -P", dir / "log.txt");
  spec.working_dir = dir.path();
  spec.extra_env = {{"SLAMSWEEP_TEST_VAR", "hello world"}};
  ASSERT_TRUE(RunProcess(spec).ok());
  EXPECT_EQ(ReadAll(dir / "log.txt"), "hello world\n" + std::filesystem::canonical(dir.path()).string() + "\n");
}

TEST(RunProcessTest, SupervisorDescriptorsDoNotLeakIntoTheChild) {
  TempDir dir;
  const int inheritable = ::open("/dev/null", O_RDONLY);  // deliberately without O_CLOEXEC
  ASSERT_GE(inheritable, 3);
  const std::string fd = std::to_string(inheritable);
  const ProcessOutcome outcome =
      RunProcess(Sh("if [ -e /proc/$$/fd/" + fd + " ]; then echo leaked; else echo clean; fi", dir / "log.txt"));
  ::close(inheritable);
  ASSERT_TRUE(outcome.ok()) << outcome.reason;
  EXPECT_EQ(ReadAll(dir / "log.txt"), "clean\n");
}

TEST(RunProcessTest, OutputClosedBeforeExit) {
  const ProcessOutcome outcome = RunProcess(Sh("exec >&- 2>&-; sleep 0.3; exit 4"));
  EXPECT_EQ(outcome.exit_code, 4);
  EXPECT_GE(outcome.wall_s, 0.25);  // waited for the exit, not just for the end of the output
}

TEST(RunProcessTest, GrandchildHoldingThePipeDoesNotHang) {
  TempDir dir;
  ProcessSpec spec = Sh("sleep 30 & echo $! > " + (dir / "pid").string() + "; echo done", dir / "log.txt");
  const ProcessOutcome outcome = RunProcess(spec);
  EXPECT_TRUE(outcome.ok()) << outcome.reason;
  EXPECT_LT(outcome.wall_s, 5.0);
  EXPECT_EQ(ReadAll(dir / "log.txt"), "done\n");
  EXPECT_TRUE(ProcessGone(ReadPidFile(dir / "pid")));
}

TEST(RunProcessTest, ResourceUsage) {
  if (::access("/usr/bin/python3", X_OK) != 0) SLAMSWEEP_SKIP_OR_FAIL_IN_CI("/usr/bin/python3 is needed");
  ProcessSpec spec;
  spec.argv = {"/usr/bin/python3", "-c",
               "import time\nt = time.process_time()\nwhile time.process_time() - t < 0.3: pass"};
  const ProcessOutcome outcome = RunProcess(spec);
  ASSERT_TRUE(outcome.ok()) << outcome.reason;
  EXPECT_GE(outcome.cpu_s, 0.2);
  EXPECT_LT(outcome.cpu_s, 5.0);
  EXPECT_GE(outcome.wall_s, outcome.cpu_s * 0.9);
  EXPECT_GT(outcome.peak_rss_kb, 1000);  // a Python interpreter needs several MB
}

TEST(ProcessSetTest, SupervisorDeathStopsTheChild) {
  TempDir dir;
  const auto pid_file = dir / "pid";
  const pid_t supervisor = ::fork();
  ASSERT_GE(supervisor, 0);
  if (supervisor == 0) {
    // A supervisor that dies without cleaning up: its child must get SIGTERM (PR_SET_PDEATHSIG).
    ProcessSet set;
    set.Start(Sh("echo $$ > " + pid_file.string() + "; exec sleep 30"));
    ReadPidFile(pid_file);
    ::_exit(0);
  }
  ::waitpid(supervisor, nullptr, 0);
  const pid_t orphan = ReadPidFile(pid_file);
  ASSERT_GT(orphan, 0);
  EXPECT_TRUE(ProcessGone(orphan));
}

TEST(ProcessSetTest, EmptySetReturnsAtOnce) {
  ProcessSet set;
  EXPECT_TRUE(set.WaitForAny().empty());
  EXPECT_TRUE(set.TerminateAll().empty());
  EXPECT_EQ(set.running(), 0u);
}

TEST(ProcessSetTest, FourChildrenRunConcurrently) {
  ProcessSet set;
  std::map<ProcessSet::Id, int> expected_code;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 4; ++i) expected_code[set.Start(Sh("sleep 0.5; exit " + std::to_string(10 + i)))] = 10 + i;
  EXPECT_EQ(set.running(), 4u);
  std::map<ProcessSet::Id, int> seen_code;
  while (set.running() > 0) {
    for (const auto& [id, outcome] : set.WaitForAny()) seen_code[id] = outcome.exit_code;
  }
  const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(seen_code, expected_code);
  EXPECT_LT(elapsed_s, 1.9);  // four 0.5 s sleeps in sequence would take 2 s
}

TEST(ProcessSetTest, FailedStartIsReportedByWaitForAny) {
  ProcessSet set;
  ProcessSpec spec;
  spec.argv = {"/nonexistent/slam"};
  const ProcessSet::Id id = set.Start(spec);
  EXPECT_EQ(set.running(), 1u);
  const auto ended = set.WaitForAny();
  ASSERT_EQ(ended.size(), 1u);
  EXPECT_EQ(ended[0].first, id);
  EXPECT_EQ(ended[0].second.ending, ProcessEnding::kFailedToStart);
  EXPECT_EQ(set.running(), 0u);
}

TEST(ProcessSetTest, ASandboxThatCannotBeSetUpIsAFailedStartNamingWhy) {
  // A stand-in for bubblewrap that fails as it does where namespaces are refused.
  TempDir dir;
  const std::string fake = (dir / "bwrap").string();
  {
    std::ofstream script(fake);
    script << "#!/bin/sh\necho 'bwrap: No permissions to creating new namespace' >&2\nexit 1\n";
  }
  ::chmod(fake.c_str(), 0755);
  ProcessSpec spec;
  spec.argv = {"/bin/true"};
  spec.sandbox = SandboxSpec{};
  spec.sandbox->bwrap_program = fake;
  spec.sandbox->init_program = "/bin/true";
  const ProcessOutcome outcome = RunProcess(spec);
  EXPECT_EQ(outcome.ending, ProcessEnding::kFailedToStart);
  EXPECT_TRUE(outcome.sandbox_failed);
  EXPECT_EQ(outcome.reason,
            "the sandbox could not be set up (bwrap exited with 1: bwrap: No permissions to creating new namespace)");
}

/// Raises `signal_number` in a helper thread after `delay`. The thread unblocks the signal itself:
/// it inherited the mask of the test thread, where the guard blocks it, and raise() targets the
/// calling thread only.
std::thread RaiseLater(int signal_number, std::chrono::milliseconds delay) {
  return std::thread([=] {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, signal_number);
    pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
    std::this_thread::sleep_for(delay);
    ::raise(signal_number);
  });
}

TEST(InterruptionTest, WaitForAnyReturnsAndTerminateAllEndsChildren) {
  TempDir dir;
  InterruptionGuard guard;
  EXPECT_FALSE(InterruptionGuard::Interrupted());
  ProcessSet set;
  const ProcessSet::Id polite = set.Start(Sh("echo $$ > " + (dir / "a").string() + "; sleep 30"));
  ProcessSpec stubborn = Sh("trap '' TERM; echo $$ > " + (dir / "b").string() + "; sleep 30");
  stubborn.grace_s = 0.3;
  set.Start(stubborn);
  const pid_t a = ReadPidFile(dir / "a");
  const pid_t b = ReadPidFile(dir / "b");

  std::thread raiser = RaiseLater(SIGINT, std::chrono::milliseconds(200));
  const auto start = std::chrono::steady_clock::now();
  const auto ended = set.WaitForAny();
  raiser.join();
  EXPECT_TRUE(ended.empty());
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
  EXPECT_TRUE(InterruptionGuard::Interrupted());
  EXPECT_EQ(InterruptionGuard::Signal(), SIGINT);
  EXPECT_TRUE(set.WaitForAny().empty());  // still interrupted: returns at once

  const auto stopped = set.TerminateAll();
  ASSERT_EQ(stopped.size(), 2u);
  for (const auto& [id, outcome] : stopped) {
    EXPECT_EQ(outcome.ending, ProcessEnding::kInterrupted);
    EXPECT_EQ(outcome.reason, id == polite ? "interrupted by SIGINT (SIGTERM)"
                                           : "interrupted by SIGINT (SIGTERM, then SIGKILL after 0.3 s grace)");
  }
  EXPECT_EQ(set.running(), 0u);
  EXPECT_TRUE(ProcessGone(a));
  EXPECT_TRUE(ProcessGone(b));
}

TEST(InterruptionTest, RunProcessStopsItsChild) {
  InterruptionGuard guard;
  std::thread raiser = RaiseLater(SIGTERM, std::chrono::milliseconds(200));
  ProcessSpec spec = Sh("sleep 30");
  const ProcessOutcome outcome = RunProcess(spec);
  raiser.join();
  EXPECT_EQ(outcome.ending, ProcessEnding::kInterrupted);
  EXPECT_EQ(outcome.reason, "interrupted by SIGTERM (SIGTERM)");
  EXPECT_LT(outcome.wall_s, 5.0);
}

TEST(InterruptionTest, NewGuardClearsAnEarlierInterruption) {
  {
    InterruptionGuard guard;
    std::thread raiser = RaiseLater(SIGHUP, std::chrono::milliseconds(0));
    raiser.join();
    EXPECT_EQ(InterruptionGuard::Signal(), SIGHUP);
  }
  // Sticky for the caller's exit code, but it no longer stops children once the guard is gone.
  EXPECT_TRUE(InterruptionGuard::Interrupted());
  EXPECT_FALSE(InterruptionPending());
  EXPECT_TRUE(RunProcess(Sh("exit 0")).ok());
  InterruptionGuard guard;
  EXPECT_FALSE(InterruptionGuard::Interrupted());
  EXPECT_TRUE(RunProcess(Sh("exit 0")).ok());
}

}  // namespace
}  // namespace slamsweep::orchestrator
