// WriteReport's segment-length and parameter pages, with a stand-in for the image maker: which pages
// and figures exist, what the figures hold (styles, order, best marks), and that the pages link up.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <variant>

#include "report/html/view_pages.h"
#include "report/html/write_report.h"
#include "report/plots/algorithm_palette.h"
#include "tests/report/fake_artwork.h"
#include "tests/report/fixture_sweep.h"
#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

namespace fs = std::filesystem;
using slamsweep::testing::TempDir;
using ::testing::HasSubstr;
using ::testing::Not;
using testing::ReadAll;

/// An artwork whose figures fail, to see the pages say so.
class FailingFigures : public testing::FakeArtwork {
 public:
  void Figures(const std::vector<FigureJob>&) override { throw std::runtime_error("gnuplot exploded"); }
};

class ViewPagesTest : public ::testing::Test {
 protected:
  void SetUp() override { testing::WriteFixtureSweep(dir_ / "sweep", testing::ViewsFixtureRuns()); }

  ReportSummary Write(Artwork* artwork) {
    ReportOptions options;
    options.artwork = artwork;
    options.jobs = 2;
    return WriteReport(dir_ / "sweep", dir_ / "report", options);
  }

  const FigureJob& FigureAt(const std::string& png_name) const {
    for (const FigureJob& job : fake_.figures) {
      if (job.png.filename() == png_name) return job;
    }
    throw std::runtime_error("no figure " + png_name);
  }

  TempDir dir_;
  testing::FakeArtwork fake_;
};

TEST_F(ViewPagesTest, EveryTableWithSegmentsOrParameterSweepsGetsItsPagesLinkedFromIndexAndSequence) {
  const ReportSummary summary = Write(&fake_);
  const fs::path report = dir_ / "report";
  EXPECT_TRUE(fs::exists(report / "sequences/intel-clean/segments.html"));
  EXPECT_TRUE(fs::exists(report / "sequences/intel-clean/parameters.html"));
  // Its folder holds the maps compared, but no extra page.
  EXPECT_FALSE(fs::exists(report / "sequences/mit-no-ref-clean/segments.html"))
      << "no reference, one row: no extra page";
  EXPECT_FALSE(fs::exists(report / "sequences/mit-no-ref-clean/parameters.html"))
      << "no reference, one row: no extra page";
  for (const char* page : {"index.html", "sequences/intel-clean.html"}) {
    const std::string html = ReadAll(report / page);
    EXPECT_THAT(html, HasSubstr("intel-clean/segments.html")) << page;
    EXPECT_THAT(html, HasSubstr("intel-clean/parameters.html")) << page;
  }
  EXPECT_THAT(ReadAll(report / "sequences/mit-no-ref-clean.html"), Not(HasSubstr("segments.html")));
  std::size_t checked = 0;
  EXPECT_TRUE(testing::BrokenLinks(report, &checked).empty()) << ::testing::PrintToString(testing::BrokenLinks(report));
  EXPECT_GT(checked, 0u);
  // 3 segment figures; per swept algorithm one figure per metric column (ATE + 3 map metrics). The same batch
  // draws the sequence page's trajectory figures: all rows together, and one error-along-the-path figure per
  // row with a median run on intel (10 rows; mit-no-ref has no reference), and one per other run on intel for its
  // own page (12).
  const auto paths = std::count_if(fake_.figures.begin(), fake_.figures.end(),
                                   [](const FigureJob& job) { return std::holds_alternative<PathFigure>(job.figure); });
  EXPECT_EQ(fake_.figures.size() - static_cast<std::size_t>(paths), 3u + 4u + 4u);
  EXPECT_EQ(paths, 1 + 10 + 12);
  EXPECT_EQ(summary.images_missing, 0u);
  // The pages show every figure they planned.
  const std::vector<std::string> images = testing::ImageSources(report / "sequences/intel-clean/parameters.html");
  EXPECT_EQ(images.size(), 8u);
  for (const std::string& src : images) EXPECT_TRUE(fs::exists(report / "sequences/intel-clean" / src)) << src;
  EXPECT_EQ(testing::ImageSources(report / "sequences/intel-clean/segments.html").size(), 3u);
}

TEST_F(ViewPagesTest, TheIndexLinksEveryExtraPageAndTheSpecificationDefinesTheSegmentMetrics) {
  Write(&fake_);
  const fs::path report = dir_ / "report";
  const std::string index = ReadAll(report / "index.html");
  for (const char* link :
       {"href=\"metrics.html\"", "href=\"validity.html\"", "href=\"sequences/intel-clean/segments.html\"",
        "href=\"sequences/intel-clean/parameters.html\""}) {
    EXPECT_THAT(index, HasSubstr(link));
  }
  for (const char* page : {"sequences/intel-clean/segments.html", "sequences/intel-clean/parameters.html"}) {
    EXPECT_THAT(ReadAll(report / page), HasSubstr("<a href=\"../../metrics.html\">metric specification</a>")) << page;
  }
  // The segment columns (segment_drift_10m, ...) are defined under their name pattern.
  const std::string spec = ReadAll(report / "metrics.html");
  for (const char* metric : {"segment_trans", "segment_drift", "segment_rot"}) {
    EXPECT_THAT(spec, HasSubstr("<code>" + std::string(metric) + "_&lt;L&gt;m</code>")) << metric;
  }
}

TEST_F(ViewPagesTest, EachAlgorithmKeepsItsColourAndMarkerInEveryPlotAndLegendsFollowTheTable) {
  Write(&fake_);
  const AlgorithmPalette palette({"gmapping", "hector", "icp-slam", "rbpf-slam", "<b>odd & name</b>"});
  // The metric plots of the tables.
  ASSERT_FALSE(fake_.plots.empty());
  std::vector<std::string> plot_order;
  for (const PlotSeriesValues& series : fake_.plots[0].series) {
    const std::string name = series.algorithm.substr(0, series.algorithm.find(" ["));
    EXPECT_EQ(series.style.rgb, palette.StyleOf(name).rgb) << series.algorithm;
    EXPECT_EQ(series.style.point_type, palette.StyleOf(name).point_type) << series.algorithm;
    plot_order.push_back(series.algorithm);
  }
  // The segment boxplot: the same styles, the same order, and a variant per further row of an algorithm.
  const auto& boxes = std::get<BoxplotFigure>(FigureAt("segments-translation.png").figure);
  ASSERT_EQ(boxes.series.size(), plot_order.size());
  for (std::size_t s = 0; s < boxes.series.size(); ++s) {
    EXPECT_EQ(boxes.series[s].label, plot_order[s]);
    const std::string name = boxes.series[s].label.substr(0, boxes.series[s].label.find(" ["));
    EXPECT_EQ(boxes.series[s].style.rgb, palette.StyleOf(name).rgb);
  }
  std::vector<int> icp_variants;
  for (const BoxSeries& series : boxes.series) {
    if (series.label.starts_with("icp-slam")) icp_variants.push_back(series.style.variant);
  }
  EXPECT_EQ(icp_variants, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(boxes.categories, (std::vector<std::string>{"10 m", "20 m", "30 m"}));
  const auto gmapping = std::find_if(boxes.series.begin(), boxes.series.end(),
                                     [](const BoxSeries& series) { return series.label == "gmapping"; });
  ASSERT_NE(gmapping, boxes.series.end());
  ASSERT_TRUE(gmapping->boxes[0]);
  EXPECT_EQ(gmapping->boxes[0]->n, 60u);  // 20 segments x 3 runs
  const auto& drift = std::get<LineFigure>(FigureAt("segments-drift.png").figure);
  EXPECT_EQ(drift.series[0].points.size(), 3u);
  EXPECT_EQ(drift.series[0].points[0].x, 10.0);
}

TEST_F(ViewPagesTest, TheParameterPageDrawsCurvesAndHeatmapsAndNamesTheBestValue) {
  Write(&fake_);
  // icp-slam: ATE against ICP.maxIterations, 40 ringed.
  const auto& curve = std::get<LineFigure>(FigureAt("parameters-0-0-0.png").figure);
  EXPECT_EQ(curve.x_label, "ICP.maxIterations");
  ASSERT_EQ(curve.series.size(), 1u);
  ASSERT_EQ(curve.series[0].points.size(), 3u);
  EXPECT_EQ(curve.series[0].points[1].x, 40.0);
  EXPECT_NEAR(curve.series[0].points[1].y, 0.125, 1e-12);
  ASSERT_TRUE(curve.series[0].points[1].spread);
  ASSERT_TRUE(curve.highlight);
  EXPECT_EQ(curve.highlight->point, 1u);
  EXPECT_TRUE(curve.x_tics.empty()) << "numeric values: a numeric axis";
  // rbpf-slam: particles x resample heatmap of ATE, the best cell framed.
  const auto& heatmap = std::get<HeatmapFigure>(FigureAt("parameters-1-0-0.png").figure);
  EXPECT_EQ(heatmap.x_values, (std::vector<std::string>{"10", "30"}));
  EXPECT_EQ(heatmap.y_values, (std::vector<std::string>{"0.5", "1.0"}));
  ASSERT_EQ(heatmap.cells.size(), 2u);
  EXPECT_TRUE(heatmap.cells[0][1].best);
  EXPECT_FALSE(heatmap.cells[1][0].best);
  EXPECT_THAT(heatmap.cells[0][1].text, HasSubstr("±"));

  const std::string page = ReadAll(dir_ / "report/sequences/intel-clean/parameters.html");
  EXPECT_THAT(page, HasSubstr("<th>Best ICP.maxIterations</th>"));
  EXPECT_THAT(page, HasSubstr("<td class=\"best\">40</td>"));  // ATE: 40 iterations
  EXPECT_THAT(page, HasSubstr("particles=30, resample=0.5"));
  EXPECT_THAT(page, HasSubstr("The same in every row: ICP.thresholdDist=0.75"));
  EXPECT_THAT(page, HasSubstr("swatch palette-c"));
}

TEST_F(ViewPagesTest, TheSegmentPageTablesDriftPerLengthAndEscapesNames) {
  Write(&fake_);
  const std::string page = ReadAll(dir_ / "report/sequences/intel-clean/segments.html");
  EXPECT_THAT(page, HasSubstr("10, 20, 30, 40 and 50 % of the reference path (100.0 m)"));
  EXPECT_THAT(page, HasSubstr("--pairs_from_reference"));
  EXPECT_THAT(page, HasSubstr("1.700 ± 0.050 %"));  // gmapping at 10 m: 1.65, 1.70, 1.75
  EXPECT_THAT(page, HasSubstr("▼ best"));
  EXPECT_THAT(page, HasSubstr("&lt;b&gt;odd &amp; name&lt;/b&gt;"));
  EXPECT_THAT(page, Not(HasSubstr("<b>odd")));
  EXPECT_THAT(page, Not(HasSubstr("style=")));
  // The run pages offer every segment for download.
  EXPECT_TRUE(fs::exists(dir_ / "report/runs/gmapping-intel-clean-i0-0000abcd/rpe_segments.csv"));
}

TEST_F(ViewPagesTest, FiguresThatCannotBeDrawnAreNamedOnThePage) {
  FailingFigures failing;
  const ReportSummary summary = Write(&failing);
  // The view figures, the trajectory figures and the path-error figures of the 12 runs on intel that are not
  // their row's median run (2 + 2 + 1 of gmapping, hector and the odd name, 1 per icp-slam and rbpf-slam row).
  EXPECT_EQ(summary.images_missing, 11u + (1u + 10u) + 12u);
  const std::string page = ReadAll(dir_ / "report/sequences/intel-clean/segments.html");
  EXPECT_THAT(page, HasSubstr("Figure not available: gnuplot exploded"));
  EXPECT_TRUE(testing::BrokenLinks(dir_ / "report").empty());
}

TEST_F(ViewPagesTest, WithoutImagesThePagesStillExist) {
  const ReportSummary summary = Write(nullptr);
  EXPECT_EQ(summary.images_missing, 0u);
  EXPECT_TRUE(fs::exists(dir_ / "report/sequences/intel-clean/parameters.html"));
  EXPECT_TRUE(testing::ImageSources(dir_ / "report/sequences/intel-clean/parameters.html").empty());
  EXPECT_TRUE(testing::BrokenLinks(dir_ / "report").empty());
}

TEST_F(ViewPagesTest, TheStyleSheetCarriesThePalette) {
  Write(&fake_);
  const std::string css = ReadAll(dir_ / "report/style.css");
  EXPECT_THAT(css, HasSubstr(PaletteStyleSheet()));
  EXPECT_THAT(css, HasSubstr(".swatch"));
}

}  // namespace
}  // namespace slamsweep::report
