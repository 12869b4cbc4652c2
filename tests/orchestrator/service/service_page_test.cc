// The service's pages in headless Chromium under the report's Content-Security-Policy (which the
// server sends with every answer): no violation may be logged, and submitted text is escaped.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/orchestrator/service/service_process.h"
#include "tests/support/headless_chromium.h"
#include "tests/support/shared_data.h"

namespace slamsweep {
namespace {

using namespace service_testing;
using ::testing::HasSubstr;
using ::testing::Not;

using slamsweep::testing::CspViolations;
using slamsweep::testing::LoadInHeadlessChromium;

TEST(ServicePageTest, PagesLoadInChromiumUnderTheReportCspWithoutViolationsAndEscapeSubmittedText) {
  if (!fs::exists(slamsweep::testing::kChromium)) {
    const std::string why = std::string(slamsweep::testing::kChromium) + " is missing (scripts/install-deps.sh)";
    if (slamsweep::testing::RunningInCi()) FAIL() << why;
    GTEST_SKIP() << why;
  }
  testing::TempDir dir;
  Server server(dir / "data", {"--jobs", "2"}, dir / "serve.log");
  ASSERT_TRUE(server.listening()) << server.Log();
  const std::string yaml =
      "name: page-test\niterations: 2\nseed: 3\nevaluation: {stages: 4}\n"
      "algorithms:\n  - {name: odometry, adapter: odometry}\n"
      "sequences:\n  - {catalog: simulated-floor, name: floor, max_scans: 30}\n";
  const auto [status, body] =
      PostSweep(server, yaml, "name=page.yaml", {{"X-Slamsweep-Submitter", "<script>alert('x')</script>&co"}});
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

  for (const auto& [name, path, expected] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {"index", "/", "page-test"},
           {"sweep", "/sweeps/1", "odometry-floor-clean-i1"},
           {"report", "/sweeps/1/report/index.html", "floor"}}) {
    const slamsweep::testing::ChromiumPage page = LoadInHeadlessChromium(server.url() + path, dir.path(), name);
    EXPECT_THAT(page.dom, HasSubstr(expected)) << name << " did not render; log:\n" << page.log;
    EXPECT_EQ(CspViolations(page.log), std::vector<std::string>{}) << name;
  }
  // The stylesheet itself was fetched by the browser (a blocked one would be a violation above).
  EXPECT_THAT(server.Log(), Not(HasSubstr("404 GET /static")));
  EXPECT_EQ(server.Signal(SIGTERM, std::chrono::seconds(60)), 0);
}

}  // namespace
}  // namespace slamsweep
