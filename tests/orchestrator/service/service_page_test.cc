// The service's pages in headless Chromium under the report's Content-Security-Policy (which the
// server sends with every answer): no violation may be logged, and submitted text is escaped.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <spawn.h>

#include "tests/orchestrator/service/service_process.h"

extern char** environ;

namespace slamsweep {
namespace {

using namespace service_testing;
using ::testing::HasSubstr;
using ::testing::Not;

struct Loaded {
  std::string dom;
  std::string log;
};

/// `chromium --headless --dump-dom URL` in its own process group, with its console and CSP log on stderr.
Loaded LoadInChromium(const std::string& url, const fs::path& work, const std::string& name) {
  const fs::path out = work / (name + ".dom"), err = work / (name + ".err");
  const std::vector<std::string> argv = {"/usr/bin/chromium", "--headless=new", "--no-sandbox", "--disable-gpu",
                                         "--no-first-run", "--enable-logging=stderr", "--v=0",
                                         "--user-data-dir=" + (work / ("profile-" + name)).string(), "--dump-dom", url};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);  // its helpers end with it
  posix_spawnattr_setpgroup(&attributes, 0);
  std::vector<char*> args;
  for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
  args.push_back(nullptr);
  pid_t pid = -1;
  const int spawned = posix_spawn(&pid, argv[0].c_str(), &actions, &attributes, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (spawned != 0) return {};
  if (WaitExit(pid, std::chrono::seconds(60)) < 0) kill(-pid, SIGKILL);
  kill(-pid, SIGKILL);
  return {ReadAll(out), ReadAll(err)};
}

std::vector<std::string> CspViolations(const std::string& log) {
  std::vector<std::string> violations;
  std::istringstream in(log);
  for (std::string line; std::getline(in, line);) {
    if (line.find("Content Security Policy") != std::string::npos || line.find("Refused to") != std::string::npos) {
      violations.push_back(line);
    }
  }
  return violations;
}

TEST(ServicePageTest, PagesLoadInChromiumUnderTheReportCspWithoutViolationsAndEscapeSubmittedText) {
  if (!fs::exists("/usr/bin/chromium")) GTEST_SKIP() << "chromium is not installed (scripts/install-deps.sh)";
  testing::TempDir dir;
  Server server(dir / "data", {"--jobs", "2"}, dir / "serve.log");
  ASSERT_TRUE(server.listening()) << server.Log();
  const std::string yaml = "name: page-test\niterations: 2\nseed: 3\nevaluation: {stages: 4}\n"
                           "algorithms:\n  - {name: odometry, adapter: odometry}\n"
                           "sequences:\n  - {catalog: simulated-floor, name: floor, max_scans: 30}\n";
  const auto [status, body] = PostSweep(server, yaml, "name=page.yaml",
                                        {{"X-Slamsweep-Submitter", "<script>alert('x')</script>&co"}});
  ASSERT_EQ(status, 201) << body.dump();
  ASSERT_EQ(WaitForSweep(server, 1, {"ok"}, std::chrono::seconds(240)).value("report", ""), "ready");
  auto client = server.Client();
  const auto index = client.Get("/");
  ASSERT_TRUE(index);
  // The report's rules without `sandbox`, which would keep the page from following its refresh.
  EXPECT_EQ(index->get_header_value("Content-Security-Policy"),
            "default-src 'none'; img-src 'self'; style-src 'self'; base-uri 'none'; form-action 'none'; "
            "frame-ancestors 'none';");
  EXPECT_EQ(client.Get("/sweeps/1/report/index.html")->get_header_value("Content-Security-Policy"),
            "sandbox allow-same-origin; default-src 'none'; img-src 'self'; style-src 'self';");
  EXPECT_THAT(index->body, HasSubstr("&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt;&amp;co"));
  EXPECT_THAT(index->body, Not(HasSubstr("<script")));
  EXPECT_THAT(index->body, Not(HasSubstr("style=")));
  EXPECT_THAT(index->body, Not(HasSubstr("data:")));

  for (const auto& [name, path, expected] :
       std::vector<std::tuple<std::string, std::string, std::string>>{{"index", "/", "page-test"},
                                                                      {"sweep", "/sweeps/1", "odometry-floor-clean-i1"},
                                                                      {"report", "/sweeps/1/report/index.html", "floor"}}) {
    const Loaded page = LoadInChromium(server.url() + path, dir.path(), name);
    EXPECT_THAT(page.dom, HasSubstr(expected)) << name << " did not render; log:\n" << page.log;
    EXPECT_EQ(CspViolations(page.log), std::vector<std::string>{}) << name;
  }
  // The stylesheet itself was fetched by the browser (a blocked one would be a violation above).
  EXPECT_THAT(server.Log(), Not(HasSubstr("404 GET /static")));
  EXPECT_EQ(server.Signal(SIGTERM, std::chrono::seconds(60)), 0);
}

}  // namespace
}  // namespace slamsweep
