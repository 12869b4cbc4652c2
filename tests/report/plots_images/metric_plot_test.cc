#include "report/plots/metric_plot.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "report/plots/gnuplot_process.h"
#include "tests/report/plots_images/plot_pixels.h"
#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

using ::testing::HasSubstr;

using slamsweep::testing::CountColour;

cv::Mat ReadPng(const std::filesystem::path& path) {
  const cv::Mat image = cv::imread(path.string(), cv::IMREAD_COLOR);
  EXPECT_FALSE(image.empty()) << path << " is not a readable PNG";
  return image;
}

MetricPlot TwoAlgorithms() {
  MetricPlot plot;
  plot.title = "ATE rmse (se2), telecom";
  plot.y_label = "m";
  // Each series in its algorithm's style (AlgorithmPalette): blue circles and vermillion squares.
  plot.series = {{"icp-slam", {0.12, 0.15, 0.11, 0.2}, {0x0072B2, 7, 0}},
                 {"rbpf-slam", {0.4, 0.35, 0.5}, {0xD55E00, 5, 0}}};
  return plot;
}

TEST(WriteMetricPlotsTest, WritesEveryPlotAsPngInOneCall) {
  REQUIRE_GNUPLOT();
  testing::TempDir dir;
  std::vector<MetricPlotJob> jobs;
  for (int i = 0; i < 3; ++i) jobs.push_back({TwoAlgorithms(), dir / ("plot" + std::to_string(i) + ".png")});
  WriteMetricPlots(jobs);
  for (const auto& job : jobs) {
    const cv::Mat image = ReadPng(job.png);
    EXPECT_EQ(image.cols, 800);
    EXPECT_EQ(image.rows, 480);
    // The two algorithms' colours (their styles: Okabe-Ito blue #0072B2 and vermillion #D55E00) are drawn.
    EXPECT_GT(CountColour(image, 0x0072B2), 20);
    EXPECT_GT(CountColour(image, 0xD55E00), 20);
  }
}

TEST(WriteMetricPlotsTest, APlotOfFewColoursIsStoredAsAPalettePng) {
  REQUIRE_GNUPLOT();
  testing::TempDir dir;
  MetricPlot plot = TwoAlgorithms();
  plot.series.pop_back();  // one algorithm: fewer than 256 colours, anti-aliasing included
  const std::filesystem::path png = dir / "one.png";
  WriteMetricPlots({{plot, png}});
  // IHDR colour type 3 (palette): the plot's pixels in far fewer bytes than pngcairo's RGB.
  std::ifstream file(png, std::ios::binary);
  std::string header(26, '\0');
  file.read(header.data(), 26);
  EXPECT_EQ(static_cast<unsigned char>(header[25]), 3u);
  const cv::Mat image = ReadPng(png);
  EXPECT_GT(CountColour(image, 0x0072B2), 20);
}

TEST(WriteMetricPlotsTest, NoJobsDoesNothing) { EXPECT_NO_THROW(WriteMetricPlots({})); }

TEST(WriteMetricPlotsTest, HostileTitlesAndNamesDoNotBreakTheScript) {
  REQUIRE_GNUPLOT();
  testing::TempDir dir;
  const std::filesystem::path marker = dir / "gnuplot-ran-a-command";
  MetricPlot plot = TwoAlgorithms();
  plot.title = "it's \"quoted\" \\ back\\slash `touch " + marker.string() + "` @macro\n<script>alert(1)</script>";
  plot.y_label = "'; system('touch " + marker.string() + "'); '";
  plot.series[0].algorithm = "<script>alert(1)</script>";
  plot.series[1].algorithm = "a'b\"c\\d{e}^f_g&h";
  const MetricPlotJob job{plot, dir / "hostile's \"file\".png"};
  WriteMetricPlots({job});
  ReadPng(job.png);
  EXPECT_FALSE(std::filesystem::exists(marker)) << "a title made gnuplot run a command";
}

TEST(WriteMetricPlotsTest, LogAxisWithZeroValuesDrawsThemAtTheFloor) {
  REQUIRE_GNUPLOT();
  testing::TempDir dir;
  MetricPlot plot;
  plot.title = "enclosed areas";
  plot.series = {{"a", {0.0, 0.0, 3.0}}, {"b", {0.0}, {0xD55E00, 5, 0}}, {"c", {}}};
  const MetricPlotJob job{plot, dir / "zeros.png"};
  WriteMetricPlots({job});
  const cv::Mat image = ReadPng(job.png);
  // Series b (vermillion #D55E00) has a single zero: its point and mean bar are drawn at the floor.
  EXPECT_GT(CountColour(image, 0xD55E00), 20);
}

TEST(WriteMetricPlotsTest, AllZeroOrEmptyPlotsStillRender) {
  REQUIRE_GNUPLOT();
  testing::TempDir dir;
  MetricPlot zeros;
  zeros.series = {{"a", {0.0}}};
  MetricPlot empty;
  empty.title = "no runs";
  MetricPlot no_values;
  no_values.series = {{"failed-everywhere", {}}};
  const std::vector<MetricPlotJob> jobs = {
      {zeros, dir / "zeros.png"}, {empty, dir / "empty.png"}, {no_values, dir / "none.png"}};
  WriteMetricPlots(jobs);
  for (const auto& job : jobs) ReadPng(job.png);
}

TEST(WriteMetricPlotsTest, FailureNamesThePlotThatFailed) {
  REQUIRE_GNUPLOT();
  testing::TempDir dir;
  MetricPlot good = TwoAlgorithms();
  MetricPlot bad = TwoAlgorithms();
  bad.title = "the unwritable one";
  const std::vector<MetricPlotJob> jobs = {
      {good, dir / "good.png"}, {bad, dir / "missing-folder" / "bad.png"}, {good, dir / "good2.png"}};
  try {
    WriteMetricPlots(jobs);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& error) {
    EXPECT_THAT(error.what(), HasSubstr("the unwritable one"));
    EXPECT_THAT(error.what(), HasSubstr("bad.png"));
  }
  ReadPng(dir / "good.png");
}

TEST(RunGnuplotTest, MissingProgramIsAnErrorNamingIt) {
  try {
    RunGnuplot("print 1\n", "/nonexistent/gnuplot");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& error) {
    EXPECT_THAT(error.what(), HasSubstr("/nonexistent/gnuplot"));
  }
}

TEST(RunGnuplotTest, CapturesStderrAndExitCode) {
  REQUIRE_GNUPLOT();
  const GnuplotOutcome ok = RunGnuplot("print 'hello'\n");
  EXPECT_EQ(ok.exit_code, 0);
  EXPECT_EQ(ok.stderr_text, "hello\n");
  const GnuplotOutcome bad = RunGnuplot("plot $nothing\n");
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_THAT(bad.stderr_text, HasSubstr("nothing"));
}

TEST(RunGnuplotTest, LargeScriptAndLargeStderrDoNotDeadlock) {
  REQUIRE_GNUPLOT();
  std::string script;
  for (int i = 0; i < 20000; ++i) script += "print 'line of output number " + std::to_string(i) + "'\n";
  const GnuplotOutcome outcome = RunGnuplot(script);
  EXPECT_EQ(outcome.exit_code, 0);
  EXPECT_THAT(outcome.stderr_text, HasSubstr("number 19999\n"));
}

}  // namespace
}  // namespace slamsweep::report
