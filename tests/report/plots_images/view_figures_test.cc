// The figures of the segment-length and parameter pages: their gnuplot scripts, and real PNGs drawn by
// gnuplot whose pixels show what was asked (each series in its colour, the best cell framed, grey where
// nothing ran). A copy of each PNG is kept beside the test binary for a person to look at.
#include "report/plots/view_figures.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "report/plots/view_figure_scripts.h"
#include "tests/report/plots_images/plot_pixels.h"
#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

using slamsweep::testing::CountColour;
using slamsweep::testing::ReadAndKeep;

BoxStats Box(double centre, std::size_t outliers = 0) {
  BoxStats box;
  box.n = 60;
  box.whisker_low = centre * 0.4;
  box.q1 = centre * 0.8;
  box.median = centre;
  box.q3 = centre * 1.2;
  box.whisker_high = centre * 1.7;
  box.mean = centre * 1.05;
  box.outliers = outliers;
  return box;
}

BoxplotFigure ThreeRowsBoxplot() {
  BoxplotFigure figure;
  figure.title = "intel: translation error per segment length";
  figure.x_label = "segment length";
  figure.y_label = "translation error (m)";
  figure.categories = {"12 m", "25 m", "37 m", "49 m", "62 m"};
  const std::pair<const char*, SeriesStyle> rows[] = {
      {"gmapping", {0x0072B2, 7, 0}}, {"hector", {0x009E73, 9, 0}}, {"hector [x=2]", {0x009E73, 9, 1}}};
  for (const auto& [label, style] : rows) {
    BoxSeries series{label, style, {}};
    for (int k = 0; k < 5; ++k)
      series.boxes.push_back(Box(0.2 * (k + 1) * (style.rgb == 0x0072B2 ? 1.0 : 2.0), k == 4 ? 3 : 0));
    figure.series.push_back(series);
  }
  figure.series[2].boxes[1].reset();  // a length without segments
  return figure;
}

TEST(ViewFigureScriptsTest, BoxesFollowTheSeriesOrderInTheirColoursAndCountOutliers) {
  const std::string script = BoxplotScript(ThreeRowsBoxplot(), "/tmp/x.png", 4);
  const std::size_t gmapping = script.find("title 'gmapping'");
  const std::size_t hector = script.find("title 'hector'");
  ASSERT_NE(gmapping, std::string::npos);
  ASSERT_NE(hector, std::string::npos);
  EXPECT_LT(gmapping, hector) << "the key lists the series in table order";
  EXPECT_THAT(script, HasSubstr("'#0072B2'"));
  EXPECT_THAT(script, HasSubstr("'#009E73'"));
  EXPECT_THAT(script, HasSubstr("fill transparent pattern 4"));  // the second hector row is hatched
  EXPECT_THAT(script, HasSubstr("(9 beyond the whiskers, not drawn)"));
  EXPECT_THAT(script, HasSubstr("print 'SLAMSWEEP_PLOT 4'"));
}

TEST(ViewFigureScriptsTest, HeatmapColoursRunFromLightToDarkAndTextStaysReadable) {
  EXPECT_EQ(HeatmapColour(0.0), 0xFDE725u);
  EXPECT_EQ(HeatmapColour(0.5), 0x21918Cu);
  EXPECT_EQ(HeatmapColour(1.0), 0x440154u);
  EXPECT_EQ(HeatmapColour(7.0), 0x440154u);
  EXPECT_FALSE(HeatmapTextIsWhite(0.0));
  EXPECT_TRUE(HeatmapTextIsWhite(1.0));
}

TEST(ViewFigureScriptsTest, EmptyFiguresStillMakeAValidScript) {
  for (const ViewFigure& figure :
       {ViewFigure(BoxplotFigure{}), ViewFigure(LineFigure{}), ViewFigure(HeatmapFigure{})}) {
    const std::string script = FigureScript({figure, "/tmp/e.png"}, 0);
    EXPECT_THAT(script, HasSubstr("plot $empty_0"));
    EXPECT_THAT(script, HasSubstr("unset output"));
  }
}

TEST(ViewFiguresTest, DrawsBoxplotsInTheSeriesColours) {
  REQUIRE_GNUPLOT();
  slamsweep::testing::TempDir dir;
  const FigureJob job{ThreeRowsBoxplot(), dir / "view_boxplot.png"};
  WriteViewFigures({job});
  const cv::Mat image = ReadAndKeep(job.png);
  EXPECT_GT(CountColour(image, 0x0072B2), 50);
  EXPECT_GT(CountColour(image, 0x009E73), 50);
}

TEST(ViewFiguresTest, DrawsLinesWithWhiskersAndRingsTheBest) {
  REQUIRE_GNUPLOT();
  slamsweep::testing::TempDir dir;
  LineFigure figure;
  figure.title = "icp-slam on intel: ATE translation RMSE against ICP.maxIterations";
  figure.x_label = "ICP.maxIterations";
  figure.y_label = "ATE translation RMSE (m), mean ± std";
  figure.log_x = true;
  figure.series.push_back(
      {"icp-slam", {0xCC79A7, 13, 0}, {{5, 0.4, 0.05, 3}, {20, 0.2, 0.02, 3}, {80, 0.25, std::nullopt, 1}}});
  figure.highlight = LineFigure::Highlight{0, 1, "lowest mean: ICP.maxIterations=20"};
  LineFigure categorical = figure;
  categorical.log_x = false;
  categorical.x_tics = {"point", "grid", "both"};
  categorical.series[0].points = {{0, 1.0, 0.1, 2}, {1, 0.5, 0.2, 2}, {2, 0.7, 0.1, 2}};
  const FigureJob numeric_job{figure, dir / "view_lines.png"};
  const FigureJob categorical_job{categorical, dir / "view_lines_categorical.png"};
  WriteViewFigures({numeric_job, categorical_job});
  for (const FigureJob* job : {&numeric_job, &categorical_job}) {
    const cv::Mat image = ReadAndKeep(job->png);
    EXPECT_GT(CountColour(image, 0xCC79A7), 30) << job->png;
  }
}

TEST(ViewFiguresTest, DrawsAnAnnotatedHeatmapWithTheBestFramedAndMissingCellsGrey) {
  REQUIRE_GNUPLOT();
  slamsweep::testing::TempDir dir;
  HeatmapFigure figure;
  figure.title = "rbpf-slam on intel: ATE translation RMSE (resample=0.5)";
  figure.x_label = "particles";
  figure.y_label = "LOG_FREQUENCY";
  figure.value_label = "ATE translation RMSE (m), mean";
  figure.x_values = {"10", "30", "60"};
  figure.y_values = {"5", "10"};
  figure.cells = {{{0.30, "0.3000 ± 0.010", false}, {0.12, "0.1200 ± 0.004", true}, {std::nullopt, "", false}},
                  {{0.50, "0.5000 ± 0.020", false}, {0.20, "0.2000 ± 0.010", false}, {0.90, "0.9000 ± 0.100", false}}};
  const FigureJob job{figure, dir / "view_heatmap.png"};
  WriteViewFigures({job});
  const cv::Mat image = ReadAndKeep(job.png);
  EXPECT_GT(CountColour(image, 0xD55E00), 50) << "the best cell's frame";
  EXPECT_GT(CountColour(image, 0xE0E0E0), 200) << "the cell without a run";
  EXPECT_GT(CountColour(image, 0x440154), 200) << "the highest value, darkest";
  EXPECT_GT(CountColour(image, 0xFFFFFF), 0);
}

TEST(ViewFiguresTest, HostileLabelsDoNotRunCommands) {
  REQUIRE_GNUPLOT();
  slamsweep::testing::TempDir dir;
  const fs::path marker = dir / "ran";
  BoxplotFigure boxes = ThreeRowsBoxplot();
  boxes.title = "it's `touch " + marker.string() + "` @x\n";
  boxes.series[0].label = "'; system('touch " + marker.string() + "'); '";
  boxes.categories[0] = "a\"b";
  HeatmapFigure heatmap;
  heatmap.title = "t";
  heatmap.x_values = {"`touch " + marker.string() + "`"};
  heatmap.y_values = {"y"};
  heatmap.cells = {{{1.0, "'; system('touch " + marker.string() + "'); '", true}}};
  WriteViewFigures({{boxes, dir / "a.png"}, {heatmap, dir / "b.png"}});
  EXPECT_TRUE(fs::exists(dir / "a.png"));
  EXPECT_TRUE(fs::exists(dir / "b.png"));
  EXPECT_FALSE(fs::exists(marker));
}

}  // namespace
}  // namespace slamsweep::report
