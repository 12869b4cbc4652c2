#include "evaluator/map_metrics/enclosed_areas.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "evaluator/core/input_error.h"
#include "tests/evaluator/map_metrics/map_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using testing::GridFromText;

// Sealed rooms: free interiors inside 1-cell occupied walls, unknown around them.
OccupancyGrid SealedRooms(int rows, int cols, const std::vector<cv::Rect>& interiors) {
  OccupancyGrid grid(cols, rows, 0.05);
  for (const cv::Rect& interior : interiors) {
    for (int r = interior.y - 1; r <= interior.y + interior.height; ++r) {
      for (int c = interior.x - 1; c <= interior.x + interior.width; ++c) {
        grid.at(r, c) = interior.contains(cv::Point(c, r)) ? 0.0f : 1.0f;
      }
    }
  }
  return grid;
}

TEST(EnclosedAreasTest, EverySealedRoomCounts) {
  const std::vector<cv::Rect> rooms = {{2, 2, 2, 2},  {8, 2, 10, 3},  {22, 3, 5, 12}, {2, 10, 6, 6},
                                       {11, 9, 4, 9}, {30, 20, 8, 2}, {3, 22, 20, 4}};
  const EnclosedAreas r = ComputeEnclosedAreas(SealedRooms(30, 42, rooms));
  EXPECT_EQ(r.enclosed_areas, 7);
  // At u = 0 unknown is as dark as the walls, so the rooms are there from the first step.
  EXPECT_EQ(r.at_unknown_value, 0);
  ASSERT_EQ(r.sweep.size(), 51u);  // u = 0, 5, ..., 250
  EXPECT_EQ(r.sweep.back().unknown_value, 250);
}

TEST(EnclosedAreasTest, RoomOfThreeCellsIsNotCounted) {
  const OccupancyGrid grid = GridFromText({
      "????????????",
      "?#####?####?",
      "?#...#?#..#?",
      "?#####?#..#?",
      "???????####?",
      "????????????",
  });
  // 3 cells on the left, 4 cells on the right.
  EXPECT_EQ(ComputeEnclosedAreas(grid).enclosed_areas, 1);
  EnclosedAreasOptions three;
  three.min_area_cells = 3;
  EXPECT_EQ(ComputeEnclosedAreas(grid, three).enclosed_areas, 2);
}

TEST(EnclosedAreasTest, RegionTouchingTheBorderIsNotCounted) {
  const OccupancyGrid grid = GridFromText({
      "######???",
      ".....#???",
      "......???",
      ".....#???",
      "######???",
  });
  EXPECT_EQ(ComputeEnclosedAreas(grid).enclosed_areas, 0);
}

TEST(EnclosedAreasTest, RoomsMeetingAtACornerAreOneRegion) {
  // The two interiors touch diagonally through the wall corner: 8-connected, one region.
  const OccupancyGrid grid = GridFromText({
      "????????",
      "?####???",
      "?#..#???",
      "?#...###",
      "?###...#",
      "???#...#",
      "???#####",
      "????????",
  });
  EXPECT_EQ(ComputeEnclosedAreas(grid).enclosed_areas, 1);
}

TEST(EnclosedAreasTest, UnknownValueThatFreesUnknownSpaceIsFound) {
  // A room whose interior is unknown, seen only as its walls, on free ground: it is enclosed
  // only when the unknown cells count as free and the outside as well, i.e. for u above the
  // threshold. The surrounding free region touches the border and is not counted.
  const OccupancyGrid grid = GridFromText({
      "..........",
      ".#####....",
      ".#???#....",
      ".#???#....",
      ".#####....",
      "..........",
  });
  const EnclosedAreas r = ComputeEnclosedAreas(grid);
  EXPECT_EQ(r.enclosed_areas, 1);
  EXPECT_GT(r.at_unknown_value, r.otsu_threshold);
  EXPECT_EQ(r.sweep.front().enclosed_areas, 0);
}

TEST(EnclosedAreasTest, BadInputIsAnInputError) {
  EXPECT_THROW(ComputeEnclosedAreas(OccupancyGrid(5, 5, 0.05)), InputError);
  const OccupancyGrid grid = GridFromText({"#.", ".#"});
  const auto message_for = [&](EnclosedAreasOptions options) {
    try {
      ComputeEnclosedAreas(grid, options);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EnclosedAreasOptions step;
  step.unknown_value_step = 0;
  EXPECT_NE(message_for(step).find("enclosed.unknown_value_step = 0"), std::string::npos);
  EnclosedAreasOptions first;
  first.first_unknown_value = 300;
  EXPECT_NE(message_for(first).find("enclosed.first_unknown_value"), std::string::npos);
  EnclosedAreasOptions empty_sweep;
  empty_sweep.unknown_value_limit = 0;
  EXPECT_NE(message_for(empty_sweep).find("enclosed.unknown_value_limit"), std::string::npos);
  EnclosedAreasOptions area;
  area.min_area_cells = 0;
  EXPECT_NE(message_for(area).find("enclosed.min_area_cells"), std::string::npos);
}

TEST(EnclosedAreasTest, MatchesReferenceMaps) {
  SLAMSWEEP_REQUIRE_SHARED(json, "reference/maps/expected_paper_metrics.json");
  for (const std::string& name : testing::ReferenceMapNames()) {
    SCOPED_TRACE(name);
    const nlohmann::json expected = testing::ExpectedPaperMetrics(json, name);
    const EnclosedAreas r = ComputeEnclosedAreas(testing::LoadReferencePgm(json.parent_path() / name));
    EXPECT_EQ(r.enclosed_areas, expected.at("enclosed_areas").get<std::int64_t>());
    EXPECT_EQ(r.at_unknown_value, expected.at("at_unknown_value").get<int>());
  }
}

// Every step of the sweep against OpenCV itself: cv::threshold with THRESH_OTSU on the 8-bit
// image, then the outer borders that cv::findContours traces (top-level contours of
// RETR_CCOMP), kept when their region does not touch the border and has at least 4 cells
// (region sizes from connectedComponentsWithStats).
TEST(EnclosedAreasTest, EveryStepAgreesWithOtsuAndFindContoursOnReferenceMaps) {
  SLAMSWEEP_REQUIRE_SHARED(json, "reference/maps/expected_paper_metrics.json");
  for (const std::string& name : testing::ReferenceMapNames()) {
    SCOPED_TRACE(name);
    const cv::Mat pgm = cv::imread((json.parent_path() / name).string(), cv::IMREAD_UNCHANGED);
    const EnclosedAreas r = ComputeEnclosedAreas(testing::LoadReferencePgm(json.parent_path() / name));
    ASSERT_EQ(r.sweep.size(), 51u);
    std::set<std::pair<int, bool>> binarisations;  // (known cells at or below t, unknown free)
    for (const EnclosedAreasStep& step : r.sweep) {
      SCOPED_TRACE("u = " + std::to_string(step.unknown_value));
      cv::Mat image = pgm.clone();
      image.setTo(step.unknown_value, pgm == 205);
      cv::Mat free_cells;
      const int threshold =
          static_cast<int>(cv::threshold(image, free_cells, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU));
      ASSERT_EQ(step.otsu_threshold, threshold);
      binarisations.emplace(cv::countNonZero((pgm <= threshold) & (pgm != 205)), step.unknown_value > threshold);

      cv::Mat labels, stats, centroids;
      cv::connectedComponentsWithStats(free_cells, labels, stats, centroids, 8, CV_32S);
      std::vector<std::vector<cv::Point>> contours;
      std::vector<cv::Vec4i> hierarchy;
      cv::findContours(free_cells, contours, hierarchy, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE);
      std::int64_t enclosed = 0;
      for (std::size_t i = 0; i < contours.size(); ++i) {
        if (hierarchy[i][3] >= 0) continue;  // a hole's border, not an outer one
        const cv::Rect box = cv::boundingRect(contours[i]);
        const bool touches =
            box.x == 0 || box.y == 0 || box.x + box.width == image.cols || box.y + box.height == image.rows;
        const int cells = stats.at<int>(labels.at<int>(contours[i][0]), cv::CC_STAT_AREA);
        enclosed += (!touches && cells >= 4) ? 1 : 0;
      }
      EXPECT_EQ(step.enclosed_areas, enclosed);
    }
    EXPECT_EQ(r.distinct_binarisations, static_cast<int>(binarisations.size()));
  }
}

}  // namespace
}  // namespace slamsweep::evaluator
