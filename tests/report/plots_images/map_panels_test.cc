#include "report/images/map_panels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgcodecs.hpp>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/map_server_format.h"
#include "evaluator/map_compare/map_compare.h"
#include "report/images/map_comparison.h"
#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

using evaluator::OccupancyGrid;

// A free 10 x 10 m square at the origin with one wall column at x in [5, 5 + cell).
OccupancyGrid SquareWithWall(double cell_m) {
  const int n = static_cast<int>(std::lround(10.0 / cell_m));
  OccupancyGrid grid(n, n, cell_m, {0.0, 0.0, 0.0}, 0.0f);
  const int wall = static_cast<int>(std::lround(5.0 / cell_m));
  for (int r = 0; r < n; ++r) grid.at(r, wall) = 1.0f;
  return grid;
}

// A free 10 x 10 grid of 1 m cells with walls in row 2 (y in [7, 8)) at columns [first, last].
OccupancyGrid WallRow(int first, int last) {
  OccupancyGrid grid(10, 10, 1.0, {}, 0.0f);
  for (int c = first; c <= last; ++c) grid.at(2, c) = 1.0f;
  return grid;
}

bool IsColour(const cv::Vec3b& pixel, const unsigned char (&bgr)[3]) {
  return pixel[0] == bgr[0] && pixel[1] == bgr[1] && pixel[2] == bgr[2];
}

TEST(ChoosePanelGeometryTest, OneMetresPerPixelFromTheLongerSideWithAMargin) {
  // 10 x 5 m with 5 % of 10 m on each side: 11 x 6 m; 200 px for 11 m.
  const PanelGeometry panel = ChoosePanelGeometry({0.0, 0.0, 10.0, 5.0}, 200, 0.05);
  EXPECT_DOUBLE_EQ(panel.metres_per_pixel, 0.055);
  EXPECT_EQ(panel.width_px, 200);
  EXPECT_EQ(panel.height_px, 110);  // 6 / 0.055 = 109.09, whole pixels
  EXPECT_DOUBLE_EQ(panel.window.min_x, -0.5);
  EXPECT_NEAR(panel.window.max_y, -0.5 + 110 * 0.055, 1e-12);
  EXPECT_THROW(ChoosePanelGeometry({1.0, 1.0, 1.0, 2.0}, 200), evaluator::InputError);
  EXPECT_THROW(ChoosePanelGeometry({0.0, 0.0, 1.0, 1.0}, 0), evaluator::InputError);
}

TEST(KnownExtentTest, PlacedCornersOfTheKnownCells) {
  OccupancyGrid grid(4, 2, 0.5);  // 2 x 1 m, all unknown
  EXPECT_FALSE(KnownExtent(grid, {}).has_value());
  grid.at(0, 0) = 0.0f;  // top-left cell: x in [0, 0.5), y in [0.5, 1)
  grid.at(1, 3) = 1.0f;  // bottom-right cell: x in [1.5, 2), y in [0, 0.5)
  const WorldWindow plain = *KnownExtent(grid, {});
  EXPECT_DOUBLE_EQ(plain.min_x, 0.0);
  EXPECT_DOUBLE_EQ(plain.max_x, 2.0);
  EXPECT_DOUBLE_EQ(plain.max_y, 1.0);
  // A quarter turn and a shift: x' = 10 - y, y' = x.
  const WorldWindow turned = *KnownExtent(grid, {10.0, 0.0, M_PI / 2, 1.0});
  EXPECT_NEAR(turned.min_x, 9.0, 1e-12);
  EXPECT_NEAR(turned.max_x, 10.0, 1e-12);
  EXPECT_NEAR(turned.min_y, 0.0, 1e-12);
  EXPECT_NEAR(turned.max_y, 2.0, 1e-12);
}

TEST(RenderMapPanelTest, MapsOfDifferentCellSizesShareOnePixelPerMetre) {
  const PanelGeometry panel = ChoosePanelGeometry({0.0, 0.0, 10.0, 10.0}, 100, 0.0);
  ASSERT_DOUBLE_EQ(panel.metres_per_pixel, 0.1);
  const cv::Mat fine = RenderMapPanel(SquareWithWall(0.05), {}, panel);
  const cv::Mat coarse = RenderMapPanel(SquareWithWall(0.1), {}, panel);
  ASSERT_EQ(fine.size(), cv::Size(100, 100));
  ASSERT_EQ(coarse.size(), fine.size());
  // The wall (x = 5 m) is pixel column 50 in both; free space is white on either side.
  for (const cv::Mat* image : {&fine, &coarse}) {
    EXPECT_EQ(image->at<unsigned char>(30, 50), 0);
    EXPECT_EQ(image->at<unsigned char>(30, 45), 255);
    EXPECT_EQ(image->at<unsigned char>(30, 55), 255);
  }
}

TEST(RenderMapPanelTest, AOneCellWallSurvivesACoarsePanel) {
  // 0.25 m per pixel over 0.05 m cells: the wall is a fifth of a pixel wide but stays black.
  const PanelGeometry panel = ChoosePanelGeometry({0.0, 0.0, 10.0, 10.0}, 40, 0.0);
  const cv::Mat image = RenderMapPanel(SquareWithWall(0.05), {}, panel);
  ASSERT_EQ(image.size(), cv::Size(40, 40));
  EXPECT_EQ(image.at<unsigned char>(10, 20), 0);  // x in [5, 5.25)
  EXPECT_EQ(image.at<unsigned char>(10, 10), 255);
}

TEST(RenderMapPanelTest, PlacementMovesTheMapIntoTheCommonFrame) {
  // The wall x = 5 m turned a quarter (x' = -y, y' = x) and shifted by (10, 0): the row y' = 5 m.
  const PanelGeometry panel = ChoosePanelGeometry({0.0, 0.0, 10.0, 10.0}, 100, 0.0);
  const cv::Mat image = RenderMapPanel(SquareWithWall(0.1), {10.0, 0.0, M_PI / 2, 1.0}, panel);
  EXPECT_EQ(image.at<unsigned char>(49, 30), 0);  // y' in [5, 5.1): row 100 - 51 = 49
  EXPECT_EQ(image.at<unsigned char>(45, 30), 255);
}

TEST(CompareWallsTest, CountsOnAHandMadePairExactMatch) {
  // Reference walls at columns 2..6, run walls at 4..8: both 4..6, run only 7..8, reference only 2..3.
  const WallDifference difference = CompareWalls(WallRow(4, 8), {}, WallRow(2, 6), {.match_radius_cells = 0});
  EXPECT_EQ(difference.counts.both, 3u);
  EXPECT_EQ(difference.counts.run_only, 2u);
  EXPECT_EQ(difference.counts.reference_only, 2u);
  ASSERT_EQ(difference.classes.size(), cv::Size(10, 10));
  EXPECT_EQ(difference.classes.at<unsigned char>(2, 2), kWallReferenceOnly);
  EXPECT_EQ(difference.classes.at<unsigned char>(2, 5), kWallBoth);
  EXPECT_EQ(difference.classes.at<unsigned char>(2, 8), kWallRunOnly);
  EXPECT_EQ(difference.classes.at<unsigned char>(5, 5), kWallFree);
}

TEST(CompareWallsTest, WithinTheMatchRadiusCountsAsBothAndAgreesWithTheScores) {
  // Radius 1: run column 7 is next to reference column 6, reference column 3 next to run column 4.
  const WallDifference difference = CompareWalls(WallRow(4, 8), {}, WallRow(2, 6), {.match_radius_cells = 1});
  EXPECT_EQ(difference.counts.both, 5u);  // columns 3..7
  EXPECT_EQ(difference.counts.run_only, 1u);
  EXPECT_EQ(difference.counts.reference_only, 1u);
  // The evaluator's scores on the same pair: 4 of 5 run walls and 4 of 5 reference walls matched.
  evaluator::MapCompareOptions options;
  options.match_radius_cells = 1;
  const evaluator::MapComparison scores = evaluator::CompareMaps(WallRow(4, 8), WallRow(2, 6), options);
  EXPECT_NEAR(scores.accuracy, 4.0 / 5.0, 1e-12);
  EXPECT_NEAR(scores.completeness, 4.0 / 5.0, 1e-12);
}

TEST(CompareWallsTest, TheRunIsPlacedAndBroughtToTheReferenceCellSize) {
  // The run of 0.5 m cells, its origin 1 m to the right, placed back by x_m = -1: walls at 1 m columns
  // 4..8 of the reference lattice, as in the exact-match case.
  OccupancyGrid run(20, 20, 0.5, {1.0, 0.0, 0.0}, 0.0f);
  for (int c = 8; c <= 17; ++c) run.at(4, c) = 1.0f;  // x in [1 + 4, 1 + 9), y in [7.5, 8)
  const WallDifference difference = CompareWalls(run, {-1.0, 0.0, 0.0, 1.0}, WallRow(2, 6), {.match_radius_cells = 0});
  EXPECT_EQ(difference.counts.both, 3u);
  EXPECT_EQ(difference.counts.run_only, 2u);
  EXPECT_EQ(difference.counts.reference_only, 2u);
}

TEST(KnownPartTest, CropsToTheKnownCellsOnTheLatticeTheScoresUsed) {
  // 1 x 1 m of 0.05 m cells, known only in columns 6..9 (x in [0.3, 0.5)), a wall in column 7 (x in
  // [0.35, 0.4)). With one cell to spare the crop would start at column 5; kept on the 0.1 m lattice of the
  // uncropped map it starts at column 4, so the wall still merges into the 0.1 m cell x in [0.3, 0.4).
  OccupancyGrid run(20, 20, 0.05);
  for (int r = 0; r < 20; ++r) {
    for (int c = 6; c <= 9; ++c) run.at(r, c) = c == 7 ? 1.0f : 0.0f;
  }
  const OccupancyGrid cropped = KnownPart(run, 0.1);
  EXPECT_EQ(cropped.width, 7);  // columns 4..10: one to spare on the right
  EXPECT_EQ(cropped.height, 20);
  EXPECT_NEAR(cropped.origin.x_m, 0.2, 1e-12);
  OccupancyGrid reference(10, 10, 0.1, {}, 0.0f);
  for (int r = 0; r < 10; ++r) reference.at(r, 3) = 1.0f;
  const WallDifference whole = CompareWalls(run, {}, reference, {.match_radius_cells = 0});
  const WallDifference part = CompareWalls(cropped, {}, reference, {.match_radius_cells = 0});
  EXPECT_EQ(whole.counts.both, 10u);
  EXPECT_EQ(part.counts.both, 10u);
  EXPECT_EQ(part.counts.run_only, 0u);
  EXPECT_EQ(part.counts.reference_only, 0u);
  // Cells of 0.03 m cannot be kept on 0.1 m cells: the grid stays whole.
  OccupancyGrid odd(20, 20, 0.03);
  odd.at(5, 5) = 1.0f;
  EXPECT_EQ(KnownPart(odd, 0.1).width, 20);
  EXPECT_EQ(KnownPart(odd, 0.03).width, 3);
}

TEST(RenderDifferencePanelTest, ThreeColoursAndLoneWallsKeptOnCoarsePixels) {
  const WallDifference difference = CompareWalls(WallRow(4, 8), {}, WallRow(2, 6), {.match_radius_cells = 0});
  const cv::Mat one = RenderDifferencePanel(difference, ChoosePanelGeometry({0.0, 0.0, 10.0, 10.0}, 10, 0.0));
  ASSERT_EQ(one.size(), cv::Size(10, 10));
  EXPECT_TRUE(IsColour(one.at<cv::Vec3b>(2, 2), kReferenceOnlyBgr));
  EXPECT_TRUE(IsColour(one.at<cv::Vec3b>(2, 5), kBothBgr));
  EXPECT_TRUE(IsColour(one.at<cv::Vec3b>(2, 8), kRunOnlyBgr));
  EXPECT_EQ(one.at<cv::Vec3b>(5, 5), cv::Vec3b(255, 255, 255));
  // 2 m pixels: the pixel of columns 2..3 and rows 2..3 holds a reference-only wall and free cells.
  const cv::Mat coarse = RenderDifferencePanel(difference, ChoosePanelGeometry({0.0, 0.0, 10.0, 10.0}, 5, 0.0));
  ASSERT_EQ(coarse.size(), cv::Size(5, 5));
  EXPECT_TRUE(IsColour(coarse.at<cv::Vec3b>(1, 1), kReferenceOnlyBgr));
  EXPECT_TRUE(IsColour(coarse.at<cv::Vec3b>(1, 4), kRunOnlyBgr));
}

TEST(WriteMapComparisonTest, PanelsOfMapsWithDifferentCellSizesHaveEqualMetresPerPixel) {
  testing::TempDir dir;
  evaluator::WriteMapServer(SquareWithWall(0.05), dir / "fine.yaml");
  evaluator::WriteMapServer(SquareWithWall(0.1), dir / "coarse.yaml");
  evaluator::WriteMapServer(SquareWithWall(0.1), dir / "reference.yaml");
  MapComparisonJob job;
  job.max_side_px = 200;
  job.reference_map_file = dir / "reference.yaml";
  job.reference_png = dir / "reference.png";
  for (const char* name : {"fine", "coarse"}) {
    MapPanelRequest panel;
    panel.map_file = dir / (std::string(name) + ".yaml");
    panel.png = dir / (std::string(name) + ".png");
    panel.reference_map_file = dir / "reference.yaml";
    panel.difference_png = dir / (std::string(name) + "-difference.png");
    job.panels.push_back(panel);
  }
  MapPanelRequest missing;
  missing.map_file = dir / "missing.yaml";
  missing.png = dir / "missing.png";
  job.panels.push_back(missing);
  const MapComparisonDrawn drawn = WriteMapComparison(job);
  // The reference's known 10 m with 3 % margins on 200 px.
  EXPECT_DOUBLE_EQ(drawn.metres_per_pixel, 10.6 / 200);
  EXPECT_TRUE(drawn.reference_made);
  ASSERT_EQ(drawn.panels.size(), 3u);
  EXPECT_FALSE(drawn.panels[2].made);
  EXPECT_NE(drawn.panels[2].note.find("missing.yaml"), std::string::npos) << drawn.panels[2].note;
  const cv::Mat fine = cv::imread((dir / "fine.png").string());
  const cv::Mat coarse = cv::imread((dir / "coarse.png").string());
  ASSERT_FALSE(fine.empty());
  EXPECT_EQ(fine.size(), cv::Size(200, 200));
  EXPECT_EQ(coarse.size(), fine.size());
  // The wall at x = 5 m: pixel (5 + 0.3) / 0.053 = 100 in both.
  EXPECT_EQ(fine.at<cv::Vec3b>(50, 100), cv::Vec3b(0, 0, 0));
  EXPECT_EQ(coarse.at<cv::Vec3b>(50, 100), cv::Vec3b(0, 0, 0));
  for (int i = 0; i < 2; ++i) {
    ASSERT_TRUE(drawn.panels[i].difference_made) << drawn.panels[i].difference_note;
    ASSERT_TRUE(drawn.panels[i].counts.has_value());
    EXPECT_EQ(drawn.panels[i].counts->run_only, 0u);
    EXPECT_EQ(drawn.panels[i].counts->reference_only, 0u);
    EXPECT_EQ(drawn.panels[i].counts->both, 100u);  // one wall column of 100 cells of 0.1 m
  }
}

}  // namespace
}  // namespace slamsweep::report
