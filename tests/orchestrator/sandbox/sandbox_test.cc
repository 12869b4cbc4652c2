// The sandbox: the bubblewrap command it builds, and real programs run in it through RunProcess
// (exact status, what exists for them, their network, their process limit, their memory counted
// over everything they started).
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "orchestrator/process/process_set.h"
#include "orchestrator/sandbox/bwrap_command.h"
#include "orchestrator/sandbox/pids_cgroup.h"
#include "orchestrator/sandbox/proc_choice.h"
#include "orchestrator/sandbox/sandbox_availability.h"
#include "tests/orchestrator/process/process_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

namespace fs = std::filesystem;
using ::slamsweep::testing::TempDir;
using testing::ReadAll;

/// The index of `item` in `argv`, or argv.size().
std::size_t Find(const std::vector<std::string>& argv, const std::vector<std::string>& items) {
  for (std::size_t i = 0; i + items.size() <= argv.size(); ++i) {
    if (std::equal(items.begin(), items.end(), argv.begin() + static_cast<long>(i))) return i;
  }
  return argv.size();
}

TEST(BwrapCommandTest, IsolatesEverythingAndShowsOnlyWhatItIsGiven) {
  SandboxSpec spec;
  spec.bwrap_program = "/usr/bin/bwrap";
  spec.init_program = "/opt/slamsweep/slamsweep-sandbox-init";
  spec.read_only = {"/data/run/input", "/opt/tool/bin/slam", "/usr/share/mrpt"};
  spec.writable = {"/data/run/raw"};
  spec.process_limit = 64;
  spec.file_size_limit_bytes = 8 << 20;
  const std::vector<std::string> argv = BwrapCommand(spec, {"/opt/tool/bin/slam", "--in", "x"}, "/data/run/raw", 7);
  EXPECT_EQ(argv.front(), "/usr/bin/bwrap");
  for (const std::vector<std::string>& option :
       std::vector<std::vector<std::string>>{{"--unshare-user"},
                                             {"--unshare-pid"},
                                             {"--unshare-net"},
                                             {"--unshare-ipc"},
                                             {"--disable-userns"},
                                             {"--die-with-parent"},
                                             {"--new-session"},
                                             {"--as-pid-1"},
                                             {"--cap-drop", "ALL"},
                                             {"--proc", "/proc"},
                                             {"--dev", "/dev"},
                                             {"--size", "8388608", "--tmpfs", "/tmp"},
                                             {"--ro-bind", "/data/run/input", "/data/run/input"},
                                             {"--ro-bind", "/opt/tool/bin/slam", "/opt/tool/bin/slam"},
                                             {"--bind", "/data/run/raw", "/data/run/raw"},
                                             {"--remount-ro", "/"},
                                             {"--chdir", "/data/run/raw"}}) {
    EXPECT_LT(Find(argv, option), argv.size()) << option.front();
  }
  // Already visible under /usr: not bound again.
  EXPECT_EQ(Find(argv, {"--ro-bind", "/usr/share/mrpt", "/usr/share/mrpt"}), argv.size());
  // Nothing of the host's home, temporary or service folders.
  for (const char* hidden : {"/home", "/root", "/var", "/run", "/etc/shadow", "/etc/ssh"}) {
    EXPECT_EQ(std::count(argv.begin(), argv.end(), hidden), 0) << hidden;
  }
  // The run's folders go on top of the private /tmp, and the root is read-only once all is bound.
  EXPECT_LT(Find(argv, {"--tmpfs", "/tmp"}), Find(argv, {"--bind", "/data/run/raw", "/data/run/raw"}));
  EXPECT_LT(Find(argv, {"--bind", "/data/run/raw", "/data/run/raw"}), Find(argv, {"--remount-ro", "/"}));
  const std::size_t init = Find(argv, {"--", "/opt/slamsweep/slamsweep-sandbox-init"});
  ASSERT_LT(init, argv.size());
  EXPECT_EQ(std::vector<std::string>(argv.begin() + static_cast<long>(init) + 1, argv.end()),
            (std::vector<std::string>{"/opt/slamsweep/slamsweep-sandbox-init", "--status-fd", "7", "--process-limit",
                                      "64", "--file-size-limit", "8388608", "--", "/opt/tool/bin/slam", "--in", "x"}));

  // A folder under /usr with a reference in it: an empty read-only tmpfs, after /usr is bound.
  spec.hidden = {"/usr/share/data/truth"};
  const std::vector<std::string> masked = BwrapCommand(spec, {"/bin/true"}, "/data/run/raw", 7);
  EXPECT_LT(Find(masked, {"--ro-bind", "/usr", "/usr"}), Find(masked, {"--tmpfs", "/usr/share/data/truth"}));
  EXPECT_LT(Find(masked, {"--remount-ro", "/usr/share/data/truth"}), masked.size());
  spec.hidden.clear();

  spec.network = true;
  const std::vector<std::string> networked = BwrapCommand(spec, {"/bin/true"}, "/data/run/raw", 7);
  EXPECT_EQ(Find(networked, {"--unshare-net"}), networked.size());
  spec.read_only = {"relative/path"};
  EXPECT_THROW(BwrapCommand(spec, {"/bin/true"}, "/data/run/raw", 7), std::invalid_argument);
}

TEST(BwrapCommandTest, WhatIsBoundUnderTheSandboxsOwnTmpStandsOnAReadOnlyTmpfs) {
  SandboxSpec spec;
  spec.init_program = "/tmp/clone/build/slamsweep-sandbox-init";
  spec.read_only = {"/tmp/clone/out/runs/r0/input", "/dev/shm/tools/slam", "/tmp/slam", "/tmp/given",
                    "/tmp/given/config.ini",        "/data/run/input"};
  spec.writable = {"/tmp/clone/out/runs/r0/raw"};
  for (const std::uint64_t size : {std::uint64_t{0}, std::uint64_t{8} << 20}) {
    spec.file_size_limit_bytes = size;
    const std::vector<std::string> argv = BwrapCommand(spec, {"/tmp/slam"}, "/tmp/clone/out/runs/r0/raw", 7);
    const std::size_t bind_raw = Find(argv, {"--bind", "/tmp/clone/out/runs/r0/raw", "/tmp/clone/out/runs/r0/raw"});
    const std::size_t last_bind = Find(argv, {"--ro-bind", "/tmp/given", "/tmp/given"});
    ASSERT_LT(bind_raw, argv.size());
    ASSERT_LT(last_bind, argv.size());
    // One stand for every first folder below /tmp or /dev/shm that holds a deeper bound path: on the private
    // tmpfs, under what is bound there, and read-only once everything is bound.
    for (const std::string stand : {"/tmp/clone", "/dev/shm/tools"}) {
      const std::size_t mounted = Find(argv, {"--tmpfs", stand});
      ASSERT_LT(mounted, argv.size()) << stand;
      EXPECT_EQ(std::count(argv.begin(), argv.end(), stand), 2) << stand << ": one tmpfs, one remount";
      EXPECT_LT(Find(argv, {"--tmpfs", stand.substr(0, stand.rfind('/'))}), mounted) << stand;
      EXPECT_LT(mounted, std::min(bind_raw, Find(argv, {"--ro-bind", "/dev/shm/tools/slam", "/dev/shm/tools/slam"})));
      EXPECT_GT(Find(argv, {"--remount-ro", stand}), std::max(bind_raw, last_bind)) << stand;
    }
    // Bound itself, right in /tmp or outside it: the host's folder (or the read-only root) holds what is in it.
    for (const char* plain : {"/tmp/slam", "/tmp/given", "/data", "/data/run"}) {
      EXPECT_EQ(Find(argv, {"--tmpfs", plain}), argv.size()) << plain;
      EXPECT_EQ(Find(argv, {"--remount-ro", plain}), argv.size()) << plain;
    }
    // The private /tmp itself stays writable: it is the program's scratch.
    EXPECT_EQ(Find(argv, {"--remount-ro", "/tmp"}), argv.size());
  }
}

TEST(BwrapCommandTest, WithoutAFreshProcThereIsNoProcAndProcessOneRefusesUserNamespaces) {
  SandboxSpec spec;
  spec.init_program = "/opt/slamsweep/slamsweep-sandbox-init";
  spec.writable = {"/data/run/raw"};
  spec.fresh_proc = false;
  const std::vector<std::string> argv = BwrapCommand(spec, {"/opt/tool/bin/slam"}, "/data/run/raw", 7);
  EXPECT_EQ(std::count(argv.begin(), argv.end(), "--proc"), 0);
  EXPECT_EQ(std::count(argv.begin(), argv.end(), "/proc"), 0) << "nothing of /proc is bound either";
  // --disable-userns writes through the sandbox's /proc: the seccomp filter of process 1 stands in for it.
  EXPECT_EQ(std::count(argv.begin(), argv.end(), "--disable-userns"), 0);
  const std::size_t init = Find(argv, {"--", "/opt/slamsweep/slamsweep-sandbox-init"});
  ASSERT_LT(init, argv.size());
  EXPECT_LT(Find(argv, {"--no-user-namespaces", "--", "/opt/tool/bin/slam"}), argv.size());
  // Everything else of the isolation stays.
  for (const char* option : {"--unshare-user", "--unshare-pid", "--unshare-net", "--unshare-ipc", "--as-pid-1",
                             "--new-session", "--die-with-parent"}) {
    EXPECT_LT(Find(argv, {option}), init) << option;
  }
  spec.fresh_proc = true;
  const std::vector<std::string> full = BwrapCommand(spec, {"/opt/tool/bin/slam"}, "/data/run/raw", 7);
  EXPECT_EQ(std::count(full.begin(), full.end(), "--no-user-namespaces"), 0);
}

/// A stand-in for bubblewrap: exits 0, except with --proc among its arguments when `refuses_proc`, and
/// always with 1 when `refuses_all`, saying so on stderr as bubblewrap does.
fs::path FakeBwrap(const fs::path& folder, bool refuses_proc, bool refuses_all) {
  const fs::path script = folder / (std::string("bwrap-") + (refuses_all ? "none" : refuses_proc ? "noproc" : "all"));
  std::ofstream out(script);
  out << "#!/bin/sh\n";
  if (refuses_all) out << "echo 'bwrap: No permissions to create new namespace' >&2; exit 1\n";
  if (refuses_proc) {
    out << R"(for a in "$@"; do [ "$a" = --proc ] && { echo "bwrap: Can't mount proc on /newroot/proc: Operation not permitted" >&2; exit 1; }; done)"
        << "\n";
  }
  out << "exit 0\n";
  out.close();
  fs::permissions(script, fs::perms::owner_all);
  return script;
}

TEST(SandboxProcChoiceTest, NoProcOnlyWhereAFreshProcIsRefusedButTheNamespacesAreNot) {
  TempDir dir;
  const SandboxProcChoice refused = ProbeSandboxProc(FakeBwrap(dir.path(), true, false));
  EXPECT_FALSE(refused.fresh_proc);
  EXPECT_NE(refused.why.find("Can't mount proc on /newroot/proc"), std::string::npos) << refused.why;
  // What the worker builds from that choice: no /proc, the filter instead.
  SandboxSpec spec;
  spec.init_program = "/opt/slamsweep/slamsweep-sandbox-init";
  spec.fresh_proc = refused.fresh_proc;
  const std::vector<std::string> argv = BwrapCommand(spec, {"/bin/true"}, "/", 7);
  EXPECT_EQ(std::count(argv.begin(), argv.end(), "--proc"), 0);
  EXPECT_EQ(std::count(argv.begin(), argv.end(), "--no-user-namespaces"), 1);

  EXPECT_TRUE(ProbeSandboxProc(FakeBwrap(dir.path(), false, false)).fresh_proc);
  // No namespaces at all: the runs fail with bubblewrap's own message, as without the probe.
  EXPECT_TRUE(ProbeSandboxProc(FakeBwrap(dir.path(), false, true)).fresh_proc);
  EXPECT_TRUE(ProbeSandboxProc(dir / "no-such-bwrap").fresh_proc);
}

TEST(SandboxProcChoiceTest, TheVariableSaysOwnOrNoneAndNothingElse) {
  EXPECT_TRUE(SandboxProcFromVariable("own").fresh_proc);
  const SandboxProcChoice none = SandboxProcFromVariable("none");
  EXPECT_FALSE(none.fresh_proc);
  EXPECT_EQ(none.why, "SLAMSWEEP_SANDBOX_PROC=none");
  const SandboxProcChoice said = SandboxProcFromVariable("none: a fresh /proc cannot be mounted here (x)");
  EXPECT_FALSE(said.fresh_proc);
  EXPECT_EQ(said.why, "a fresh /proc cannot be mounted here (x)");
  EXPECT_THROW(SandboxProcFromVariable("host"), std::invalid_argument);
  EXPECT_THROW(SandboxProcFromVariable("nonetheless"), std::invalid_argument);
}

class SandboxedProcessTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const SandboxPrograms& programs = FindSandboxPrograms();
    if (!programs.missing.empty()) {
      if (::slamsweep::testing::RunningInCi()) FAIL() << programs.missing;
      GTEST_SKIP() << programs.missing;
    }
    fs::create_directories(dir_ / "raw");
    ::chmod(dir_.path().c_str(), 0755);
    ::chmod((dir_ / "raw").c_str(), 0777);
    sandbox_.bwrap_program = programs.bwrap;
    sandbox_.init_program = programs.init;
    sandbox_.writable = {dir_ / "raw"};
    sandbox_.process_limit = 32;
    sandbox_.file_size_limit_bytes = 1 << 20;
    if (::geteuid() == 0) sandbox_.user = SandboxSpec::User{65534, 65534};
  }

  ProcessOutcome Run(const std::string& script, double timeout_s = 60) {
    ProcessSpec spec = testing::Sh(script, dir_ / "log.txt");
    spec.working_dir = dir_ / "raw";
    spec.sandbox = sandbox_;
    spec.timeout_s = timeout_s;
    return RunProcess(spec);
  }

  std::string Log() { return ReadAll(dir_ / "log.txt"); }

  TempDir dir_;
  SandboxSpec sandbox_;
};

TEST_F(SandboxedProcessTest, TheExactStatusComesBackWhetherSignalledOrExitedWith128PlusN) {
  ProcessOutcome outcome = Run("kill -SEGV $$");
  EXPECT_EQ(outcome.ending, ProcessEnding::kSignaled) << outcome.reason << Log();
  EXPECT_EQ(outcome.signal, SIGSEGV);
  outcome = Run("exit 139");
  EXPECT_EQ(outcome.ending, ProcessEnding::kExited) << outcome.reason << Log();
  EXPECT_EQ(outcome.exit_code, 139);
  outcome = Run("echo hello > out.txt");
  EXPECT_TRUE(outcome.ok()) << outcome.reason << Log();
  EXPECT_EQ(ReadAll(dir_ / "raw" / "out.txt"), "hello\n");
  // The program's own time and memory, through bubblewrap and the sandbox's process 1.
  outcome = Run("i=0; while [ $i -lt 200000 ]; do i=$((i+1)); done");
  EXPECT_GT(outcome.cpu_s, 0.05) << outcome.reason;
  EXPECT_GT(outcome.peak_rss_kb, 500);
}

TEST_F(SandboxedProcessTest, OnlyTheSystemAndTheGivenFoldersExistInAnOwnNamespaceWithoutNetwork) {
  std::ofstream(dir_ / "secret.txt") << "truth\n";
  const ProcessOutcome outcome =
      Run("ls / | tr '\\n' ' '; echo; for p in " + (dir_ / "secret.txt").string() +
          " /etc/shadow /etc/ssh; do [ -e $p ] && echo VISIBLE $p; done; "
          "for f in /home /root /var; do [ -e $f ] && echo LISTED $f $(ls -A $f); done; "
          "echo pids $(ls /proc | grep -c '^[0-9]'); grep -c : /proc/net/dev; id -u; "
          "grep CapEff /proc/self/status; echo x > /etc/x 2>/dev/null && echo WROTE-ETC; true");
  EXPECT_TRUE(outcome.ok()) << outcome.reason << Log();
  const std::string log = Log();
  EXPECT_EQ(log.find("VISIBLE"), std::string::npos) << log;
  // Nothing of the host's home, root or service folders: where process 1 or raw/ lies in one (a checkout
  // under /var/tmp or /home), only the folder leading to it exists there.
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string word, folder;
    if (!(words >> word >> folder) || word != "LISTED") continue;
    std::set<std::string> leading;
    for (const fs::path& bound : {sandbox_.init_program, dir_ / "raw"}) {
      const fs::path relative = bound.lexically_relative(folder);
      if (!relative.empty() && *relative.begin() != "..") leading.insert(relative.begin()->string());
    }
    EXPECT_FALSE(leading.empty()) << folder << " exists with nothing bound in it: " << line;
    for (std::string entry; words >> entry;) EXPECT_TRUE(leading.count(entry)) << folder << " shows " << entry;
  }
  EXPECT_EQ(log.find("WROTE-ETC"), std::string::npos) << log;
  // The shell, a subshell or two, ls and the sandbox's process 1: a handful, not the host's.
  EXPECT_NE(log.find("pids "), std::string::npos) << log;
  EXPECT_LT(std::stoi(log.substr(log.find("pids ") + 5)), 8) << log;
  // Loopback only: the header line of /proc/net/dev has no ':', so the count is of interfaces.
  EXPECT_NE(log.find("\n1\n"), std::string::npos) << log;
  EXPECT_NE(log.find("CapEff:\t0000000000000000"), std::string::npos) << log;
}

TEST_F(SandboxedProcessTest, NothingButRawIsWritableAroundTheRunFolderWhereverItIs) {
  // Under the sandbox's own /tmp and /dev/shm bubblewrap makes the run folder's parents itself; elsewhere
  // (/var/tmp, never under /tmp) the host's folders are not shown and the root is read-only.
  for (const fs::path& base : {fs::path("/tmp"), fs::path("/dev/shm"), fs::path("/var/tmp")}) {
    const fs::path top = base / (dir_.path().filename().string() + "-run");
    const fs::path run = top / "out" / "runs" / "r0";
    fs::create_directories(run / "input");
    fs::create_directories(run / "raw");
    for (const fs::path& folder : {top, top / "out", top / "out" / "runs", run, run / "input"}) {
      ::chmod(folder.c_str(), 0755);
    }
    ::chmod((run / "raw").c_str(), 0777);
    SandboxSpec sandbox = sandbox_;
    sandbox.read_only = {run / "input"};
    sandbox.writable = {run / "raw"};
    const std::vector<fs::path> beside = {run / "beside", run / "input" / "beside", top / "out" / "beside",
                                          top / "beside", run / "newdir"};
    std::string script;
    for (std::size_t i = 0; i + 1 < beside.size(); ++i) {
      script += "(echo x > " + beside[i].string() + ") 2>/dev/null && echo WROTE " + beside[i].string() + "; ";
    }
    script += "mkdir " + beside.back().string() + " 2>/dev/null && echo WROTE " + beside.back().string() + "; ";
    script += "echo x > /tmp/scratch && echo scratch ok; echo x > out.txt";
    ProcessSpec spec = testing::Sh(script, dir_ / "log.txt");
    spec.working_dir = run / "raw";
    spec.sandbox = sandbox;
    const ProcessOutcome outcome = RunProcess(spec);
    const std::string log = Log();
    EXPECT_TRUE(outcome.ok()) << base << ": " << outcome.reason << log;
    // In the sandbox: every write beside raw/ refused, the private /tmp writable.
    EXPECT_EQ(log.find("WROTE"), std::string::npos) << base << ": " << log;
    EXPECT_NE(log.find("scratch ok"), std::string::npos) << base << ": " << log;
    // On the host: raw/ got its output and nothing else was made.
    EXPECT_EQ(ReadAll(run / "raw" / "out.txt"), "x\n") << base;
    for (const fs::path& path : beside) EXPECT_FALSE(fs::exists(path)) << path;
    fs::remove_all(top);
  }
}

TEST_F(SandboxedProcessTest, NoNestedUserNamespaceWithOrWithoutAProc) {
  // unshare(1) reports the refused system call; threads still start (clone3 refused, the C library falls back).
  const std::string script =
      "unshare -U true 2>&1; echo nested=$?; ls /proc >/dev/null 2>&1; echo proc=$?; "
      "/usr/bin/python3 -c 'import threading; t = threading.Thread(target=print, args=(\"thread ran\",)); t.start(); "
      "t.join()'";
  for (const bool fresh_proc : {true, false}) {
    sandbox_.fresh_proc = fresh_proc;
    const ProcessOutcome outcome = Run(script);
    const std::string log = Log();
    EXPECT_TRUE(outcome.ok()) << outcome.reason << log;
    EXPECT_NE(log.find("nested=1"), std::string::npos) << "fresh_proc " << fresh_proc << ": " << log;
    EXPECT_NE(log.find(fresh_proc ? "proc=0" : "proc=2"), std::string::npos) << log;
    EXPECT_NE(log.find("thread ran"), std::string::npos) << log;
  }
  // Without the filter and without --disable-userns, the same sandbox would allow one: the check can fail.
  sandbox_.fresh_proc = false;
  // Process 1's status line goes to descriptor 2, which it closes for the program: the echo is on stdout.
  std::vector<std::string> argv =
      BwrapCommand(sandbox_, {"/bin/sh", "-c", "unshare -U true; echo nested=$?"}, dir_ / "raw", 2);
  argv.erase(std::find(argv.begin(), argv.end(), "--no-user-namespaces"));
  ProcessSpec unfiltered;
  unfiltered.argv = {argv.begin(), argv.end()};
  unfiltered.working_dir = dir_ / "raw";
  unfiltered.log_path = dir_ / "unfiltered.txt";
  const ProcessOutcome allowed = RunProcess(unfiltered);
  EXPECT_TRUE(allowed.ok()) << allowed.reason;
  EXPECT_NE(ReadAll(dir_ / "unfiltered.txt").find("nested=0"), std::string::npos) << ReadAll(dir_ / "unfiltered.txt");
}

TEST_F(SandboxedProcessTest, AForkStormEndsAtTheProcessLimitAndNothingOutlivesTheRun) {
  // Like a fork bomb, it holds what it started and keeps trying.
  const ProcessOutcome outcome =
      Run("(setsid sleep 300 &); exec /usr/bin/python3 -c 'import os, time\n"
          "for i in range(100):\n"
          "  try:\n"
          "    if os.fork() == 0: time.sleep(30); os._exit(0)\n"
          "  except OSError: pass\n"
          "time.sleep(30)'",
          60);
  EXPECT_EQ(outcome.ending, ProcessEnding::kProcessLimit) << outcome.reason << Log();
  EXPECT_NE(outcome.reason.find("process_limit"), std::string::npos) << outcome.reason;
  EXPECT_LT(outcome.wall_s, 30.0);
}

TEST_F(SandboxedProcessTest, APidsCgroupCountsEveryForkItRefusesWhereOneCanBeMade) {
  std::string why;
  std::unique_ptr<PidsCgroup> cgroup = PidsCgroup::Create(16, why);
  if (!cgroup) {
    // The fallback (RLIMIT_NPROC, the other tests here) is what such a machine uses; say why.
    EXPECT_FALSE(why.empty());
    std::cout << "no pids cgroup here: " << why << "\n";
    return;
  }
  const fs::path folder = cgroup->ProcsFile().parent_path();
  sandbox_.user.reset();
  sandbox_.process_limit = 0;
  sandbox_.pids_cgroup_procs = cgroup->ProcsFile();
  // Gives up at once on its first refused fork: no sampling would see it, the cgroup does.
  const ProcessOutcome outcome = Run("i=0; while [ $i -lt 40 ]; do sleep 30 & i=$((i+1)); done");
  EXPECT_FALSE(outcome.ok()) << Log();
  EXPECT_GE(cgroup->Refusals(), 1u);
  cgroup.reset();
  EXPECT_FALSE(fs::exists(folder)) << "the cgroup is removed with its object";
}

TEST_F(SandboxedProcessTest, AFileOverTheLimitEndsTheWriterWithSigxfsz) {
  const ProcessOutcome outcome = Run("exec head -c 2000000 /dev/zero > big");
  EXPECT_EQ(outcome.ending, ProcessEnding::kSignaled) << outcome.reason << Log();
  EXPECT_EQ(outcome.signal, SIGXFSZ);
  EXPECT_EQ(fs::file_size(dir_ / "raw" / "big"), 1u << 20);
}

TEST_F(SandboxedProcessTest, MemoryIsCountedOverEverythingTheProgramStarted) {
  ProcessSpec spec = testing::Sh(
      "setsid sh -c 'head -c 300000000 /dev/zero | tail -c 300000000 >/dev/null; sleep 30' & wait", dir_ / "log.txt");
  spec.working_dir = dir_ / "raw";
  spec.sandbox = sandbox_;
  spec.memory_limit_mb = 100;
  spec.timeout_s = 60;
  const ProcessOutcome outcome = RunProcess(spec);
  EXPECT_EQ(outcome.ending, ProcessEnding::kMemoryLimit) << outcome.reason << Log();
}

}  // namespace
}  // namespace slamsweep::orchestrator
