// The service's parts without processes: token files, the constant-time check, loopback addresses,
// the pages' escaping, the metrics text (read back by the Prometheus project's own parser), the queue.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include "orchestrator/config/input_policy.h"
#include "orchestrator/service/auth.h"
#include "orchestrator/service/leftover_workers.h"
#include "orchestrator/service/queue_store.h"
#include "orchestrator/service/service_metrics.h"
#include "orchestrator/service/status_page.h"
#include "tests/orchestrator/service/queued_sweep_fixture.h"
#include "tests/support/child_process.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator::service {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

TEST(TokenFileTest, OnlyAPrivateFileOfTheServersUserIsAccepted) {
  testing::TempDir dir;
  const fs::path file = testing::WriteFile(dir / "token", "  tok-123\n");
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write, fs::perm_options::replace);
  EXPECT_EQ(ReadTokenFile(file), "tok-123");
  fs::permissions(file, fs::perms::owner_read, fs::perm_options::replace);
  EXPECT_EQ(ReadTokenFile(file), "tok-123");
  for (const fs::perms extra : {fs::perms::group_read, fs::perms::others_read, fs::perms::others_write}) {
    fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write | extra, fs::perm_options::replace);
    EXPECT_THROW(ReadTokenFile(file), evaluator::InputError);
  }
  const fs::path empty = testing::WriteFile(dir / "empty", "\n");
  fs::permissions(empty, fs::perms::owner_read | fs::perms::owner_write, fs::perm_options::replace);
  EXPECT_THROW(ReadTokenFile(empty), evaluator::InputError);
  EXPECT_THROW(ReadTokenFile(dir / "missing"), evaluator::InputError);
  EXPECT_THROW(ReadTokenFile(dir.path()), evaluator::InputError);
}

TEST(BearerAuthTest, AcceptsOnlyTheExactToken) {
  const BearerAuth auth(std::string("tok-123"));
  EXPECT_EQ(auth.Check(std::string_view("Bearer tok-123")), BearerAuth::Verdict::kAllowed);
  EXPECT_EQ(auth.Check(std::nullopt), BearerAuth::Verdict::kMissing);
  EXPECT_EQ(auth.Check(std::string_view("Basic dG9rLTEyMw==")), BearerAuth::Verdict::kMissing);
  EXPECT_EQ(auth.Check(std::string_view("Bearer ")), BearerAuth::Verdict::kMissing);
  for (const char* wrong :
       {"Bearer tok-12", "Bearer tok-1234", "Bearer TOK-123", "Bearer xok-123", "Bearer tok-12\x00"}) {
    EXPECT_EQ(auth.Check(std::string_view(wrong)), BearerAuth::Verdict::kWrong) << wrong;
  }
  const BearerAuth open(std::nullopt);
  EXPECT_EQ(open.Check(std::nullopt), BearerAuth::Verdict::kAllowed);
  EXPECT_FALSE(open.enabled());
}

TEST(LoopbackTest, OnlyThisMachinesAddresses) {
  for (const char* host : {"127.0.0.1", "127.1.2.3", "::1", "localhost"}) EXPECT_TRUE(IsLoopbackAddress(host)) << host;
  for (const char* host : {"0.0.0.0", "10.0.0.1", "::", "128.0.0.1", "example.org", "::ffff:10.0.0.1"}) {
    EXPECT_FALSE(IsLoopbackAddress(host)) << host;
  }
}

TEST(InputPolicyTest, PathsAreCheckedAfterResolvingDotsAndLinks) {
  testing::TempDir dir;
  fs::create_directories(dir / "data" / "sets");
  fs::create_directories(dir / "data" / "sets-private");
  fs::create_symlink("/etc", dir / "data" / "sets" / "escape");
  InputPolicy policy;
  policy.allowed_roots = {dir / "data" / "sets"};
  EXPECT_TRUE(IsAllowedPath(policy, dir / "data" / "sets" / "a.log"));
  EXPECT_TRUE(IsAllowedPath(policy, dir / "data" / "sets" / "sub" / ".." / "a.log"));
  EXPECT_FALSE(IsAllowedPath(policy, dir / "data" / "sets" / ".." / "sets-private" / "a.log"));
  EXPECT_FALSE(IsAllowedPath(policy, dir / "data" / "sets-private" / "a.log")) << "a sibling sharing the prefix";
  EXPECT_FALSE(IsAllowedPath(policy, dir / "data" / "sets" / "escape" / "passwd")) << "a link out of the root";
  EXPECT_FALSE(IsAllowedPath(policy, "/etc/passwd"));
  EXPECT_TRUE(IsAllowedPath(InputPolicy{}, "/etc/passwd")) << "no roots: the command line's trust";
}

TEST(StatusPageTest, SubmittedTextIsEscapedEverywhere) {
  EXPECT_EQ(HtmlEscape("<a href=\"x\">'&'</a>"), "&lt;a href=&quot;x&quot;&gt;&#39;&amp;&#39;&lt;/a&gt;");
  SweepView view;
  view.sweep.id = 7;
  view.sweep.name = "n<i>";
  view.sweep.submitter = "\"><img src=x>";
  view.sweep.config_name = "<c>.yaml";
  view.sweep.message = "<m>";
  view.sweep.state = QueuedSweepState::kRunning;
  const std::string index = RenderIndexPage({view}, QueueGauges{});
  const std::string page =
      RenderSweepPage(view, {RunView{"r<1>", QueuedRunState::kFailed, 1, std::nullopt, 1.5, "<reason>"}});
  for (const std::string& html : {index, page}) {
    EXPECT_EQ(html.find("<i>"), std::string::npos);
    EXPECT_EQ(html.find("<img"), std::string::npos);
    EXPECT_EQ(html.find("style="), std::string::npos) << "no inline style";
    EXPECT_EQ(html.find("<script"), std::string::npos);
  }
  EXPECT_THAT(page, HasSubstr("&lt;reason&gt;"));
  EXPECT_THAT(index, HasSubstr("<meta http-equiv=\"refresh\""));
  EXPECT_THAT(index, HasSubstr("href=\"/static/service.css\""));
}

TEST(ServiceMetricsTest, TheTextIsValidPrometheusExpositionFormat) {
  ServiceMetrics metrics;
  metrics.RunFinished(QueuedRunState::kOk, 3.0, true);
  metrics.RunFinished(QueuedRunState::kOk, 90.0, true);
  metrics.RunFinished(QueuedRunState::kFailed, 0.5, true);
  metrics.RunFinished(QueuedRunState::kReused, 0.0, false);
  metrics.SchedulingOverhead(0.004);
  metrics.HttpRequest(200, 0.0007);
  metrics.HttpRequest(429, 0.0002);
  QueueGauges gauges;
  gauges.runs_queued = 12;
  gauges.runs_running = 2;
  gauges.slots = 2;
  gauges.sweeps_by_state = {{QueuedSweepState::kRunning, 1}, {QueuedSweepState::kOk, 3}};
  testing::TempDir dir;
  testing::WriteFile(dir / "metrics.txt", metrics.Render(gauges));
  // The official client library's parser, an independent reader of the format.
  const std::string script =
      "import sys\n"
      "from prometheus_client.parser import text_string_to_metric_families\n"
      "values = {}\n"
      "for family in text_string_to_metric_families(open(sys.argv[1]).read()):\n"
      "    for sample in family.samples:\n"
      "        values[sample.name + str(sorted(sample.labels.items()))] = sample.value\n"
      "print(values[\"slamsweep_queue_depth[]\"], values[\"slamsweep_runs_running[]\"],\n"
      "      values[\"slamsweep_runs_finished_total[('status', 'ok')]\"],\n"
      "      values[\"slamsweep_run_duration_seconds_bucket[('le', '5')]\"],\n"
      "      values[\"slamsweep_run_duration_seconds_count[]\"],\n"
      "      values[\"slamsweep_sweeps[('state', 'ok')]\"])\n";
  testing::WriteFile(dir / "parse.py", script);
  const std::string command = "/usr/bin/python3 " + (dir / "parse.py").string() + " " + (dir / "metrics.txt").string() +
                              " > " + (dir / "parsed.txt").string() + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << std::ifstream(dir / "parsed.txt").rdbuf();
  std::ifstream parsed(dir / "parsed.txt");
  std::string line;
  std::getline(parsed, line);
  // 12 queued, 2 running, 2 ok finished, 2 runs <= 5 s (0.5 and 3), 3 runs timed, 3 ok sweeps.
  EXPECT_EQ(line, "12.0 2.0 2.0 2.0 3.0 3.0");
}

TEST(QueueStoreTest, ARestartQueuesTheRunsLeftRunning) {
  testing::TempDir dir;
  QueueStore queue = QueueStore::Open(dir / "queue.sqlite");
  const QueuedSweep added =
      queue.AddSweep(SweepNamedS(), {{{"run_id", "a"}}, {{"run_id", "b"}}, {{"run_id", "c"}}}, dir / "sweeps");
  EXPECT_EQ(added.id, 1);
  EXPECT_EQ(added.result_dir, dir / "sweeps" / "1");
  queue.SetRunState(1, "a", QueuedRunState::kOk, true, 2.0);
  queue.SetRunState(1, "b", QueuedRunState::kRunning, true);
  EXPECT_EQ(queue.RequeueRunning(), 1u);
  const std::vector<QueuedRun> runs = queue.Runs(1);
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_EQ(runs[0].state, QueuedRunState::kOk);
  EXPECT_EQ(runs[1].state, QueuedRunState::kQueued);
  EXPECT_EQ(runs[1].attempt, 1);
  EXPECT_EQ(queue.SweepsWithOkRun("a", 2), std::vector<std::int64_t>{1});
  EXPECT_TRUE(queue.SweepsWithOkRun("a", 1).empty());
  EXPECT_EQ(queue.AddSweep(SweepNamedS(), {}, dir / "sweeps").id, 2);
}

}  // namespace
}  // namespace slamsweep::orchestrator::service

namespace slamsweep::orchestrator::service {
namespace {

// A killed server's Slurm arrays are cancelled on restart; everyone else's are left alone. Stand-in
// squeue/scancel on PATH: squeue lists two jobs until scancel was called for ours.
TEST(LeftoverSlurmJobsTest, OnlyTheArraysOfThisServersStateFolderAreCancelled) {
  testing::TempDir dir;
  const fs::path bin = dir / "bin", state = dir / "data" / "slurm";
  fs::create_directories(bin);
  fs::create_directories(state);
  testing::WriteFile(bin / "squeue",
                     "#!/bin/sh\n"
                     "echo \"77|/home/other/job.sh\"\n"
                     "if ! grep -qx 41 \"" +
                         (dir / "cancelled").string() +
                         "\" 2>/dev/null; then\n"
                         "  echo \"41|" +
                         state.string() + "/array-9-0.sh\"\nfi\n");
  testing::WriteFile(bin / "scancel", "#!/bin/sh\necho \"$1\" >> \"" + (dir / "cancelled").string() + "\"\n");
  fs::permissions(bin / "squeue", fs::perms::owner_all);
  fs::permissions(bin / "scancel", fs::perms::owner_all);
  const std::string saved_path = std::getenv("PATH");
  setenv("PATH", (bin.string() + ":" + saved_path).c_str(), 1);
  const std::vector<std::string> cancelled = EndLeftoverSlurmJobs(state, 10.0);
  setenv("PATH", saved_path.c_str(), 1);
  EXPECT_EQ(cancelled, std::vector<std::string>{"41"});
  std::ifstream log(dir / "cancelled");
  std::string line, all;
  while (std::getline(log, line)) all += line + ";";
  EXPECT_EQ(all, "41;");
}

/// A stand-in for a worker that its killed server left: a process whose command line is exactly
/// `PROGRAM worker RUN_DIR` (/bin/sh under another argv[0], running the script `worker` in
/// `script_dir`, outside every sweep), in a process group of its own like a real worker.
pid_t StartStandInWorker(const fs::path& script_dir, const std::string& program, const fs::path& run_dir) {
  const pid_t pid = fork();
  if (pid == 0) {
    setpgid(0, 0);
    if (chdir(script_dir.c_str()) != 0) _exit(127);
    execl("/bin/sh", program.c_str(), "worker", run_dir.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

/// The NUL-separated command line of `pid`, once it shows `worker` (after the exec).
std::string WorkerCommandLine(pid_t pid) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  std::string text;
  while (std::chrono::steady_clock::now() < deadline) {
    std::ifstream in("/proc/" + std::to_string(pid) + "/cmdline", std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    text = bytes.str();
    if (text.find(std::string("\0worker\0", 8)) != std::string::npos) return text;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return text;
}

/// Waits until the stand-in's `sleep` child has exec'd: until then the forked shell shows the
/// stand-in's own worker command line and would be counted as a third leftover.
bool WaitForSleepingChild(pid_t pid) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  const std::string id = std::to_string(pid);
  while (std::chrono::steady_clock::now() < deadline) {
    std::ifstream children("/proc/" + id + "/task/" + id + "/children");
    pid_t child = 0;
    while (children >> child) {
      std::ifstream in("/proc/" + std::to_string(child) + "/cmdline", std::ios::binary);
      std::stringstream bytes;
      bytes << in.rdbuf();
      if (bytes.str() == std::string("sleep\0"
                                     "60\0",
                                     9))
        return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

// Workers run as `slamsweep-sweep worker RUN_DIR` (the sweep helper that runs serve), or, when
// SLAMSWEEP_WORKER_PROGRAM names the core, start as `slamsweep worker RUN_DIR`: a restarted server
// ends both when RUN_DIR lies under its sweeps folder, and a worker of another data folder never.
TEST(LeftoverProcessesTest, WorkersOfTheSweepHelperAndTheCoreUnderTheSweepsFolderAreEnded) {
  testing::TempDir dir;
  const fs::path sweeps = dir / "data" / "sweeps", script_dir = dir / "bin";
  fs::create_directories(script_dir);
  testing::WriteFile(script_dir / "worker", "sleep 60 &\nwait\n");
  const fs::path ours_helper = sweeps / "1" / "runs" / "a", ours_core = sweeps / "2" / "runs" / "b";
  const fs::path theirs = dir / "other-data" / "sweeps" / "1" / "runs" / "c";
  const pid_t helper = StartStandInWorker(script_dir, "/opt/slamsweep/lib/slamsweep/slamsweep-sweep", ours_helper);
  const pid_t core = StartStandInWorker(script_dir, "/opt/slamsweep/bin/slamsweep", ours_core);
  const pid_t other = StartStandInWorker(script_dir, "/opt/slamsweep/lib/slamsweep/slamsweep-sweep", theirs);
  const std::string nul(1, '\0');
  ASSERT_EQ(WorkerCommandLine(helper),
            "/opt/slamsweep/lib/slamsweep/slamsweep-sweep" + nul + "worker" + nul + ours_helper.string() + nul);
  ASSERT_EQ(WorkerCommandLine(core), "/opt/slamsweep/bin/slamsweep" + nul + "worker" + nul + ours_core.string() + nul);
  ASSERT_THAT(WorkerCommandLine(other), HasSubstr(nul + "worker" + nul + theirs.string()));
  for (const pid_t stand_in : {helper, core, other}) ASSERT_TRUE(WaitForSleepingChild(stand_in)) << stand_in;

  EXPECT_THAT(FindLeftoverProcesses(sweeps), ::testing::UnorderedElementsAre(helper, core));
  EXPECT_EQ(EndLeftoverProcesses(sweeps, 10.0), 2u);
  EXPECT_EQ(slamsweep::testing::WaitExit(helper, std::chrono::seconds(10)), 128 + SIGTERM);
  EXPECT_EQ(slamsweep::testing::WaitExit(core, std::chrono::seconds(10)), 128 + SIGTERM);
  EXPECT_EQ(::kill(other, 0), 0) << "another server's worker was ended";
  ::kill(-other, SIGKILL);
  slamsweep::testing::WaitExit(other, std::chrono::seconds(10));
}

}  // namespace
}  // namespace slamsweep::orchestrator::service
