#include "report/plots/metric_plot_script.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace slamsweep::report {
namespace {

TEST(ComputeSpreadTest, MeanAndSampleStd) {
  // 2, 4, 4, 4, 5, 5, 7, 9: mean 5, squared deviations sum 32, sample variance 32 / 7.
  const std::vector<double> values = {2, 4, 4, 4, 5, 5, 7, 9};
  const SeriesSpread spread = ComputeSpread(values);
  EXPECT_EQ(spread.n, 8u);
  EXPECT_DOUBLE_EQ(spread.mean, 5.0);
  ASSERT_TRUE(spread.std.has_value());
  EXPECT_DOUBLE_EQ(*spread.std, std::sqrt(32.0 / 7.0));
}

TEST(ComputeSpreadTest, SingleValueHasNoStd) {
  const std::vector<double> values = {0.3};
  const SeriesSpread spread = ComputeSpread(values);
  EXPECT_EQ(spread.n, 1u);
  EXPECT_DOUBLE_EQ(spread.mean, 0.3);
  EXPECT_FALSE(spread.std.has_value());
}

TEST(ComputeSpreadTest, IgnoresNonFiniteValues) {
  const std::vector<double> values = {1.0, std::numeric_limits<double>::quiet_NaN(), 3.0,
                                      std::numeric_limits<double>::infinity()};
  const SeriesSpread spread = ComputeSpread(values);
  EXPECT_EQ(spread.n, 2u);
  EXPECT_DOUBLE_EQ(spread.mean, 2.0);
  EXPECT_DOUBLE_EQ(*spread.std, std::sqrt(2.0));
}

TEST(ComputeSpreadTest, NoValues) {
  const SeriesSpread spread = ComputeSpread({});
  EXPECT_EQ(spread.n, 0u);
  EXPECT_FALSE(spread.std.has_value());
}

TEST(LogAxisFloorTest, OneDecadeBelowTheSmallestPositiveValue) {
  MetricPlot plot;
  plot.series = {{"a", {0.0, 0.034, 2.0}}, {"b", {-1.0, 0.5}}};
  EXPECT_DOUBLE_EQ(LogAxisFloor(plot), 0.001);  // smallest positive 0.034 -> decade 0.01 -> 0.001
  plot.series = {{"a", {250.0, 700.0}}};
  EXPECT_DOUBLE_EQ(LogAxisFloor(plot), 10.0);
}

TEST(LogAxisFloorTest, NoPositiveValue) {
  MetricPlot plot;
  plot.series = {{"a", {0.0, 0.0}}};
  EXPECT_DOUBLE_EQ(LogAxisFloor(plot), 0.1);
}

TEST(MetricPlotScriptTest, NotesValuesAtTheFloorInTheTitle) {
  MetricPlot plot;
  plot.title = "corners";
  plot.series = {{"a", {0.0, 12.0, 0.0}}, {"b", {30.0}}};
  const std::string script = MetricPlotScript(plot, "/tmp/x.png", 3);
  EXPECT_NE(script.find("set title 'corners (2 values <= 0 drawn at the axis floor 1)' noenhanced"), std::string::npos)
      << script;
  EXPECT_NE(script.find("set logscale y"), std::string::npos);
  // The axis starts below the floor (1 / 1.5), which is marked with a "<= 0" tick.
  EXPECT_NE(script.find("set yrange [0.6666666666666666:*]"), std::string::npos) << script;
  EXPECT_NE(script.find("set ytics add ('<= 0' 1)"), std::string::npos);
  EXPECT_NE(script.find("$points_3 << EOD"), std::string::npos);
}

TEST(MetricPlotScriptTest, LinearAxisLeavesZeroValuesAlone) {
  MetricPlot plot;
  plot.title = "t";
  plot.log_scale = false;
  plot.series = {{"a", {0.0, 1.0}}};
  const std::string script = MetricPlotScript(plot, "/tmp/x.png", 0);
  EXPECT_EQ(script.find("logscale"), std::string::npos);
  EXPECT_EQ(script.find("floor"), std::string::npos);
}

TEST(MetricPlotScriptTest, SingleIterationHasNoErrorBar) {
  MetricPlot plot;
  plot.series = {{"a", {0.5}}};
  const std::string script = MetricPlotScript(plot, "/tmp/x.png", 0);
  EXPECT_EQ(script.find("yerrorbars"), std::string::npos);
  EXPECT_NE(script.find("with vectors"), std::string::npos);  // the mean bar is still there
}

TEST(MetricPlotScriptTest, ErrorBarIsMeanPlusMinusSampleStd) {
  MetricPlot plot;
  plot.log_scale = false;
  plot.series = {{"a", {1.0, 3.0}}};  // mean 2, sample std sqrt(2)
  const std::string script = MetricPlotScript(plot, "/tmp/x.png", 0);
  EXPECT_NE(script.find("$bars_0 << EOD\n1 2 0.5857864376269049 3.414213562373095 "), std::string::npos) << script;
}

TEST(MetricPlotScriptTest, LabelsEveryAlgorithmWithItsCount) {
  MetricPlot plot;
  plot.series = {{"gmapping", {1.0, 2.0}}, {"it's", {}}};
  const std::string script = MetricPlotScript(plot, "/tmp/x.png", 0);
  EXPECT_NE(script.find("set xtics ('gmapping (n=2)' 1, 'it' . sprintf('%c', 39) . 's (n=0)' 2)"), std::string::npos)
      << script;
}

}  // namespace
}  // namespace slamsweep::report
