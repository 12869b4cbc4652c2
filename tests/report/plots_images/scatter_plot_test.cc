// The validity page's scatter plots: graded noise colours, each series' marker, the key's title, and
// real PNGs drawn by gnuplot whose pixels show every series in its colour. A copy of each PNG is kept
// beside the test binary for a person to look at.
#include "report/plots/scatter_plot.h"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <opencv2/imgcodecs.hpp>

#include "report/plots/view_figure_scripts.h"
#include "tests/report/plots_images/plot_pixels.h"
#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

namespace fs = std::filesystem;
using slamsweep::testing::CountColour;
using ::testing::HasSubstr;
using ::testing::Not;

double Luminance(std::uint32_t rgb) {
  return 0.2126 * ((rgb >> 16) & 0xFF) + 0.7152 * ((rgb >> 8) & 0xFF) + 0.0722 * (rgb & 0xFF);
}

/// Three noise settings of one algorithm (icp-slam's pentagon) and one point of another (gmapping's circle).
ScatterPlot NoiseScatter() {
  ScatterPlot plot;
  plot.title = "intel";
  plot.x_label = "Corners (count)";
  plot.y_label = "ATE translation RMSE (m)";
  plot.key_title = "colour: noise setting, marker: algorithm";
  for (std::size_t level = 0; level < 3; ++level) {
    ScatterSeries series{"odo-" + std::to_string(level + 1) + " · icp-slam", {GradedColour(level, 3), 15, 0}, {}, {}};
    for (int i = 0; i < 5; ++i) {
      series.x.push_back(10.0 * static_cast<double>(level + 1) + i);
      series.y.push_back(0.1 * static_cast<double>(level + 1) + 0.01 * i);
    }
    plot.series.push_back(series);
  }
  plot.series.push_back({"odo-1 · gmapping", {GradedColour(0, 3), 7, 0}, {12.0}, {0.12}});
  return plot;
}

TEST(ScatterPlotTest, GradedColoursRunFromLightToDarkOnTheHeatmapScaleWithoutItsPalestPart) {
  EXPECT_EQ(GradedColour(4, 5), HeatmapColour(1.0));
  EXPECT_EQ(GradedColour(0, 5), HeatmapColour(0.2));
  EXPECT_EQ(GradedColour(0, 1), HeatmapColour(1.0));  // a single setting: the darkest, best seen
  for (std::size_t i = 1; i < 8; ++i) {
    EXPECT_GT(Luminance(GradedColour(i - 1, 8)), Luminance(GradedColour(i, 8))) << i;
  }
  // The heatmaps' palest yellow is too faint for a point on white: the lightest shade is darker.
  EXPECT_LT(Luminance(GradedColour(0, 8)), Luminance(HeatmapColour(0.0)) - 20.0);
}

TEST(ScatterPlotTest, ScriptDrawsEachSeriesInItsColourAndMarkerUnderTheKeyTitle) {
  const ScatterPlot plot = NoiseScatter();
  const std::string script = ScatterPlotScript(plot, "/tmp/x.png", 3);
  EXPECT_THAT(script, HasSubstr("print 'SLAMSWEEP_PLOT 3'"));
  EXPECT_THAT(script, HasSubstr("set key title 'colour: noise setting, marker: algorithm'"));
  EXPECT_THAT(script, HasSubstr("set key below"));
  EXPECT_THAT(script,
              HasSubstr(fmt::format("pointtype 15 pointsize 0.9 linecolor rgb '#{:06X}' title 'odo-1 · icp-slam'",
                                    GradedColour(0, 3))));
  EXPECT_THAT(script,
              HasSubstr(fmt::format("pointtype 15 pointsize 0.9 linecolor rgb '#{:06X}' title 'odo-3 · icp-slam'",
                                    GradedColour(2, 3))));
  EXPECT_THAT(script, HasSubstr("pointtype 7 pointsize 0.9"));
  EXPECT_THAT(script, HasSubstr("intel (16 runs)"));
  // Corners span 10-34 (a factor below 10): linear; the ATE spans 0.1-0.34: linear too.
  EXPECT_THAT(script, Not(HasSubstr("set logscale")));
  const std::size_t odo1 = script.find("title 'odo-1 · icp-slam'");
  const std::size_t odo3 = script.find("title 'odo-3 · icp-slam'");
  EXPECT_LT(odo1, odo3) << "the key lists the settings in their order";
}

TEST(ScatterPlotTest, NonFinitePointsAreLeftOutAndWideRangesGetALogAxis) {
  ScatterPlot plot;
  plot.title = "floor";
  const double nan = std::numeric_limits<double>::quiet_NaN();
  plot.series.push_back({"odo-1", {}, {0.01, 1.0, nan, 5.0}, {1.0, 2.0, 3.0, std::numeric_limits<double>::infinity()}});
  const std::string script = ScatterPlotScript(plot, "/tmp/x.png", 0);
  EXPECT_THAT(script, HasSubstr("floor (2 runs)"));
  EXPECT_THAT(script, HasSubstr("set logscale x"));
  EXPECT_THAT(script, Not(HasSubstr("set logscale y")));
  EXPECT_THAT(script, Not(HasSubstr("set key title")));  // no key title asked for, none drawn
}

TEST(ScatterPlotTest, GnuplotDrawsEverySeriesInItsColour) {
  REQUIRE_GNUPLOT();
  slamsweep::testing::TempDir dir;
  ScatterPlot empty;
  empty.title = "no runs";
  const std::vector<ScatterPlotJob> jobs = {{NoiseScatter(), dir / "validity-scatter.png"}, {empty, dir / "empty.png"}};
  WriteScatterPlots(jobs);
  const cv::Mat image = slamsweep::testing::ReadAndKeep(jobs[0].png);
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.cols, 560);
  for (std::size_t level = 0; level < 3; ++level) EXPECT_GT(CountColour(image, GradedColour(level, 3)), 20) << level;
  EXPECT_FALSE(cv::imread(jobs[1].png.string(), cv::IMREAD_COLOR).empty());
}

}  // namespace
}  // namespace slamsweep::report
