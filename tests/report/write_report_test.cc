#include "report/html/write_report.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <variant>

#include <nlohmann/json.hpp>

#include "evaluator/core/input_error.h"
#include "orchestrator/store/validity_table.h"
#include "report/model/load_runs.h"
#include "report/plots/algorithm_palette.h"
#include "report/plots/scatter_plot.h"
#include "tests/report/fake_artwork.h"
#include "tests/report/fixture_sweep.h"
#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

namespace fs = std::filesystem;
using slamsweep::testing::TempDir;
using testing::ReadAll;

class WriteReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    testing::WriteFixtureSweep(dir_ / "sweep", testing::StandardFixtureRuns());
    options_.artwork = &artwork_;
  }
  ReportSummary Write() { return WriteReport(dir_ / "sweep", dir_ / "report", options_); }
  std::string AllPages() {
    std::string all;
    for (const auto& entry : fs::recursive_directory_iterator(dir_ / "report")) {
      if (entry.path().extension() == ".html") all += ReadAll(entry.path());
    }
    return all;
  }
  TempDir dir_;
  testing::FakeArtwork artwork_;
  ReportOptions options_;
};

TEST_F(WriteReportTest, WritesTheSite) {
  const ReportSummary summary = Write();
  EXPECT_EQ(summary.runs, 10u);
  EXPECT_EQ(summary.pages, 1u + 2u + 10u + 2u);  // index, 2 sequences, 10 runs, metrics.html, validity.html
  const fs::path out = dir_ / "report";
  for (const char* file :
       {"index.html", "style.css", "summary.csv", "runs.csv", "summary.json", "sequences/intel-clean.html",
        "sequences/mit-no-ref-clean.html", "files/gmapping/intel-clean/rmse.txt",
        "files/gmapping/intel-clean/pose_log.tum", "files/gmapping/mit-no-ref-clean/corners.txt",
        "runs/gmapping-intel-clean-i1-0000abcd.html", "runs/gmapping-intel-clean-i1-0000abcd/map.pgm",
        "runs/gmapping-intel-clean-i1-0000abcd/map.yaml", "runs/gmapping-intel-clean-i1-0000abcd/trajectory.tum",
        "runs/gmapping-intel-clean-i1-0000abcd/map.geojson", "runs/gmapping-intel-clean-i1-0000abcd/stages.gif"}) {
    EXPECT_TRUE(fs::is_regular_file(out / file)) << file;
  }
  // 9 successful runs: an overlay and a GIF each, the reference on the overlay for the 6 on intel
  // (gmapping 3, hostile 2, single 1); thumbnails only for the 4 gallery (median) runs: 3 algorithms
  // on intel, 1 on mit-no-ref.
  EXPECT_EQ(artwork_.thumbnails, 4);
  EXPECT_EQ(artwork_.overlays, 9);
  EXPECT_EQ(artwork_.overlays_with_reference, 6);
  EXPECT_EQ(artwork_.gifs, 9);
}

TEST_F(WriteReportTest, EveryLinkResolvesInsideTheReport) {
  Write();
  std::size_t checked = 0;
  const std::vector<std::string> broken = testing::BrokenLinks(dir_ / "report", &checked);
  EXPECT_TRUE(broken.empty()) << ::testing::PrintToString(broken);
  EXPECT_GT(checked, 100u);
}

TEST_F(WriteReportTest, NoScriptNoInlineStyleNoDataUri) {
  Write();
  const std::string all = AllPages();
  EXPECT_EQ(all.find("<script"), std::string::npos);
  EXPECT_EQ(all.find("<style"), std::string::npos);
  EXPECT_EQ(all.find(" style="), std::string::npos);
  EXPECT_EQ(all.find("data:"), std::string::npos);
}

TEST_F(WriteReportTest, HostileNamesAndLogsAreEscaped) {
  Write();
  const std::string index = ReadAll(dir_ / "report/index.html");
  EXPECT_NE(index.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
  const std::string run_page = ReadAll(dir_ / "report/runs/_script_alert_1___script_-intel-clean-i0-0000abcd.html");
  EXPECT_NE(run_page.find("&lt;b&gt;bold&lt;/b&gt; &amp; &lt;img src=x onerror=alert(2)&gt;"), std::string::npos);
  EXPECT_EQ(run_page.find("<b>bold"), std::string::npos);
}

TEST_F(WriteReportTest, TableMarksBestAndCountsFailures) {
  Write();
  const std::string index = ReadAll(dir_ / "report/index.html");
  // gmapping on intel: ATE 0.10 0.11 0.12 -> 0.1100 ± 0.0100, the best of the column.
  EXPECT_NE(index.find("<td class=\"best\">0.1100 ± 0.0100 <span class=\"n\">n=3</span> <span class=\"marker\">▼ best"),
            std::string::npos);
  // The single iteration has no std.
  EXPECT_NE(index.find("0.5000 ± n/a"), std::string::npos);
  EXPECT_NE(index.find("3 runs: 2 ok, 1 failed"), std::string::npos);
  EXPECT_NE(index.find("alignment se2"), std::string::npos);
  const std::string failed = ReadAll(dir_ / "report/runs/_script_alert_1___script_-intel-clean-i2-0000abcd.html");
  EXPECT_NE(failed.find("Status: failed (exit_code): killed by SIGSEGV"), std::string::npos);
}

TEST_F(WriteReportTest, TheBaselineIsDrawnApartAndAWithheldBestSaysWhy) {
  std::vector<testing::FixtureRun> runs = testing::StandardFixtureRuns();
  for (int i = 0; i < 3; ++i) {
    testing::FixtureRun odometry = testing::MakeRun("odometry", "intel", i);
    odometry.adapter = "odometry";
    odometry.ape_rmse_m = 2.0 + i;
    odometry.occupied_ratio = 0.01;  // a smeared map with the lowest occupied ratio of the table
    odometry.corners = 5.0;
    odometry.enclosed_areas = 0.0;
    runs.push_back(odometry);
  }
  testing::WriteFixtureSweep(dir_ / "with-baseline", runs);
  WriteReport(dir_ / "with-baseline", dir_ / "report", options_);
  const std::string page = ReadAll(dir_ / "report/sequences/intel-clean.html");
  EXPECT_NE(page.find("<tr class=\"baseline\">"), std::string::npos) << page;
  EXPECT_NE(page.find("baseline: the odometry as the robot recorded it"), std::string::npos);
  EXPECT_NE(page.find("not ranked: 1 of 3 runs did not succeed"), std::string::npos);
  // Nine runs are too few for the validity study: the map metrics are shown, none marked, and the
  // note under the table says so for each.
  EXPECT_NE(page.find("<ul class=\"table-notes\">"), std::string::npos);
  EXPECT_NE(page.find("Corners: not marked best: the validity study of this sequence does not show that it tracks"),
            std::string::npos);
  const std::size_t map_table = page.find("Map metrics without ground truth");
  ASSERT_NE(map_table, std::string::npos);
  EXPECT_EQ(page.find("▼ best", map_table), std::string::npos);
}

TEST_F(WriteReportTest, SequenceWithoutReferenceRendersSensibly) {
  Write();
  const std::string page = ReadAll(dir_ / "report/sequences/mit-no-ref-clean.html");
  EXPECT_NE(page.find("Table I is not available"), std::string::npos);
  EXPECT_NE(page.find("median run by corner count, iteration 1"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "report/files/gmapping/mit-no-ref-clean/reference.tum"));
  const std::string rmse = ReadAll(dir_ / "report/files/gmapping/mit-no-ref-clean/rmse.txt");
  EXPECT_NE(rmse.find("rmse_mean: n/a"), std::string::npos);
}

// A log of part of a run: the relations outside it are named as such on the sequence page, apart from the
// table's numbers, and never as relations the runs missed.
TEST(WriteReportRelationsTest, RelationsOutsideThePartialLogAreShownAsOutsideTheLog) {
  TempDir dir;
  std::vector<testing::FixtureRun> runs;
  for (int i = 0; i < 2; ++i) {
    testing::FixtureRun run = testing::MakeRun("cartographer", "intel-full-rate", i);
    run.with_reference = false;
    run.relations_mean_m = 0.02 + 0.01 * i;
    run.relations_used = 1033;
    run.relations_outside_log = 1951;
    run.corners = 30;
    runs.push_back(run);
  }
  testing::WriteFixtureSweep(dir / "sweep", runs);
  testing::FakeArtwork artwork;
  ReportOptions options;
  options.artwork = &artwork;
  WriteReport(dir / "sweep", dir / "report", options);
  const std::string page = ReadAll(dir / "report/sequences/intel-full-rate-clean.html");
  EXPECT_NE(page.find("scored on the 1033 relations with both stamps inside this log; 1951 more of the relations "
                      "file lie outside the log"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("Relations translation mean"), std::string::npos);
}

TEST_F(WriteReportTest, TextFilesOfThePaperService) {
  Write();
  const std::string rmse = ReadAll(dir_ / "report/files/gmapping/intel-clean/rmse.txt");
  EXPECT_NE(rmse.find("n: 3\n"), std::string::npos) << rmse;
  EXPECT_NE(rmse.find("rmse_mean: 0.11"), std::string::npos) << rmse;
  EXPECT_NE(rmse.find("specification: alignment se2"), std::string::npos) << rmse;
  const std::string single = ReadAll(dir_ / "report/files/single/intel-clean/rmse.txt");
  EXPECT_NE(single.find("rmse_std: n/a"), std::string::npos) << single;
  const std::string corners = ReadAll(dir_ / "report/files/gmapping/mit-no-ref-clean/corners.txt");
  EXPECT_NE(corners.find("corners_mean: 29\n"), std::string::npos) << corners;
  EXPECT_NE(corners.find("corners_std: 1\n"), std::string::npos) << corners;
  // The pose log is the median run's trajectory (iteration 1).
  EXPECT_EQ(ReadAll(dir_ / "report/files/gmapping/intel-clean/pose_log.tum"),
            ReadAll(dir_ / "sweep/runs/gmapping-intel-clean-i1-0000abcd/trajectory.tum"));
}

TEST_F(WriteReportTest, TheSweepsTablesAreCopiedNotRecomputed) {
  // summary.csv (one line per comparison group) and runs.csv come from the orchestrator: the report
  // links the sweep's own files, so the numbers a user downloads are the numbers the sweep recorded.
  Write();
  EXPECT_EQ(ReadAll(dir_ / "report/summary.csv"), ReadAll(dir_ / "sweep/summary.csv"));
  EXPECT_EQ(ReadAll(dir_ / "report/runs.csv"), ReadAll(dir_ / "sweep/runs.csv"));
  const std::string index = ReadAll(dir_ / "report/index.html");
  EXPECT_NE(index.find("href=\"summary.csv\""), std::string::npos);
  EXPECT_NE(index.find("href=\"runs.csv\""), std::string::npos);
  fs::remove(dir_ / "sweep/runs.csv");
  Write();
  EXPECT_FALSE(fs::exists(dir_ / "report/runs.csv"));
  EXPECT_EQ(ReadAll(dir_ / "report/index.html").find("href=\"runs.csv\""), std::string::npos);
  EXPECT_TRUE(testing::BrokenLinks(dir_ / "report").empty());
}

TEST_F(WriteReportTest, PlotsGetEveryIterationPerAlgorithm) {
  Write();
  ASSERT_FALSE(artwork_.plots.empty());
  bool found = false;
  for (const PlotRequest& plot : artwork_.plots) {
    EXPECT_TRUE(plot.log_scale);
    if (plot.title != "intel, noise clean: ATE translation RMSE, alignment se2") continue;
    found = true;
    ASSERT_EQ(plot.series.size(), 3u);
    EXPECT_EQ(plot.series[1].algorithm, "gmapping");
    ASSERT_EQ(plot.series[1].values.size(), 3u);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(plot.series[1].values[i], 0.10 + 0.01 * i, 1e-12);
  }
  EXPECT_TRUE(found);
  // 2 sequences: intel has ATE + 3 map metrics, mit-no-ref the 3 map metrics.
  EXPECT_EQ(artwork_.plots.size(), 7u);
}

TEST_F(WriteReportTest, FailedImagesAreNamedNotLinked) {
  artwork_.fail_thumbnails = true;
  const ReportSummary summary = Write();
  EXPECT_EQ(summary.images_missing, 4u);
  const std::string page = ReadAll(dir_ / "report/runs/gmapping-intel-clean-i1-0000abcd.html");
  EXPECT_NE(page.find("Map thumbnail not made: thumbnail maker broke on map.pgm"), std::string::npos);
  EXPECT_TRUE(testing::BrokenLinks(dir_ / "report").empty());
}

TEST_F(WriteReportTest, WithoutArtworkThereAreNoImages) {
  options_.artwork = nullptr;
  Write();
  EXPECT_TRUE(testing::ImageSources(dir_ / "report/index.html").empty());
  EXPECT_NE(ReadAll(dir_ / "report/index.html").find("Plot not available"), std::string::npos);
  EXPECT_TRUE(testing::BrokenLinks(dir_ / "report").empty());
}

TEST_F(WriteReportTest, RerunReplacesAndForeignFolderIsRefused) {
  Write();
  Write();  // a report folder may be rewritten
  fs::create_directories(dir_ / "other");
  slamsweep::testing::WriteFile(dir_ / "other/precious.txt", "keep");
  EXPECT_THROW(WriteReport(dir_ / "sweep", dir_ / "other", options_), evaluator::InputError);
  EXPECT_TRUE(fs::exists(dir_ / "other/precious.txt"));
  EXPECT_THROW(WriteReport(dir_ / "nowhere", dir_ / "r2", options_), evaluator::InputError);
}

TEST_F(WriteReportTest, HostileRunFolderNamesStayInside) {
  testing::FixtureRun run = testing::MakeRun("x", "s", 0);
  run.run_id = "a b&c<d>";
  run.corners = 3.0;
  testing::WriteFixtureSweep(dir_ / "sweep", {run});
  Write();
  EXPECT_NE(ReadAll(dir_ / "report/sequences/s-clean.html").find("a b&amp;c&lt;d&gt;"), std::string::npos);
  EXPECT_TRUE(testing::BrokenLinks(dir_ / "report").empty());
}

TEST_F(WriteReportTest, UnreadableRunIsShownWithItsReason) {
  slamsweep::testing::WriteFile(dir_ / "sweep/runs/gmapping-intel-clean-i0-0000abcd/result.json", "{broken");
  Write();
  const std::string page = ReadAll(dir_ / "report/runs/gmapping-intel-clean-i0-0000abcd.html");
  EXPECT_NE(page.find("Status: unreadable"), std::string::npos);
  EXPECT_NE(page.find("result.json: expected JSON"), std::string::npos);
}

TEST_F(WriteReportTest, LogTailShowsTheLastLines) {
  testing::FixtureRun run = testing::MakeRun("x", "s", 0);
  run.corners = 3.0;
  run.log.clear();
  for (int i = 0; i < 100; ++i) run.log += "line " + std::to_string(i) + "\n";
  testing::WriteFixtureSweep(dir_ / "sweep", {run});
  options_.log_tail_lines = 10;
  Write();
  const std::string page = ReadAll(dir_ / "report/runs/x-s-clean-i0-0000abcd.html");
  EXPECT_NE(page.find("line 90\nline 91"), std::string::npos);
  EXPECT_NE(page.find("line 99\n"), std::string::npos);
  EXPECT_EQ(page.find("line 89\n"), std::string::npos);
  EXPECT_NE(page.find("Only the last lines are shown"), std::string::npos);
  // The whole log is downloadable.
  EXPECT_EQ(ReadAll(dir_ / "report/runs/x-s-clean-i0-0000abcd/log.txt"), run.log);
}

TEST_F(WriteReportTest, StagePathsLeavingTheRunFolderAreIgnored) {
  const fs::path run_dir = dir_ / "sweep/runs/gmapping-intel-clean-i0-0000abcd";
  std::string result = ReadAll(run_dir / "result.json");
  const std::string stage = "\"stages/stage_0000.png\"";
  result.replace(result.find(stage), stage.size(), "\"../gmapping-intel-clean-i1-0000abcd/stages/stage_0000.png\"");
  slamsweep::testing::WriteFile(run_dir / "result.json", result);
  Write();
  // The other two stages are still used; nothing outside the run folder is read.
  EXPECT_EQ(artwork_.gifs, 9);
  EXPECT_EQ(artwork_.stages.size(), 9u * 3u - 1u);
  for (const fs::path& stage : artwork_.stages) EXPECT_EQ(stage.string().find(".."), std::string::npos) << stage;
  EXPECT_TRUE(testing::BrokenLinks(dir_ / "report").empty());
}

TEST_F(WriteReportTest, EveryPageLinksTheMetricSpecification) {
  Write();
  const std::string spec = ReadAll(dir_ / "report/metrics.html");
  // Every metric a page shows is defined, the map-versus-reference scores included.
  for (const char* metric : {"ape_trans", "rpe_trans", "relations_trans", "occupied_to_free_unknown", "corners",
                             "enclosed_areas", "map_chamfer", "map_accuracy", "map_completeness", "map_f1",
                             "map_iou_occupied", "map_iou_free", "wall_s", "peak_rss_kb", "spearman_rho"}) {
    EXPECT_NE(spec.find("<code>" + std::string(metric) + "</code>"), std::string::npos) << metric;
  }
  for (const char* page :
       {"index.html", "sequences/intel-clean.html", "runs/gmapping-intel-clean-i1-0000abcd.html", "validity.html"}) {
    const std::string root = std::string(page).find('/') == std::string::npos ? "" : "../";
    EXPECT_NE(ReadAll(dir_ / "report" / page).find("<a href=\"" + root + "metrics.html\">metric specification</a>"),
              std::string::npos)
        << page;
  }
}

TEST_F(WriteReportTest, FewRunsGiveNoCorrelation) {
  // The standard sweep has 6 successful runs with an ATE on intel: below 8, no number.
  Write();
  const std::string page = ReadAll(dir_ / "report/validity.html");
  EXPECT_NE(page.find("too few runs"), std::string::npos);
  EXPECT_EQ(page.find("ρ ="), std::string::npos);
  EXPECT_NE(ReadAll(dir_ / "report/index.html").find("href=\"validity.html\""), std::string::npos);
}

// The study summary.json carries is the report's when it was drawn from the same runs by the same program
// (its inputs_sha256); a stored study that does not match is never shown. A planted verdict tells which
// one the page shows.
TEST_F(WriteReportTest, TheSweepsStoredValidityStudyIsTakenOnlyForTheSameInputs) {
  fs::remove_all(dir_ / "sweep");
  testing::WriteFixtureSweep(dir_ / "sweep", testing::ValidityFixtureRuns());
  const std::vector<evaluator::ValidityRun> inputs = orchestrator::ToValidityRuns(LoadRuns(dir_ / "sweep"));
  nlohmann::json validity = evaluator::ToJson(evaluator::ComputeValidityStudy(inputs));
  for (nlohmann::json& c : validity.at("correlations")) {
    if (c.at("verdict") == "tracks error") c["verdict"] = "opposite";  // planted: the computed study says otherwise
  }
  const auto write_summary = [&](const std::string& digest) {
    nlohmann::json summary = nlohmann::json::parse(ReadAll(dir_ / "sweep/summary.json"));
    summary["validity"] = validity;
    summary["validity"]["inputs_sha256"] = digest;
    slamsweep::testing::WriteFile(dir_ / "sweep/summary.json", summary.dump());
  };

  write_summary(orchestrator::ValidityInputsDigest(inputs));
  Write();
  const std::string planted = ReadAll(dir_ / "report/validity.html");
  EXPECT_EQ(planted.find("n=9, tracks error"), std::string::npos);
  EXPECT_NE(planted.find("n=9, opposite"), std::string::npos);

  std::vector<evaluator::ValidityRun> other = inputs;
  other.pop_back();
  write_summary(orchestrator::ValidityInputsDigest(other));
  Write();
  const std::string computed = ReadAll(dir_ / "report/validity.html");
  EXPECT_NE(computed.find("n=9, tracks error"), std::string::npos);
}

TEST_F(WriteReportTest, TheValidityPageShowsCorrelationsIntervalsAndPlots) {
  fs::remove_all(dir_ / "sweep");
  testing::WriteFixtureSweep(dir_ / "sweep", testing::ValidityFixtureRuns());
  slamsweep::testing::WriteFile(dir_ / "sweep/validity.csv", "candidate,target\n");
  Write();
  const std::string page = ReadAll(dir_ / "report/validity.html");
  EXPECT_NE(page.find("Which metrics can be trusted?"), std::string::npos);
  // Corners rise exactly with the ATE on each sequence: +1 with a degenerate interval, all 9 runs.
  EXPECT_NE(page.find("<td class=\"verdict-tracks\">ρ = +1.00 [+1.00, +1.00]<br><span class=\"n\">n=9, tracks error"),
            std::string::npos);
  // Over both sequences (never ranked together), still exactly +1 with all 18 runs.
  EXPECT_NE(page.find("n=18, tracks error"), std::string::npos);
  // The occupied ratio falls with it; enclosed areas never change.
  EXPECT_NE(page.find("<td class=\"verdict-opposite\">ρ = -1.00 [-1.00, -1.00]"), std::string::npos);
  EXPECT_NE(page.find("no variation"), std::string::npos);
  EXPECT_NE(page.find("Against Map vs reference: Chamfer distance"), std::string::npos);
  EXPECT_EQ(page.find("Against Relations"), std::string::npos);  // no relations in this sweep
  EXPECT_NE(page.find("href=\"validity.csv\""), std::string::npos);
  EXPECT_EQ(ReadAll(dir_ / "report/validity.csv"), "candidate,target\n");  // the sweep's own file, copied

  // One scatter plot per real error x candidate with values x sequence: 2 x 6 x 2.
  ASSERT_EQ(artwork_.scatter_plots.size(), 24u);
  const ScatterPlot* corners = nullptr;
  for (const ScatterPlotJob& job : artwork_.scatter_plots) {
    EXPECT_TRUE(fs::exists(job.png)) << job.png;
    const ScatterPlot& plot = job.plot;
    if (plot.title == "intel" && plot.x_label == "Corners (count)" && plot.y_label == "ATE translation RMSE (m)") {
      corners = &plot;
    }
  }
  ASSERT_NE(corners, nullptr);
  EXPECT_NE(page.find("<figcaption>intel: Corners vs ATE translation RMSE</figcaption>"), std::string::npos);
  // No run has the other occupied proportions: no rows for them.
  EXPECT_EQ(page.find("Unknown / all cells"), std::string::npos);
  // A series per noise setting, in natural order: odo-1, odo-2, odo-10, graded light to dark, and the
  // key says the colour is the noise setting; the marker is icp-slam's, as in every plot of the report.
  std::string labels;
  for (const ScatterSeries& series : corners->series) labels += series.label + ";";
  ASSERT_EQ(corners->series.size(), 3u) << labels;
  EXPECT_EQ(corners->series[0].label, "odo-1");
  EXPECT_EQ(corners->series[2].label, "odo-10");
  EXPECT_EQ(corners->series[2].x, (std::vector<double>{100.0, 101.0, 102.0}));
  EXPECT_EQ(corners->key_title, "colour: noise setting");
  EXPECT_EQ(corners->series[0].style.rgb, GradedColour(0, 3));
  EXPECT_EQ(corners->series[2].style.rgb, GradedColour(2, 3));
  const int icp_marker = AlgorithmPalette({"icp-slam"}).StyleOf("icp-slam").point_type;
  for (const ScatterSeries& series : corners->series) EXPECT_EQ(series.style.point_type, icp_marker) << series.label;
  EXPECT_NE(page.find("colour: its noise setting"), std::string::npos);
  EXPECT_EQ(testing::ImageSources(dir_ / "report/validity.html").size(), 24u);
  EXPECT_TRUE(testing::BrokenLinks(dir_ / "report").empty())
      << ::testing::PrintToString(testing::BrokenLinks(dir_ / "report"));
}

/// The report of `runs` (icp-slam and gmapping on the validity fixture) and its first scatter plot
/// (intel's, "Occupied proportion" against the ATE).
class ValidityPlotTest : public WriteReportTest {
 protected:
  const ScatterPlot& FirstValidityPlot(const std::vector<testing::FixtureRun>& runs) {
    fs::remove_all(dir_ / "sweep");
    testing::WriteFixtureSweep(dir_ / "sweep", runs);
    Write();
    if (artwork_.scatter_plots.empty()) throw std::runtime_error("no scatter plot was planned");
    return artwork_.scatter_plots.front().plot;
  }
};

TEST_F(ValidityPlotTest, ValidityPlotsOfSeveralAlgorithmsMarkEachWithItsPaletteMarker) {
  std::vector<testing::FixtureRun> runs = testing::ValidityFixtureRuns();
  for (testing::FixtureRun run : testing::ValidityFixtureRuns()) {
    run.algorithm = "gmapping";
    runs.push_back(run);
  }
  const ScatterPlot& plot = FirstValidityPlot(runs);
  const AlgorithmPalette palette({"icp-slam", "gmapping"});
  EXPECT_EQ(plot.key_title, "colour: noise setting, marker: algorithm");
  std::string labels;
  for (const ScatterSeries& series : plot.series) labels += series.label + ";";
  // Noise settings in natural order, the algorithms by name within each; colour by setting, marker by algorithm.
  EXPECT_EQ(labels,
            "odo-1 · gmapping;odo-1 · icp-slam;odo-2 · gmapping;odo-2 · icp-slam;odo-10 · gmapping;"
            "odo-10 · icp-slam;");
  ASSERT_EQ(plot.series.size(), 6u);
  EXPECT_EQ(plot.series[0].style.rgb, plot.series[1].style.rgb);
  EXPECT_EQ(plot.series[4].style.rgb, GradedColour(2, 3));
  EXPECT_EQ(plot.series[0].style.point_type, palette.StyleOf("gmapping").point_type);
  EXPECT_EQ(plot.series[1].style.point_type, palette.StyleOf("icp-slam").point_type);
  EXPECT_NE(plot.series[0].style.point_type, plot.series[1].style.point_type);
}

TEST_F(ValidityPlotTest, ValidityPlotsOfOneNoiseSettingColourEachAlgorithmAsEverywhere) {
  std::vector<testing::FixtureRun> runs;
  for (testing::FixtureRun run : testing::ValidityFixtureRuns()) {
    if (run.noise != "odo-2") continue;
    runs.push_back(run);
    run.algorithm = "gmapping";
    run.corners = *run.corners + 1.0;
    runs.push_back(run);
  }
  const ScatterPlot& plot = FirstValidityPlot(runs);
  const AlgorithmPalette palette({"icp-slam", "gmapping"});
  EXPECT_EQ(plot.key_title, "algorithm (noise setting odo-2)");
  ASSERT_EQ(plot.series.size(), 2u);
  EXPECT_EQ(plot.series[0].label, "gmapping");
  EXPECT_EQ(plot.series[0].style.rgb, palette.StyleOf("gmapping").rgb);
  EXPECT_EQ(plot.series[0].style.point_type, palette.StyleOf("gmapping").point_type);
  EXPECT_EQ(plot.series[1].label, "icp-slam");
  EXPECT_EQ(plot.series[1].style.rgb, palette.StyleOf("icp-slam").rgb);
}

TEST_F(WriteReportTest, WithoutReferenceDataThereIsNoValidityPage) {
  Write();
  ASSERT_TRUE(fs::exists(dir_ / "report/validity.html"));
  testing::FixtureRun run = testing::MakeRun("x", "s", 0);
  run.with_reference = false;
  run.corners = 3.0;
  fs::remove_all(dir_ / "sweep");
  testing::WriteFixtureSweep(dir_ / "sweep", {run});
  Write();
  EXPECT_FALSE(fs::exists(dir_ / "report/validity.html"));  // the earlier report's page is gone
  EXPECT_EQ(ReadAll(dir_ / "report/index.html").find("validity.html"), std::string::npos);
  EXPECT_TRUE(testing::BrokenLinks(dir_ / "report").empty());
}

TEST_F(WriteReportTest, DrawsEveryRowsTrajectoryOverTheReferenceAndEachPathsError) {
  Write();
  // intel has a reference and three rows with a median run (gmapping, the hostile name, single); mit-no-ref has none.
  std::vector<const PathFigure*> paths;
  for (const FigureJob& job : artwork_.figures) {
    if (const auto* path = std::get_if<PathFigure>(&job.figure)) paths.push_back(path);
  }
  // The figure of every row, one per median run, then one per other successful run on intel (gmapping's
  // iterations 0 and 2, the hostile name's iteration 1: its iteration 2 failed).
  ASSERT_EQ(paths.size(), 1u + 3u + 3u);
  const PathFigure& together = *paths[0];
  ASSERT_EQ(together.series.size(), 1u + 3u);
  EXPECT_TRUE(together.series[0].reference);
  EXPECT_EQ(together.series[0].label, "reference");
  for (std::size_t s = 1; s < together.series.size(); ++s) {
    EXPECT_FALSE(together.series[s].reference);
    EXPECT_TRUE(together.series[s].colour_values.empty());
    EXPECT_FALSE(together.series[s].x.empty());
  }
  for (std::size_t f = 1; f < paths.size(); ++f) {
    ASSERT_EQ(paths[f]->series.size(), 2u);
    const PathSeries& path = paths[f]->series[1];
    ASSERT_EQ(path.colour_values.size(), path.x.size());
    for (const double error : path.colour_values) EXPECT_GE(error, 0.0);
  }
  const std::string page = ReadAll(dir_ / "report" / "sequences" / "intel-clean.html");
  EXPECT_NE(page.find("<h2>Trajectories</h2>"), std::string::npos);
  EXPECT_NE(page.find("intel-clean/trajectories.png"), std::string::npos);
  EXPECT_NE(page.find("intel-clean/path-error-0.png"), std::string::npos);
  EXPECT_EQ(ReadAll(dir_ / "report" / "sequences" / "mit-no-ref-clean.html").find("<h2>Trajectories</h2>"),
            std::string::npos);
}

TEST_F(WriteReportTest, EveryRunPageShowsItsErrorAlongThePath) {
  Write();
  const fs::path report = dir_ / "report";
  // A run that is not its row's median run has its own figure, drawn in the figure batch.
  const std::string other = ReadAll(report / "runs/gmapping-intel-clean-i0-0000abcd.html");
  EXPECT_NE(other.find("src=\"../runs/gmapping-intel-clean-i0-0000abcd/path-error.png\""), std::string::npos);
  EXPECT_TRUE(fs::is_regular_file(report / "runs/gmapping-intel-clean-i0-0000abcd/path-error.png"));
  std::size_t own = 0;
  for (const FigureJob& job : artwork_.figures) {
    if (job.png.filename() == "path-error.png") {
      ++own;
      EXPECT_NE(FigureTitle(job.figure).find("-i"), std::string::npos) << "the title names the run";
    }
  }
  EXPECT_EQ(own, 3u);
  // The median run (iteration 1) shows its table's figure, not a second drawing of it.
  const std::string median = ReadAll(report / "runs/gmapping-intel-clean-i1-0000abcd.html");
  EXPECT_NE(median.find("src=\"../sequences/intel-clean/path-error-"), std::string::npos);
  EXPECT_FALSE(fs::exists(report / "runs/gmapping-intel-clean-i1-0000abcd/path-error.png"));
  // Without a reference there is no error to colour by.
  EXPECT_EQ(ReadAll(report / "runs/gmapping-mit-no-ref-clean-i0-0000abcd.html").find("path-error"), std::string::npos);
  EXPECT_TRUE(testing::BrokenLinks(report).empty());
}

TEST_F(WriteReportTest, BeyondTheEveryRunLimitOnlyMedianRunsGetTheErrorAlongThePath) {
  options_.figures_for_every_run_up_to = 2;
  Write();
  for (const FigureJob& job : artwork_.figures) EXPECT_NE(job.png.filename(), "path-error.png") << job.png;
  EXPECT_EQ(ReadAll(dir_ / "report/runs/gmapping-intel-clean-i0-0000abcd.html").find("path-error"), std::string::npos);
  EXPECT_NE(ReadAll(dir_ / "report/runs/gmapping-intel-clean-i1-0000abcd.html").find("path-error"), std::string::npos);
}

TEST_F(WriteReportTest, RunFoldersWithoutAVectorMapGetOneTracedFromTheirMap) {
  std::vector<testing::FixtureRun> runs = testing::StandardFixtureRuns();
  for (testing::FixtureRun& run : runs) run.vector_map = false;
  fs::remove_all(dir_ / "sweep");
  testing::WriteFixtureSweep(dir_ / "sweep", runs);
  options_.figures_for_every_run_up_to = 2;  // own figures (and the vector map) for median and failed runs only
  Write();
  const fs::path report = dir_ / "report";
  // gmapping on intel: iteration 1 is the median run (ATE 0.10 0.11 0.12), iteration 0 is not.
  const fs::path traced = report / "runs/gmapping-intel-clean-i1-0000abcd/map.geojson";
  ASSERT_TRUE(fs::is_regular_file(traced));
  const nlohmann::json geojson = nlohmann::json::parse(ReadAll(traced));
  EXPECT_EQ(geojson.at("type"), "FeatureCollection");
  EXPECT_FALSE(geojson.at("features").empty());  // the room's walls
  EXPECT_NE(ReadAll(report / "runs/gmapping-intel-clean-i1-0000abcd.html").find("map.geojson"), std::string::npos);
  EXPECT_FALSE(fs::exists(report / "runs/gmapping-intel-clean-i0-0000abcd/map.geojson"));
  EXPECT_EQ(ReadAll(report / "runs/gmapping-intel-clean-i0-0000abcd.html").find("map.geojson"), std::string::npos);
  EXPECT_TRUE(testing::BrokenLinks(report).empty());
}

TEST_F(WriteReportTest, TheIndexOpensWithTheRankedOverviewAndItsVerdict) {
  Write();
  const std::string index = ReadAll(dir_ / "report" / "index.html");
  const std::size_t overview = index.find("Which is better, and is the difference real?");
  ASSERT_NE(overview, std::string::npos);
  EXPECT_LT(overview, index.find("Sequence intel"));
  EXPECT_NE(index.find("ATE translation RMSE (m), mean [95 % interval]"), std::string::npos);
  EXPECT_NE(index.find("only ground-truth-free metrics"), std::string::npos);  // mit-no-ref
}

TEST_F(WriteReportTest, ASequenceWhoseScansAreTooFarApartIsMarkedAndItsDensityShown) {
  std::vector<testing::FixtureRun> runs = testing::DensityFixtureRuns();
  runs.push_back(testing::MakeRun("gmapping", "old-sweep", 0));  // recorded before the block
  testing::WriteFixtureSweep(dir_ / "density", runs);
  WriteReport(dir_ / "density", dir_ / "report", options_);

  const std::string intel = ReadAll(dir_ / "report/sequences/intel-clean.html");
  const std::size_t mark = intel.find("<p class=\"sparse-data\">Sparse data: scans too far apart for scan matching");
  ASSERT_NE(mark, std::string::npos) << intel;
  EXPECT_LT(mark, intel.find("<table>"));  // above the tables it qualifies
  EXPECT_NE(intel.find("0.67 m apart at the median (by the odometry), beyond 0.12 m"), std::string::npos);
  EXPECT_NE(intel.find("<h2>Data density</h2>"), std::string::npos);
  EXPECT_NE(intel.find("<th>Travel (m)</th><td class=\"num\">0.6700</td><td class=\"num\">1.050</td>"),
            std::string::npos)
      << intel;
  EXPECT_NE(intel.find("<th>Time gap (s)</th><td class=\"num\">3.310</td><td class=\"num\">4.890</td>"),
            std::string::npos);
  EXPECT_NE(intel.find("909 steps"), std::string::npos);
  EXPECT_NE(ReadAll(dir_ / "report/index.html").find("<p class=\"sparse-data\">"), std::string::npos);

  const std::string other = ReadAll(dir_ / "report/sequences/mit-no-ref-clean.html");
  EXPECT_EQ(other.find("sparse-data"), std::string::npos);
  EXPECT_NE(other.find("Dense enough for scan matching"), std::string::npos);
  EXPECT_NE(ReadAll(dir_ / "report/sequences/old-sweep-clean.html").find("Not recorded"), std::string::npos);

  // The mark is styled by the site's stylesheet, never inline.
  EXPECT_EQ(AllPages().find(" style="), std::string::npos);
  EXPECT_NE(ReadAll(dir_ / "report/style.css").find("p.sparse-data"), std::string::npos);
}

}  // namespace
}  // namespace slamsweep::report
