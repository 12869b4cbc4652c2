// The report in a real browser: headless Chromium loads pages from a local server that sends
// Jenkins' default Content-Security-Policy. No CSP violation may be logged and every <img> of a
// page must have been fetched with status 200. Screenshots of the pages are kept as artefacts in
// SLAMSWEEP_ARTIFACT_DIR (build/artefacts/report-screenshots/), named in the test output.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "report/html/standard_artwork.h"
#include "report/html/write_report.h"
#include "tests/report/fake_artwork.h"
#include "tests/report/fixture_sweep.h"
#include "tests/support/headless_chromium.h"
#include "tests/support/shared_data.h"

extern char** environ;

namespace slamsweep::report {
namespace {

namespace fs = std::filesystem;
using slamsweep::testing::TempDir;
using testing::ReadAll;

constexpr const char* kPython = "/usr/bin/python3";
using slamsweep::testing::ChildProcess;
using slamsweep::testing::ChromiumPage;
using slamsweep::testing::CspViolations;
using slamsweep::testing::kChromium;
using slamsweep::testing::LoadInHeadlessChromium;

class BrowserTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kChromium) || !fs::exists(kPython)) {
      const std::string why = std::string(kChromium) + " or " + kPython + " is missing (apt-get install chromium)";
      if (slamsweep::testing::RunningInCi()) FAIL() << why;
      GTEST_SKIP() << why;
    }
    std::error_code error;
    fs::create_directories(SLAMSWEEP_ARTIFACT_DIR, error);
    ASSERT_FALSE(error) << SLAMSWEEP_ARTIFACT_DIR << ": " << error.message();
    testing::WriteFixtureSweep(dir_ / "sweep", Runs());
    artwork_ = MakeStandardArtwork();
    ReportOptions options;
    options.artwork = artwork_ ? artwork_.get() : &fake_;
    WriteReport(dir_ / "sweep", dir_ / "report", options);
    server_ = std::make_unique<ChildProcess>(
        std::vector<std::string>{kPython, SLAMSWEEP_CSP_SERVER, (dir_ / "report").string(), (dir_ / "port").string(),
                                 (dir_ / "requests.log").string()},
        dir_ / "server.out", dir_ / "server.err");
    ASSERT_TRUE(server_->started());
    for (int i = 0; i < 200 && !fs::exists(dir_ / "port"); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    ASSERT_TRUE(fs::exists(dir_ / "port")) << ReadAll(dir_ / "server.err");
    base_url_ = "http://127.0.0.1:" + ReadAll(dir_ / "port") + "/";
  }
  void TearDown() override {
    if (server_) server_->Stop();
  }

  virtual std::vector<testing::FixtureRun> Runs() const { return testing::StandardFixtureRuns(); }

  // Loads `page` and checks: no CSP violation, every image of the page requested with 200.
  void CheckPage(const std::string& page, const fs::path& screenshot = {}, int window_height_px = 2000) {
    SCOPED_TRACE(page);
    const std::string name = "page" + std::to_string(++pages_);
    const ChromiumPage run = LoadInHeadlessChromium(base_url_ + page, dir_.path(), name, screenshot, window_height_px);
    EXPECT_TRUE(run.finished) << "chromium did not finish in 40 s";
    EXPECT_TRUE(CspViolations(run.log).empty()) << ::testing::PrintToString(CspViolations(run.log));
    const std::string log = ReadAll(dir_ / "requests.log");
    EXPECT_NE(log.find("200 /" + page), std::string::npos) << log;
    EXPECT_NE(log.find("200 /style.css"), std::string::npos) << log;
    const fs::path page_dir = fs::path("/" + page).parent_path();
    const std::vector<std::string> images = testing::ImageSources(dir_ / "report" / page);
    for (const std::string& src : images) {
      const std::string path = (page_dir / src).lexically_normal().generic_string();
      EXPECT_NE(log.find("200 " + path + "\n"), std::string::npos) << "image not loaded: " << path;
    }
  }

  TempDir dir_;
  testing::FakeArtwork fake_;
  std::unique_ptr<Artwork> artwork_;
  std::unique_ptr<ChildProcess> server_;
  std::string base_url_;
  int pages_ = 0;
};

TEST_F(BrowserTest, PagesLoadUnderJenkinsCsp) {
  const fs::path screenshot = fs::path(SLAMSWEEP_ARTIFACT_DIR) / "report_index_screenshot.png";
  CheckPage("index.html", screenshot);
  EXPECT_TRUE(fs::exists(screenshot));
  std::cout << "screenshot of the index: " << screenshot.string() << "\n";
  std::cout << "screenshots of the report are kept in " << SLAMSWEEP_ARTIFACT_DIR << "\n";
  RecordProperty("screenshot", screenshot.string());
  EXPECT_FALSE(testing::ImageSources(dir_ / "report/index.html").empty());
  CheckPage("sequences/intel-clean.html");
  CheckPage("runs/_script_alert_1___script_-intel-clean-i0-0000abcd.html");
  CheckPage("validity.html");
  const fs::path metrics_screenshot = fs::path(SLAMSWEEP_ARTIFACT_DIR) / "report_metrics_screenshot.png";
  CheckPage("metrics.html", metrics_screenshot, 3400);
  EXPECT_TRUE(fs::exists(metrics_screenshot));
  std::cout << "screenshot of the metric specification: " << metrics_screenshot.string() << "\n";
}

// The sparse-data mark and the "Data density" table of a sequence page, and the mark on the index.
class DensityBrowserTest : public BrowserTest {
 protected:
  std::vector<testing::FixtureRun> Runs() const override { return testing::DensityFixtureRuns(); }
};

TEST_F(DensityBrowserTest, TheSparseDataMarkLoadsUnderJenkinsCsp) {
  ASSERT_NE(ReadAll(dir_ / "report/sequences/intel-clean.html").find("<p class=\"sparse-data\">"), std::string::npos);
  CheckPage("sequences/intel-clean.html", fs::path(SLAMSWEEP_ARTIFACT_DIR) / "report_sparse_data_screenshot.png");
  CheckPage("index.html");
}

// The validity page (report/html/validity_page.h) with numbers and its scatter plots, on a sweep of
// graded noise settings; its screenshot is kept as an artifact.
class ValidityBrowserTest : public BrowserTest {
 protected:
  std::vector<testing::FixtureRun> Runs() const override { return testing::ValidityFixtureRuns(); }
};

TEST_F(ValidityBrowserTest, TheValidityPageWithItsPlotsLoadsUnderJenkinsCsp) {
  const fs::path screenshot = fs::path(SLAMSWEEP_ARTIFACT_DIR) / "report_validity_screenshot.png";
  fs::remove(screenshot);
  CheckPage("validity.html", screenshot, 3400);
  EXPECT_TRUE(fs::exists(screenshot));
  EXPECT_EQ(testing::ImageSources(dir_ / "report/validity.html").size(), 24u);
  std::cout << "screenshot of the validity page: " << screenshot.string() << "\n";
}

// The segment-length and parameter pages (report/html/view_pages.h) on a sweep that has both; their
// screenshots, and the sequence page's with its palette swatches, are kept as artifacts.
class ViewsBrowserTest : public BrowserTest {
 protected:
  std::vector<testing::FixtureRun> Runs() const override { return testing::ViewsFixtureRuns(); }
};

TEST_F(ViewsBrowserTest, SegmentAndParameterPagesLoadUnderJenkinsCsp) {
  const std::pair<const char*, const char*> pages[] = {
      {"sequences/intel-clean/segments.html", "report_segments_screenshot.png"},
      {"sequences/intel-clean/parameters.html", "report_parameters_screenshot.png"},
      {"sequences/intel-clean.html", "report_sequence_screenshot.png"}};
  for (const auto& [page, file] : pages) {
    const fs::path screenshot = fs::path(SLAMSWEEP_ARTIFACT_DIR) / file;
    fs::remove(screenshot);
    // Tall windows: the screenshot shows the whole page, every figure of it.
    CheckPage(page, screenshot, 3400);
    EXPECT_TRUE(fs::exists(screenshot)) << page;
    EXPECT_FALSE(testing::ImageSources(dir_ / "report" / page).empty()) << page;
    std::cout << "screenshot of " << page << ": " << screenshot.string() << "\n";
    RecordProperty(std::string("screenshot ") + page, screenshot.string());
  }
  EXPECT_TRUE(testing::BrokenLinks(dir_ / "report").empty());
}

// The sequence page's "Maps compared" (report/html/map_figures.h), drawn by the real image maker: the browser
// must find and fetch every map panel and difference image; the page's screenshot is kept as an artefact.
class MapsBrowserTest : public BrowserTest {
 protected:
  std::vector<testing::FixtureRun> Runs() const override { return testing::MapsFixtureRuns(); }
};

TEST_F(MapsBrowserTest, MapPanelsLoadUnderJenkinsCsp) {
  const fs::path screenshot = fs::path(SLAMSWEEP_ARTIFACT_DIR) / "report_maps_screenshot.png";
  fs::remove(screenshot);
  // A window as tall as the page: the maps come after the tables, plots and trajectories.
  CheckPage("sequences/intel-clean.html", screenshot, 5200);
  EXPECT_TRUE(fs::exists(screenshot));
  std::cout << "screenshot of the maps compared (sequences/intel-clean.html): " << screenshot.string() << "\n";
  RecordProperty("screenshot maps", screenshot.string());
  // The DOM as the browser built it: the reference, one map per row and one difference per row.
  const ChromiumPage dom =
      LoadInHeadlessChromium(base_url_ + "sequences/intel-clean.html", dir_.path(), "maps-dom", {});
  ASSERT_TRUE(dom.finished);
  std::size_t panels = 0;
  for (std::size_t at = dom.dom.find("class=\"map-panel\" src="); at != std::string::npos;
       at = dom.dom.find("class=\"map-panel\" src=", at + 1)) {
    ++panels;
  }
  EXPECT_EQ(panels, 5u) << "the page shows no (or not every) map panel";
  const std::vector<std::string> images = testing::ImageSources(dir_ / "report/sequences/intel-clean.html");
  std::size_t drawn = 0;
  for (const std::string& src : images) {
    if (src.find("/map-") == std::string::npos) continue;
    ++drawn;
    EXPECT_GT(fs::file_size(dir_ / "report/sequences" / src), 200u) << src;  // a real PNG, not a placeholder
  }
  EXPECT_EQ(drawn, 5u);
  EXPECT_TRUE(testing::BrokenLinks(dir_ / "report").empty());
}

// The overview of a sweep shaped like the paper's opens with the verdict across data sets and its critical-
// difference diagram (inline SVG); under Jenkins' CSP. Its screenshot is the README's (scripts/readme-screenshot.sh).
class AcrossDataSetsBrowserTest : public BrowserTest {
 protected:
  std::vector<testing::FixtureRun> Runs() const override { return testing::PaperLikeFixtureRuns(); }
};

TEST_F(AcrossDataSetsBrowserTest, TheOverviewOpensWithTheVerdictAcrossDataSets) {
  const fs::path screenshot = fs::path(SLAMSWEEP_ARTIFACT_DIR) / "report_overview_screenshot.png";
  fs::remove(screenshot);
  CheckPage("index.html", screenshot, 1500);
  EXPECT_TRUE(fs::exists(screenshot));
  std::cout << "screenshot of the overview: " << screenshot.string() << "\n";
  RecordProperty("screenshot overview", screenshot.string());
  // The DOM as the browser built it: the first section heading is the verdict across data sets, with its diagram.
  const ChromiumPage dom = LoadInHeadlessChromium(base_url_ + "index.html", dir_.path(), "overview-dom", {});
  ASSERT_TRUE(dom.finished);
  const std::size_t first_h2 = dom.dom.find("<h2>");
  ASSERT_NE(first_h2, std::string::npos);
  const std::string heading = "<h2>Which is better overall?</h2>";
  EXPECT_EQ(dom.dom.compare(first_h2, heading.size(), heading), 0) << dom.dom.substr(first_h2, 80);
  const std::size_t diagram = dom.dom.find("<svg class=\"cd\"");
  EXPECT_NE(diagram, std::string::npos);
  EXPECT_LT(diagram, dom.dom.find("Which is better, and is the difference real?"));
  EXPECT_NE(dom.dom.find("cartographer is better than hector"), std::string::npos);
  EXPECT_EQ(dom.dom.find("<script"), std::string::npos);
}

// The detector itself: a page with an inline style must be reported, or a silent browser would
// pass every check above.
TEST_F(BrowserTest, InlineStyleIsReportedAsViolation) {
  slamsweep::testing::WriteFile(
      dir_ / "report/bad.html",
      "<!DOCTYPE html><html><head><style>p{color:red}</style></head><body><p>x</p></body></html>");
  const ChromiumPage run = LoadInHeadlessChromium(base_url_ + "bad.html", dir_.path(), "bad", {});
  EXPECT_TRUE(run.finished);
  EXPECT_FALSE(CspViolations(run.log).empty()) << run.log;
}

}  // namespace
}  // namespace slamsweep::report
