// The sequence page's "Maps compared": which run of each row is drawn, how it is placed, what the page says.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "report/html/standard_artwork.h"
#include "report/html/write_report.h"
#include "tests/report/fake_artwork.h"
#include "tests/report/fixture_sweep.h"
#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

namespace fs = std::filesystem;
using slamsweep::testing::TempDir;
using testing::ReadAll;

class MapsComparedTest : public ::testing::Test {
 protected:
  void SetUp() override { testing::WriteFixtureSweep(dir_ / "sweep", testing::MapsFixtureRuns()); }
  void Write(Artwork* artwork) {
    ReportOptions options;
    options.artwork = artwork;
    WriteReport(dir_ / "sweep", dir_ / "report", options);
  }
  const MapComparisonJob* JobWithPanel(const std::string& run_id) const {
    for (const MapComparisonJob& job : fake_.map_comparisons) {
      for (const MapPanelRequest& panel : job.panels) {
        if (panel.map_file.parent_path().filename() == run_id) return &job;
      }
    }
    return nullptr;
  }
  TempDir dir_;
  testing::FakeArtwork fake_;
};

TEST_F(MapsComparedTest, EachRowsMedianRunPlacedByItsMapScoresTransform) {
  Write(&fake_);
  ASSERT_EQ(fake_.map_comparisons.size(), 2u);  // intel and mit-no-ref
  // ATE 0.05, 0.06, 0.07 and 0.3, 0.4, 0.5: the median runs are the iterations 1.
  const MapComparisonJob* intel = JobWithPanel("gmapping-intel-clean-i1-0000abcd");
  ASSERT_NE(intel, nullptr);
  ASSERT_EQ(intel->panels.size(), 2u);
  EXPECT_EQ(intel->panels[1].map_file.parent_path().filename(), "hector-intel-clean-i1-0000abcd");
  EXPECT_DOUBLE_EQ(intel->panels[1].placement.x_m, 0.2);  // the fixture's transform: 2 x Chamfer
  EXPECT_DOUBLE_EQ(intel->panels[0].placement.x_m, 2 * 0.03);
  EXPECT_EQ(intel->panels[1].match.match_radius_cells, 1);
  EXPECT_EQ(intel->reference_map_file, fs::absolute(dir_ / "sweep/reference_maps/intel.yaml"));
  for (const MapPanelRequest& panel : intel->panels) EXPECT_EQ(panel.reference_map_file, intel->reference_map_file);
  // Without a reference: as recorded, no difference image, no reference panel.
  const MapComparisonJob* no_reference = JobWithPanel("gmapping-mit-no-ref-clean-i1-0000abcd");
  ASSERT_NE(no_reference, nullptr);
  EXPECT_TRUE(no_reference->reference_map_file.empty());
  EXPECT_TRUE(no_reference->panels[0].difference_png.empty());
  EXPECT_DOUBLE_EQ(no_reference->panels[0].placement.x_m, 0.0);
}

TEST_F(MapsComparedTest, ThePageShowsPanelsDifferencesLegendAndScores) {
  Write(&fake_);
  const std::string page = ReadAll(dir_ / "report/sequences/intel-clean.html");
  ASSERT_NE(page.find("<h2 id=\"maps-compared\">Maps compared</h2>"), std::string::npos);
  SCOPED_TRACE(page.substr(page.find("<h2 id=\"maps-compared\">Maps compared</h2>"), 4000));
  for (const char* image : {"intel-clean/map-reference.png", "intel-clean/map-0.png", "intel-clean/map-1.png",
                            "intel-clean/map-difference-0.png", "intel-clean/map-difference-1.png"}) {
    EXPECT_NE(page.find(image), std::string::npos) << image;
    EXPECT_TRUE(fs::is_regular_file(dir_ / "report/sequences" / image)) << image;
  }
  EXPECT_NE(page.find("at 0.05000 m per pixel"), std::string::npos);
  EXPECT_NE(page.find("cells: 1 only in the run, 2 only in the reference, 3 in both"), std::string::npos);
  EXPECT_NE(page.find("class=\"wall-key wall-run-only\""), std::string::npos);
  EXPECT_NE(page.find("within 1 cell of"), std::string::npos);
  // hector's scores from result.json: Chamfer 0.1, F1 1 / 1.1.
  EXPECT_NE(page.find("Chamfer 0.1000 m"), std::string::npos);
  EXPECT_NE(page.find("F1 0.9091"), std::string::npos);
  EXPECT_NE(page.find("placed on the reference by ATE alignment"), std::string::npos);
  const std::string css = ReadAll(dir_ / "report/style.css");
  for (const char* rule : {"img.map-panel", ".wall-run-only", ".wall-reference-only", ".wall-both"}) {
    EXPECT_NE(css.find(rule), std::string::npos) << rule;
  }
  EXPECT_EQ(page.find("style="), std::string::npos);
  const std::string other = ReadAll(dir_ / "report/sequences/mit-no-ref-clean.html");
  EXPECT_NE(other.find("<h2 id=\"maps-compared\">Maps compared</h2>"), std::string::npos);
  EXPECT_NE(other.find("as recorded"), std::string::npos);
  EXPECT_EQ(other.find("Walls against the reference map"), std::string::npos);
}

TEST_F(MapsComparedTest, WithoutAnImageMakerThePageSaysWhy) {
  Write(nullptr);
  const std::string page = ReadAll(dir_ / "report/sequences/intel-clean.html");
  EXPECT_NE(page.find("Maps not drawn (no image maker configured)"), std::string::npos);
}

TEST_F(MapsComparedTest, RealPanelsShareOneSize) {
  const std::unique_ptr<Artwork> artwork = MakeStandardArtwork();
  if (!artwork) {
    if (slamsweep::testing::RunningInCi()) FAIL() << "built without the image libraries (report/images)";
    GTEST_SKIP() << "built without the image libraries";
  }
  Write(artwork.get());
  const fs::path folder = dir_ / "report/sequences/intel-clean";
  const cv::Mat reference = cv::imread((folder / "map-reference.png").string());
  ASSERT_FALSE(reference.empty());
  for (const char* name : {"map-0.png", "map-1.png", "map-difference-0.png", "map-difference-1.png"}) {
    const cv::Mat image = cv::imread((folder / name).string());
    ASSERT_FALSE(image.empty()) << name;
    EXPECT_EQ(image.size(), reference.size()) << name;
  }
  // hector's wall 6 cells in and 0.2 m off: its difference has walls only in the run (blue, #0072B2).
  const cv::Mat hector = cv::imread((folder / "map-difference-1.png").string());
  cv::Mat blue;
  cv::inRange(hector, cv::Scalar(0xB2, 0x72, 0x00), cv::Scalar(0xB2, 0x72, 0x00), blue);
  EXPECT_GT(cv::countNonZero(blue), 0);
  const std::string page = ReadAll(dir_ / "report/sequences/intel-clean.html");
  EXPECT_EQ(page.find("not drawn"), std::string::npos);
}

}  // namespace
}  // namespace slamsweep::report
