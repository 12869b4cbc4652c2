// The real `slamsweep serve` and `slamsweep submit` processes: the API round trip against a plain
// `slamsweep run` of the same config, the answers to bad and hostile requests, reuse of identical runs
// across sweeps, cancel, kill -9 and restart, SIGTERM drain.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <set>

#include "tests/orchestrator/service/service_process.h"

namespace slamsweep {
namespace {

using namespace service_testing;
using ::testing::HasSubstr;
using ::testing::Not;

constexpr auto kLong = std::chrono::seconds(240);

std::map<std::string, nlohmann::json> RunsById(const nlohmann::json& summary) {
  std::map<std::string, nlohmann::json> runs;
  for (const auto& run : summary.at("runs")) runs[run.at("run_id").get<std::string>()] = run;
  return runs;
}

std::multiset<std::string> TestcaseNames(const std::string& junit) {
  std::multiset<std::string> names;
  for (std::size_t at = junit.find("<testcase "); at != std::string::npos; at = junit.find("<testcase ", at + 1)) {
    const std::size_t name = junit.find(" name=\"", at);
    names.insert(junit.substr(name + 7, junit.find('"', name + 7) - name - 7));
  }
  return names;
}

std::size_t SweepFolders(const fs::path& data) {
  std::size_t count = 0;
  if (!fs::exists(data / "sweeps")) return 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(data / "sweeps")) ++count;
  return count;
}

class ServiceApiTest : public ::testing::Test {
 protected:
  testing::TempDir dir_;
};

// submit --wait into the service gives the same runs, metrics and JUnit cases as `slamsweep run`, in a
// result directory with run's layout that `slamsweep report` reads.
TEST_F(ServiceApiTest, SubmitWaitEqualsAPlainRunOfTheSameConfig) {
  const fs::path config = testing::WriteFile(dir_ / "odometry.yaml",
                                             "name: roundtrip\niterations: 3\nseed: 7\nevaluation: {stages: 4}\n"
                                             "algorithms:\n  - {name: odometry, adapter: odometry, timeout_s: 60}\n"
                                             "sequences:\n  - {catalog: simulated-floor, name: floor, max_scans: 60}\n"
                                             "noise:\n  - name: noisy\n    odometry: {alpha1: 0.01, alpha3: 0.01}\n");
  ASSERT_EQ(RunToEnd({SLAMSWEEP_BINARY, "run", config.string(), "--output", (dir_ / "plain").string(), "--no-report"},
                     dir_ / "run.log", kLong),
            0)
      << ReadAll(dir_ / "run.log");
  Server server(dir_ / "data", {"--jobs", "2"}, dir_ / "serve.log");
  ASSERT_TRUE(server.listening()) << server.Log();
  const int code =
      RunToEnd({SLAMSWEEP_BINARY, "submit", config.string(), "--server", server.url(), "--wait", "--poll", "0.2",
                "--junit", (dir_ / "got" / "junit.xml").string(), "--report", (dir_ / "got" / "report").string()},
               dir_ / "submit.log", kLong);
  const std::string submit_log = ReadAll(dir_ / "submit.log");
  ASSERT_EQ(code, 0) << submit_log << server.Log();
  EXPECT_THAT(submit_log, HasSubstr("[3/3] ok"));

  const fs::path result_dir = dir_ / "data" / "sweeps" / "1";
  for (const char* file :
       {"results.sqlite", "summary.json", "summary.csv", "runs.csv", "junit.xml", "report/index.html"}) {
    EXPECT_TRUE(fs::exists(result_dir / file)) << file;
  }
  const auto plain = RunsById(nlohmann::json::parse(ReadAll(dir_ / "plain" / "summary.json")));
  const auto served = RunsById(nlohmann::json::parse(ReadAll(result_dir / "summary.json")));
  ASSERT_EQ(plain.size(), 3u);
  ASSERT_EQ(served.size(), plain.size());
  for (const auto& [run_id, run] : plain) {
    ASSERT_EQ(served.count(run_id), 1u) << run_id;
    EXPECT_EQ(served.at(run_id).at("status"), "ok");
    EXPECT_EQ(served.at(run_id).at("metrics"), run.at("metrics")) << run_id;
    EXPECT_TRUE(run.at("metrics").contains("ape_trans")) << "nothing compared for " << run_id;
    EXPECT_TRUE(fs::exists(result_dir / "runs" / run_id / "result.json"));
  }
  EXPECT_EQ(TestcaseNames(ReadAll(dir_ / "got" / "junit.xml")), TestcaseNames(ReadAll(dir_ / "plain" / "junit.xml")));
  EXPECT_EQ(TestcaseNames(ReadAll(dir_ / "got" / "junit.xml")).size(), 3u);
  EXPECT_TRUE(fs::exists(dir_ / "got" / "report" / "index.html"));
  // The result directory is an ordinary one: the report command reads it.
  EXPECT_EQ(RunToEnd({SLAMSWEEP_BINARY, "report", result_dir.string(), "-o", (dir_ / "again").string()},
                     dir_ / "report.log", kLong),
            0)
      << ReadAll(dir_ / "report.log");
  EXPECT_EQ(server.Signal(SIGTERM, std::chrono::seconds(60)), 0) << server.Log();
}

TEST_F(ServiceApiTest, AConfigErrorIs400WithTheMessageOfPlan) {
  const std::string yaml = "name: broken\nalgorithms:\n  - name: x\n    adapter: nope\nsequences: [simulated-floor]\n";
  testing::WriteFile(dir_ / "broken.yaml", yaml);
  // `plan broken.yaml` from the sweep's folder, as the submitter typed it.
  const pid_t plan = fork();
  if (plan == 0) {
    if (chdir(dir_.path().c_str()) != 0) _exit(127);
    const int fd = ::open("plan.log", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 2);
    execl(SLAMSWEEP_BINARY, SLAMSWEEP_BINARY, "plan", "broken.yaml", static_cast<char*>(nullptr));
    _exit(127);
  }
  ASSERT_EQ(WaitExit(plan, std::chrono::seconds(60)), 2);
  std::string expected = ReadAll(dir_ / "plan.log");
  ASSERT_THAT(expected, HasSubstr("broken.yaml:4:14:"));
  expected = expected.substr(std::string("slamsweep: error: ").size());
  expected.pop_back();  // newline

  Server server(dir_ / "data", {}, dir_ / "serve.log");
  ASSERT_TRUE(server.listening()) << server.Log();
  const auto [status, body] = PostSweep(server, yaml, "name=broken.yaml&base=" + dir_.path().string());
  EXPECT_EQ(status, 400);
  EXPECT_EQ(body.value("error", ""), expected);
  EXPECT_EQ(SweepFolders(dir_ / "data"), 0u);
}

TEST_F(ServiceApiTest, BadAndHostileRequestsGet4xxAndLeaveNothingBehind) {
  const fs::path token = testing::WriteFile(dir_ / "token", "s3cret-token-value\n");
  fs::permissions(token, fs::perms::owner_read | fs::perms::owner_write);
  Server server(dir_ / "data", {"--token-file", token.string(), "--max-runs", "50", "--max-body-kb", "16"},
                dir_ / "serve.log");
  ASSERT_TRUE(server.listening()) << server.Log();
  const httplib::Headers auth = {{"Authorization", "Bearer s3cret-token-value"}};
  const std::string good =
      "name: fine\nalgorithms:\n  - {name: odometry, adapter: odometry}\n"
      "sequences:\n  - {catalog: simulated-floor, name: floor, max_scans: 20}\n";
  // 401 without or with a wrong token; the log says why but never shows a token.
  EXPECT_EQ(PostSweep(server, good).first, 401);
  EXPECT_EQ(PostSweep(server, good, "name=a.yaml", {{"Authorization", "Bearer not-the-token-at-all"}}).first, 401);
  EXPECT_EQ(PostSweep(server, good, "name=a.yaml", {{"Authorization", "Basic czNjcmV0"}}).first, 401);
  EXPECT_THAT(server.Log(), HasSubstr("wrong bearer token"));
  EXPECT_THAT(server.Log(), Not(HasSubstr("not-the-token-at-all")));
  EXPECT_THAT(server.Log(), Not(HasSubstr("s3cret-token-value")));
  auto client = server.Client();
  EXPECT_EQ(client.Post("/api/sweeps/1/cancel", "", "text/plain")->status, 401);

  struct Case {
    std::string what;
    std::string yaml;
    std::string query;
    int status;
  };
  const std::vector<Case> cases = {
      {"broken YAML", "name: [unclosed\n", "name=x.yaml", 400},
      {"not a map", "- just\n- a list\n", "name=x.yaml", 400},
      {"huge iterations",
       "name: big\niterations: 1000000\nalgorithms:\n  - {name: odometry, adapter: odometry}\n"
       "sequences: [simulated-floor]\n",
       "name=x.yaml", 413},
      {"more runs than the limit",
       "name: big\niterations: 51\nalgorithms:\n  - {name: odometry, adapter: odometry}\n"
       "sequences: [simulated-floor]\n",
       "name=x.yaml", 413},
      {"a number beyond 64 bits",
       "name: big\nseed: 99999999999999999999999999\nalgorithms:\n"
       "  - {name: odometry, adapter: odometry}\nsequences: [simulated-floor]\n",
       "name=x.yaml", 400},
      {"path escape",
       "name: escape\nalgorithms:\n  - {name: odometry, adapter: odometry}\nsequences:\n"
       "  - {name: x, format: carmen, ground_truth: none, path: ../../../../../../etc/passwd}\n",
       "name=x.yaml", 403},
      {"catalog outside the roots",
       "name: escape\ncatalog: /etc/passwd\nalgorithms:\n"
       "  - {name: odometry, adapter: odometry}\nsequences: [x]\n",
       "name=x.yaml", 403},
      {"command adapter",
       "name: cmd\nalgorithms:\n  - name: c\n    adapter: command\n    command: {argv: [/bin/sh, "
       "-c, \"touch /tmp/owned\"], trajectory: {path: t.tum, format: tum}}\n"
       "sequences: [simulated-floor]\n",
       "name=x.yaml", 403},
      {"network without --allow-network",
       "name: net\nalgorithms:\n  - {name: odometry, adapter: odometry, network: true}\n"
       "sequences: [simulated-floor]\n",
       "name=x.yaml", 403},
      {"HTML in the sweep name", "name: \"<script>alert(1)</script>\"\n" + good.substr(good.find('\n') + 1),
       "name=x.yaml", 400},
      {"markup and shell in an algorithm name",
       "name: names\nalgorithms:\n  - {name: \"<b>$(reboot)</b>\", adapter: odometry}\n"
       "sequences:\n  - {catalog: simulated-floor, name: floor, max_scans: 20}\n",
       "name=x.yaml", 400},
      {"bad priority", good, "name=x.yaml&priority=1e999", 400},
      {"priority out of range", good, "name=x.yaml&priority=101", 400},
      {"relative base", good, "name=x.yaml&base=../..", 400},
      {"body over the size limit", "name: x\n# " + std::string(20000, 'a') + "\n", "name=x.yaml", 413},
  };
  for (const Case& test : cases) {
    const auto [status, body] = PostSweep(server, test.yaml, test.query, auth);
    EXPECT_EQ(status, test.status) << test.what << ": " << body.dump();
    EXPECT_TRUE(body.is_object() && !body.value("error", "").empty()) << test.what << ": " << body.dump();
  }
  EXPECT_EQ(SweepFolders(dir_ / "data"), 0u);
  EXPECT_EQ(GetJson(server, "/api/sweeps").at("sweeps").size(), 0u) << "a refused sweep was queued";
  EXPECT_FALSE(fs::exists("/tmp/owned") &&
               fs::last_write_time("/tmp/owned") > fs::file_time_type::clock::now() - std::chrono::minutes(5));
  // Unknown sweeps and paths are 404 with a JSON message; the server still serves.
  EXPECT_EQ(client.Get("/api/sweeps/999")->status, 404);
  EXPECT_EQ(client.Get("/api/sweeps/99999999999999999999")->status, 404);
  EXPECT_EQ(client.Get("/sweeps/1/report/../../../../etc/passwd")->status, 404);
  // The good sweep goes through with the token.
  const auto [status, body] = PostSweep(server, good, "name=fine.yaml", auth);
  ASSERT_EQ(status, 201) << body.dump();
  EXPECT_EQ(WaitForSweep(server, body.at("id"), {"ok"}, kLong).value("state", ""), "ok");
  EXPECT_EQ(server.Signal(SIGTERM, std::chrono::seconds(60)), 0);
}

TEST_F(ServiceApiTest, TooManyQueuedSweepsIs429AndTheServerKeepsServing) {
  FakeProgramSweep fake(dir_.path());
  fake.SetSlow("slow", true);
  Server server(dir_ / "data",
                {"--jobs", "1", "--max-queued", "1", "--allow-commands", "--allow-root", dir_.path().string(),
                 "--drain-timeout", "1"},
                dir_ / "serve.log");
  ASSERT_TRUE(server.listening()) << server.Log();
  const auto [first, body] = PostSweep(server, fake.Yaml("one", {"slow"}, 1));
  ASSERT_EQ(first, 201) << body.dump();
  const auto [second, refused] = PostSweep(server, fake.Yaml("two", {"slow"}, 1));
  EXPECT_EQ(second, 429);
  EXPECT_THAT(refused.value("error", ""), HasSubstr("queued or running"));
  EXPECT_EQ(server.Client().Get("/healthz")->status, 200);
  EXPECT_EQ(SweepFolders(dir_ / "data"), 1u);
  EXPECT_EQ(server.Signal(SIGTERM, std::chrono::seconds(60)), 0);
}

TEST_F(ServiceApiTest, TokenFileReadableByOthersAndOpenNonLoopbackAreRefused) {
  const fs::path token = testing::WriteFile(dir_ / "token", "abc\n");
  fs::permissions(token, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  EXPECT_EQ(RunToEnd({SLAMSWEEP_BINARY, "serve", "--data", (dir_ / "d1").string(), "--token-file", token.string(),
                      "--listen", "127.0.0.1:0"},
                     dir_ / "mode.log", std::chrono::seconds(60)),
            2);
  EXPECT_THAT(ReadAll(dir_ / "mode.log"), HasSubstr("expected 0600"));
  EXPECT_EQ(RunToEnd({SLAMSWEEP_BINARY, "serve", "--data", (dir_ / "d2").string(), "--listen", "0.0.0.0:0"},
                     dir_ / "open.log", std::chrono::seconds(60)),
            2);
  EXPECT_THAT(ReadAll(dir_ / "open.log"), HasSubstr("without --token-file"));
}

// The second sweep's runs are the first's (hard links, recorded in its own store), not run again.
TEST_F(ServiceApiTest, AnIdenticalRunIsReusedAcrossSweepsNotRepeated) {
  FakeProgramSweep fake(dir_.path());
  Server server(dir_ / "data", {"--jobs", "2", "--allow-commands", "--allow-root", dir_.path().string()},
                dir_ / "serve.log");
  ASSERT_TRUE(server.listening()) << server.Log();
  const auto [first_status, first] = PostSweep(server, fake.Yaml("nightly", {"alpha", "beta"}, 2));
  ASSERT_EQ(first_status, 201) << first.dump();
  ASSERT_EQ(WaitForSweep(server, first.at("id"), {"ok", "failed"}, kLong).value("state", ""), "ok");
  // Another sweep (another name) sharing alpha's runs and adding gamma.
  const auto [second_status, second] = PostSweep(server, fake.Yaml("by-hand", {"alpha", "gamma"}, 2));
  ASSERT_EQ(second_status, 201) << second.dump();
  const nlohmann::json done = WaitForSweep(server, second.at("id"), {"ok", "failed"}, kLong);
  ASSERT_EQ(done.value("state", ""), "ok") << done.dump();
  EXPECT_EQ(done.at("counts").value("reused", 0), 2);
  EXPECT_EQ(fake.Invocations("alpha"), 2u);
  EXPECT_EQ(fake.Invocations("beta"), 2u);
  EXPECT_EQ(fake.Invocations("gamma"), 2u);
  const fs::path first_dir = dir_ / "data" / "sweeps" / "1", second_dir = dir_ / "data" / "sweeps" / "2";
  const auto first_runs = RunsById(nlohmann::json::parse(ReadAll(first_dir / "summary.json")));
  const auto second_runs = RunsById(nlohmann::json::parse(ReadAll(second_dir / "summary.json")));
  ASSERT_EQ(second_runs.size(), 4u);
  std::size_t shared = 0;
  for (const auto& [run_id, run] : second_runs) {
    EXPECT_EQ(run.at("status"), "ok") << run_id;
    if (first_runs.count(run_id) == 0) continue;
    ++shared;
    EXPECT_EQ(run.at("metrics"), first_runs.at(run_id).at("metrics"));
    struct stat a = {}, b = {};
    stat((first_dir / "runs" / run_id / "trajectory.tum").c_str(), &a);
    stat((second_dir / "runs" / run_id / "trajectory.tum").c_str(), &b);
    EXPECT_EQ(a.st_ino, b.st_ino) << "not a hard link: " << run_id;
    EXPECT_THAT(ReadAll(second_dir / "runs" / run_id / "run.json"), HasSubstr("\"sweep\": \"by-hand\""));
    EXPECT_THAT(ReadAll(first_dir / "runs" / run_id / "run.json"), HasSubstr("\"sweep\": \"nightly\""));
  }
  EXPECT_EQ(shared, 2u);
  EXPECT_EQ(server.Signal(SIGTERM, std::chrono::seconds(60)), 0);
}

TEST_F(ServiceApiTest, CancelStopsRunningRunsKeepsFinishedOnesAndSubmitWaitExits130) {
  FakeProgramSweep fake(dir_.path());
  fake.SetSlow("slow", true);
  Server server(dir_ / "data", {"--jobs", "2", "--allow-commands", "--allow-root", dir_.path().string()},
                dir_ / "serve.log");
  ASSERT_TRUE(server.listening()) << server.Log();
  const fs::path config = testing::WriteFile(dir_ / "cancel.yaml", fake.Yaml("cancel-me", {"fast", "slow"}, 2));
  const pid_t submit =
      Spawn({SLAMSWEEP_BINARY, "submit", config.string(), "--server", server.url(), "--wait", "--poll", "0.2"},
            dir_ / "submit.log");
  // Both fast runs end; then a slow one runs (one slot is free for it).
  const auto deadline = Clock::now() + std::chrono::seconds(120);
  while (Clock::now() < deadline && !(fake.Invocations("fast") == 2 && fake.Invocations("slow") >= 1)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_GE(fake.Invocations("slow"), 1u) << server.Log();
  auto client = server.Client();
  auto answer = client.Post("/api/sweeps/1/cancel", "", "text/plain");
  ASSERT_TRUE(answer);
  EXPECT_EQ(answer->status, 202) << answer->body;
  const nlohmann::json sweep = WaitForSweep(server, 1, {"cancelled"}, std::chrono::seconds(120));
  ASSERT_EQ(sweep.value("state", ""), "cancelled") << sweep.dump();
  EXPECT_EQ(sweep.at("counts").value("ok", 0), 2);
  EXPECT_EQ(sweep.at("counts").value("cancelled", 0), 2);
  EXPECT_EQ(WaitExit(submit, std::chrono::seconds(60)), 130) << ReadAll(dir_ / "submit.log");
  const auto runs = RunsById(nlohmann::json::parse(ReadAll(dir_ / "data" / "sweeps" / "1" / "summary.json")));
  EXPECT_EQ(runs.size(), 2u) << "only the finished runs are results";
  for (const auto& entry : fs::directory_iterator(dir_ / "data" / "sweeps" / "1" / "runs")) {
    EXPECT_EQ(entry.path().filename().string().rfind("slow-", 0), std::string::npos) << "left behind: " << entry.path();
  }
  // A finished sweep cannot be cancelled again.
  EXPECT_EQ(client.Post("/api/sweeps/1/cancel", "", "text/plain")->status, 409);
  EXPECT_EQ(server.Signal(SIGTERM, std::chrono::seconds(60)), 0);
}

TEST_F(ServiceApiTest, Kill9ThenRestartLosesNothingAndRunsNothingTwice) {
  FakeProgramSweep fake(dir_.path());
  fake.SetSlow("slow", true);
  const std::vector<std::string> args = {"--jobs", "2", "--allow-commands", "--allow-root", dir_.path().string()};
  auto server = std::make_unique<Server>(dir_ / "data", args, dir_ / "serve1.log");
  ASSERT_TRUE(server->listening()) << server->Log();
  const auto [status, body] = PostSweep(*server, fake.Yaml("restart", {"fast", "slow"}, 2));
  ASSERT_EQ(status, 201) << body.dump();
  const auto deadline = Clock::now() + std::chrono::seconds(120);
  while (Clock::now() < deadline && !(fake.Invocations("fast") == 2 && fake.Invocations("slow") == 2)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_EQ(fake.Invocations("slow"), 2u) << server->Log();
  server->Signal(SIGKILL, std::chrono::seconds(30));
  server.reset();
  fake.SetSlow("slow", false);
  Server restarted(dir_ / "data", args, dir_ / "serve2.log");
  ASSERT_TRUE(restarted.listening()) << restarted.Log();
  const nlohmann::json sweep = WaitForSweep(restarted, 1, {"ok", "failed"}, kLong);
  ASSERT_EQ(sweep.value("state", ""), "ok") << sweep.dump() << restarted.Log();
  EXPECT_EQ(fake.Invocations("fast"), 2u) << "a finished run was repeated";
  EXPECT_EQ(fake.Invocations("slow"), 4u) << "each interrupted run runs exactly once more";
  const auto runs = RunsById(nlohmann::json::parse(ReadAll(dir_ / "data" / "sweeps" / "1" / "summary.json")));
  EXPECT_EQ(runs.size(), 4u);
  for (const auto& [run_id, run] : runs) EXPECT_EQ(run.at("status"), "ok") << run_id;
  EXPECT_EQ(restarted.Signal(SIGTERM, std::chrono::seconds(60)), 0);
}

TEST_F(ServiceApiTest, SigtermDrainsRunningRunsAndExits0) {
  FakeProgramSweep fake(dir_.path());
  fake.SetSlow("slow", true);
  Server server(dir_ / "data",
                {"--jobs", "1", "--allow-commands", "--allow-root", dir_.path().string(), "--drain-timeout", "30"},
                dir_ / "serve.log");
  ASSERT_TRUE(server.listening()) << server.Log();
  const auto [status, body] = PostSweep(server, fake.Yaml("drain", {"slow"}, 2));
  ASSERT_EQ(status, 201) << body.dump();
  const auto deadline = Clock::now() + std::chrono::seconds(60);
  while (Clock::now() < deadline && fake.Invocations("slow") < 1)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_EQ(fake.Invocations("slow"), 1u);
  kill(server.pid(), SIGTERM);
  std::this_thread::sleep_for(std::chrono::seconds(1));
  // Draining: health says so, submissions wait for the next server, the running run may finish.
  EXPECT_EQ(server.Client().Get("/healthz")->status, 503);
  EXPECT_EQ(PostSweep(server, fake.Yaml("late", {"slow"}, 1)).first, 503);
  std::this_thread::sleep_for(std::chrono::seconds(1));
  EXPECT_EQ(fake.Invocations("slow"), 1u) << "no new run starts while draining";
  fake.SetSlow("slow", false);  // the running program ends now
  EXPECT_EQ(server.WaitForExit(std::chrono::seconds(60)), 0) << server.Log();
  EXPECT_EQ(fake.Invocations("slow"), 1u) << "no new run starts while draining";
  // The drained run is recorded; the other one waits in the queue for the next server.
  Server next(dir_ / "data", {"--jobs", "1", "--allow-commands", "--allow-root", dir_.path().string()},
              dir_ / "serve2.log");
  ASSERT_TRUE(next.listening()) << next.Log();
  const nlohmann::json sweep = WaitForSweep(next, 1, {"ok", "failed"}, kLong);
  EXPECT_EQ(sweep.value("state", ""), "ok") << sweep.dump();
  EXPECT_EQ(fake.Invocations("slow"), 2u) << "the drained run is not repeated";
  EXPECT_EQ(next.Signal(SIGTERM, std::chrono::seconds(60)), 0);
}

TEST_F(ServiceApiTest, ARunStillGoingAfterTheDrainGraceIsStoppedAndQueuedAgain) {
  FakeProgramSweep fake(dir_.path());
  fake.SetSlow("slow", true);
  const std::vector<std::string> args = {
      "--jobs", "1", "--allow-commands", "--allow-root", dir_.path().string(), "--drain-timeout", "1"};
  auto server = std::make_unique<Server>(dir_ / "data", args, dir_ / "serve.log");
  ASSERT_TRUE(server->listening()) << server->Log();
  ASSERT_EQ(PostSweep(*server, fake.Yaml("grace", {"slow"}, 1)).first, 201);
  const auto deadline = Clock::now() + std::chrono::seconds(60);
  while (Clock::now() < deadline && fake.Invocations("slow") < 1)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_EQ(fake.Invocations("slow"), 1u);
  EXPECT_EQ(server->Signal(SIGTERM, std::chrono::seconds(60)), 0) << server->Log();
  server.reset();
  EXPECT_FALSE(fs::exists(dir_ / "data" / "sweeps" / "1" / "summary.json")) << "the sweep is not over";
  fake.SetSlow("slow", false);
  Server next(dir_ / "data", args, dir_ / "serve2.log");
  ASSERT_TRUE(next.listening()) << next.Log();
  EXPECT_EQ(WaitForSweep(next, 1, {"ok", "failed"}, kLong).value("state", ""), "ok");
  EXPECT_EQ(fake.Invocations("slow"), 2u) << "stopped once by the drain, run once more";
  EXPECT_EQ(next.Signal(SIGTERM, std::chrono::seconds(60)), 0);
}

}  // namespace
}  // namespace slamsweep
