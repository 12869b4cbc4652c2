#include "report/history/history_pages.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>

#include "evaluator/core/input_error.h"
#include "orchestrator/history/history_store.h"
#include "report/history/history_site.h"
#include "report/html/write_report.h"
#include "tests/orchestrator/history/synthetic_sweep.h"
#include "tests/report/fake_artwork.h"
#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

namespace fs = std::filesystem;
using slamsweep::testing::TempDir;

// Every href/src of every page under `root` names an existing file (links to other nights' reports may leave the
// folder, but must resolve), and no page has script, inline style or data: URI.
std::vector<std::string> UnresolvedLinks(const fs::path& root, std::size_t* checked) {
  std::vector<std::string> broken;
  const std::regex link(R"((href|src)="([^"]*)\")");
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".html") continue;
    const std::string page = testing::ReadAll(entry.path());
    if (page.find("<script") != std::string::npos || page.find("style=") != std::string::npos ||
        page.find("data:") != std::string::npos) {
      broken.push_back(entry.path().string() + ": script, inline style or data: URI");
    }
    for (std::sregex_iterator it(page.begin(), page.end(), link), end; it != end; ++it) {
      // Page names come from SafeFileName: no character needs unescaping.
      const std::string target = (*it)[2].str();
      ++*checked;
      if (target.find(':') != std::string::npos || !fs::is_regular_file(entry.path().parent_path() / target)) {
        broken.push_back(entry.path().string() + ": " + target);
      }
    }
  }
  return broken;
}

// RESULT_DIR/report with the history pages of `history_file`.
ReportSummary WriteHistoryReport(const fs::path& result_dir, const fs::path& history_file, bool compare_previous,
                                 bool draw_plots) {
  HistorySiteOptions history;
  history.history_file = history_file;
  history.result_dir = result_dir;
  history.compare_previous = compare_previous;
  history.draw_plots = draw_plots;
  std::unique_ptr<SiteExtension> site = MakeHistorySite(history);
  ReportOptions options;
  options.jobs = 1;
  options.history = site.get();
  return WriteReport(result_dir, result_dir / "report", options);
}

class HistoryReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    orchestrator::testing::SyntheticSweep night;
    night.iterations = 6;
    orchestrator::testing::WriteSyntheticSweep(dir_ / "night1", night);
    fs::create_directories(dir_ / "night1/report");
    slamsweep::testing::WriteFile(dir_ / "night1/report/index.html", "<!DOCTYPE html><title>night 1</title>\n");
    night.seed = 2;
    night.started_at = "2026-11-21T02:00:00Z";
    night.failed_iterations = {5};
    orchestrator::testing::WriteSyntheticSweep(dir_ / "night2", night);  // no report: named, not linked
    night.seed = 3;
    night.failed_iterations = {};
    night.odometry_sigma *= 2.0;  // tonight's sweep: noisier odometry, a regression
    night.started_at = "2026-11-22T02:00:00Z";
    orchestrator::testing::WriteSyntheticSweep(dir_ / "night3", night);
    orchestrator::HistoryStore store = orchestrator::HistoryStore::Open(dir_ / "history.sqlite");
    store.Record(orchestrator::ReadNight(dir_ / "night1", "monday"));
    store.Record(orchestrator::ReadNight(dir_ / "night2", "tuesday"));
  }

  ReportSummary Write(bool compare_previous, bool draw_plots) {
    return WriteHistoryReport(dir_ / "night3", dir_ / "history.sqlite", compare_previous, draw_plots);
  }

  TempDir dir_;
};

TEST_F(HistoryReportTest, PagesRenderAndLinksResolve) {
  const bool gnuplot = fs::exists("/usr/bin/gnuplot");
  const ReportSummary summary = Write(/*compare_previous=*/true, /*draw_plots=*/gnuplot);
  const fs::path report = dir_ / "night3/report";
  const std::string index = testing::ReadAll(report / "index.html");
  EXPECT_NE(index.find("Nightly history"), std::string::npos);
  // Two recorded nights plus tonight's, which is not recorded yet.
  EXPECT_NE(index.find("3 nights in"), std::string::npos) << index;
  EXPECT_NE(index.find("<a href=\"../../night1/report/index.html\">monday</a>"), std::string::npos) << index;
  EXPECT_NE(index.find("(not recorded)"), std::string::npos);
  // Compared with the previous night (tuesday): the doubled odometry noise is a regression of ape_trans.
  EXPECT_NE(index.find("Compared with night tuesday"), std::string::npos);
  EXPECT_NE(index.find("1 regressions, 0 improvements"), std::string::npos) << index;
  EXPECT_NE(index.find("<caption>Regressions</caption>"), std::string::npos);

  const fs::path ape_page =
      report / (HistoryPageStem({"icp-slam", "intel", "noisy", "recorded", "ape_trans", "rmse", "m"}) + ".html");
  ASSERT_TRUE(fs::is_regular_file(ape_page)) << ape_page;
  EXPECT_TRUE(fs::is_regular_file(
      report / (HistoryPageStem({"icp-slam", "intel", "noisy", "recorded", "corners", "value", ""}) + ".html")));
  const std::string page = testing::ReadAll(ape_page);
  // monday's report exists: linked relatively; tuesday's does not: named only; tonight's: this report.
  EXPECT_NE(page.find("href=\"../../../night1/report/index.html\">monday</a>"), std::string::npos) << page;
  EXPECT_NE(page.find("<td>tuesday</td>"), std::string::npos) << page;
  EXPECT_NE(page.find("href=\"../index.html\">2026-11-22T02:00:00Z (not recorded)</a>"), std::string::npos);
  // tuesday had a failed run and 5 ok ones.
  EXPECT_NE(page.find("<tr class=\"failures\">"), std::string::npos);
  // Only the compared statistic gets a page: no page for ape_trans mean.
  std::size_t history_pages = 0;
  for (const auto& entry : fs::directory_iterator(report / "history"))
    history_pages += entry.path().extension() == ".html";
  EXPECT_EQ(history_pages, 2u);

  if (gnuplot) {
    EXPECT_EQ(testing::ImageSources(ape_page).size(), 1u);
    EXPECT_GT(fs::file_size(fs::path(ape_page).replace_extension(".png")), 1000u);
    EXPECT_GE(summary.images, 2u);
  } else {
    EXPECT_NE(page.find("No plot"), std::string::npos);
  }
  std::size_t checked = 0;
  EXPECT_EQ(UnresolvedLinks(report, &checked), std::vector<std::string>{});
  EXPECT_GT(checked, 10u);
}

TEST_F(HistoryReportTest, WithoutComparisonOrEarlierNight) {
  Write(/*compare_previous=*/false, /*draw_plots=*/false);
  const std::string index = testing::ReadAll(dir_ / "night3/report/index.html");
  EXPECT_EQ(index.find("Compared with night"), std::string::npos);
  const std::string page = testing::ReadAll(
      dir_ / "night3/report" /
      (HistoryPageStem({"icp-slam", "intel", "noisy", "recorded", "ape_trans", "rmse", "m"}) + ".html"));
  EXPECT_NE(page.find("No plot: images were not requested"), std::string::npos);

  // A history with nothing before tonight: the comparison is a note, not an error.
  orchestrator::HistoryStore::Open(dir_ / "empty.sqlite");
  HistorySiteOptions options;
  options.history_file = dir_ / "empty.sqlite";
  options.result_dir = dir_ / "night3";
  options.compare_previous = true;
  options.draw_plots = false;
  std::unique_ptr<SiteExtension> site = MakeHistorySite(options);
  ReportOptions report_options;
  report_options.history = site.get();
  WriteReport(dir_ / "night3", dir_ / "other-report", report_options);
  EXPECT_NE(testing::ReadAll(dir_ / "other-report/index.html").find("holds no night before this sweep"),
            std::string::npos);
}

TEST_F(HistoryReportTest, BadHistoryFileIsInputError) {
  HistorySiteOptions options;
  options.history_file = dir_ / "missing.sqlite";
  options.result_dir = dir_ / "night3";
  std::unique_ptr<SiteExtension> site = MakeHistorySite(options);
  ReportOptions report_options;
  report_options.history = site.get();
  EXPECT_THROW(WriteReport(dir_ / "night3", dir_ / "r", report_options), evaluator::InputError);
  options.history_file = dir_ / "night1/results.sqlite";  // a results database, not a history
  site = MakeHistorySite(options);
  report_options.history = site.get();
  EXPECT_THROW(WriteReport(dir_ / "night3", dir_ / "r2", report_options), evaluator::InputError);
  options.regression.alpha = 0.0;
  EXPECT_THROW(MakeHistorySite(options), evaluator::InputError);
}

// Nights on the recorded odometry and nights handed the reference: a page per mode, titled with it, and the
// comparison finds the regression within the reference nights only.
TEST(HistoryOdometryPagesTest, APagePerModeAndNoComparisonAcrossModes) {
  TempDir dir;
  orchestrator::testing::SyntheticSweep night;
  night.iterations = 6;
  night.odometry = "recorded";
  orchestrator::testing::WriteSyntheticSweep(dir / "monday", night);
  night.odometry = "reference";
  night.odometry_sigma *= 2.0;  // worse than monday, but another mode: never its regression
  night.seed = 2;
  night.started_at = "2026-11-21T02:00:00Z";
  orchestrator::testing::WriteSyntheticSweep(dir / "tuesday", night);
  night.odometry_sigma *= 2.0;  // tonight, on the reference again: a regression against tuesday
  night.seed = 3;
  night.started_at = "2026-11-22T02:00:00Z";
  orchestrator::testing::WriteSyntheticSweep(dir / "tonight", night);
  {
    orchestrator::HistoryStore store = orchestrator::HistoryStore::Open(dir / "history.sqlite");
    store.Record(orchestrator::ReadNight(dir / "monday", "monday"));
    store.Record(orchestrator::ReadNight(dir / "tuesday", "tuesday"));
  }
  WriteHistoryReport(dir / "tonight", dir / "history.sqlite", /*compare_previous=*/true, /*draw_plots=*/false);
  const fs::path report = dir / "tonight/report";

  const fs::path recorded_page =
      report / (HistoryPageStem({"icp-slam", "intel", "noisy", "recorded", "ape_trans", "rmse", "m"}) + ".html");
  const fs::path reference_page =
      report / (HistoryPageStem({"icp-slam", "intel", "noisy", "reference", "ape_trans", "rmse", "m"}) + ".html");
  ASSERT_NE(recorded_page, reference_page);
  ASSERT_TRUE(fs::is_regular_file(recorded_page)) << recorded_page;
  ASSERT_TRUE(fs::is_regular_file(reference_page)) << reference_page;
  const std::string recorded = testing::ReadAll(recorded_page);
  const std::string reference = testing::ReadAll(reference_page);
  EXPECT_NE(recorded.find("icp-slam on intel (noisy, recorded odometry): ape_trans rmse"), std::string::npos)
      << recorded;
  EXPECT_NE(reference.find("icp-slam on intel (noisy, reference odometry): ape_trans rmse"), std::string::npos);
  // Each page holds its own mode's nights only.
  EXPECT_NE(recorded.find(">monday<"), std::string::npos);
  EXPECT_EQ(recorded.find("tuesday"), std::string::npos);
  EXPECT_EQ(recorded.find("not recorded"), std::string::npos);
  EXPECT_EQ(reference.find("monday"), std::string::npos);
  EXPECT_NE(reference.find("<td>tuesday</td>"), std::string::npos) << reference;
  EXPECT_NE(reference.find("(not recorded)"), std::string::npos);
  std::size_t history_pages = 0;
  for (const auto& entry : fs::directory_iterator(report / "history"))
    history_pages += entry.path().extension() == ".html";
  EXPECT_EQ(history_pages, 4u);  // ape_trans and corners, in each mode

  // Compared with tuesday (the previous night): the reference series regressed; monday's recorded series has no
  // counterpart tonight.
  const std::string index = testing::ReadAll(report / "index.html");
  EXPECT_NE(index.find("Compared with night tuesday"), std::string::npos);
  EXPECT_NE(index.find("1 regressions, 0 improvements"), std::string::npos) << index;
  EXPECT_NE(index.find("<th>odometry</th>"), std::string::npos);
  EXPECT_NE(index.find("<td>reference</td>"), std::string::npos);
  EXPECT_EQ(index.find("<td>recorded</td>"), std::string::npos);
  std::size_t checked = 0;
  EXPECT_EQ(UnresolvedLinks(report, &checked), std::vector<std::string>{});
}

TEST(HistoryPagesTest, UnknownModeIsSaidOnItsPage) {
  HistorySeriesPage page;
  page.key = {"icp-slam", "intel", "noisy", "unknown", "ape_trans", "rmse", "m"};
  page.page = HistoryPageStem(page.key) + ".html";
  const std::string html = RenderHistoryPage(page);
  EXPECT_NE(html.find("(noisy, unknown odometry)"), std::string::npos) << html;
  EXPECT_NE(html.find("Odometry mode unknown: these nights were recorded before the history kept"), std::string::npos);
  page.key.odometry = "recorded";
  EXPECT_EQ(RenderHistoryPage(page).find("Odometry mode"), std::string::npos);
}

TEST(HistoryPagesTest, EscapesEverythingAndSummarizes) {
  HistorySeriesPage page;
  page.key = {"<script>alert(1)</script>", "seq\"&", "n'", "recorded", "ape_trans", "rmse", "m"};
  page.page = HistoryPageStem(page.key) + ".html";
  page.plot = HistoryPageStem(page.key) + ".png";
  NightPoint night = SummarizeNight({1.0, 2.0, 3.0, 6.0});
  // Hand computation: mean 3, sample std sqrt(((4 + 1 + 0 + 9) / 3)) = sqrt(14/3).
  EXPECT_DOUBLE_EQ(night.mean, 3.0);
  EXPECT_DOUBLE_EQ(night.min, 1.0);
  EXPECT_DOUBLE_EQ(night.max, 6.0);
  ASSERT_TRUE(night.std.has_value());
  EXPECT_NEAR(*night.std, std::sqrt(14.0 / 3.0), 1e-12);
  EXPECT_FALSE(SummarizeNight({2.0}).std.has_value());
  night.label = "<b>night</b>";
  page.nights.push_back(night);
  const std::string html = RenderHistoryPage(page);
  EXPECT_EQ(html.find("<script>"), std::string::npos);
  EXPECT_EQ(html.find("<b>"), std::string::npos);
  EXPECT_NE(html.find("&lt;b&gt;night&lt;/b&gt;"), std::string::npos);
  EXPECT_EQ(page.page.find('<'), std::string::npos);
  EXPECT_EQ(page.page.rfind("history/", 0), 0u);
  // The gnuplot script gives text as single-quoted literals (gnuplot expands backquotes inside double quotes) and
  // uses a log axis when every value is positive.
  const std::string script = HistoryPlotScript(page, "/tmp/x.png");
  EXPECT_NE(script.find("set logscale y"), std::string::npos);
  EXPECT_NE(script.find("set title '<script>"), std::string::npos) << script;
  EXPECT_EQ(script.find("set title \""), std::string::npos);
  page.nights[0].min = -1.0;
  EXPECT_EQ(HistoryPlotScript(page, "/tmp/x.png").find("set logscale y"), std::string::npos);
}

}  // namespace
}  // namespace slamsweep::report
