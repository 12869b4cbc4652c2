#include "evaluator/map_metrics/corner_count.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "evaluator/core/input_error.h"
#include "tests/evaluator/map_metrics/map_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

// A rows x cols grid of unknown cells with one room: free interior, 1-cell occupied walls.
OccupancyGrid RoomMap(int rows, int cols, cv::Rect interior) {
  OccupancyGrid grid(cols, rows, 0.05);
  for (int r = interior.y - 1; r <= interior.y + interior.height; ++r) {
    for (int c = interior.x - 1; c <= interior.x + interior.width; ++c) {
      grid.at(r, c) = interior.contains(cv::Point(c, r)) ? 0.0f : 1.0f;
    }
  }
  return grid;
}

TEST(CornerCountTest, AllFreeMapHasNoCorners) {
  // Remapped to 1 everywhere: the Laplacian of a constant is 0 (the border is reflected), so
  // the structure mask is empty and nothing reaches the Harris detector.
  const OccupancyGrid grid(150, 140, 0.05, {}, 0.0f);
  const CornerCount r = ComputeCornerCount(grid);
  EXPECT_EQ(r.corners, 0);
  EXPECT_EQ(r.max_abs_log, 0.0);
  EXPECT_EQ(r.structure_blobs_kept, 0);
}

TEST(CornerCountTest, SingleKnownCellDoesNotCrash) {
  OccupancyGrid grid(20, 20, 0.05);
  grid.at(10, 10) = 0.0f;
  EXPECT_NO_THROW(ComputeCornerCount(grid));
}

TEST(CornerCountTest, RectangularRoomHasFourCorners) {
  // Walls and unknown both remap to 0, so the map is one bright 40 x 25 rectangle on black.
  // Its LoG is a ring along the rectangle's edge; on the cleaned ring the Harris response is
  // negative along straight edges and peaks only where the edges turn, once per corner
  // (the rectangle's sides are far longer than the 10-cell minimum distance, and the peaks
  // of one corner lie within it).
  const CornerCount r = ComputeCornerCount(RoomMap(80, 100, cv::Rect(30, 25, 40, 25)));
  EXPECT_EQ(r.corners, 4);
  EXPECT_EQ(r.structure_blobs_dropped, 0);
}

TEST(CornerCountTest, TwoSeparateRoomsHaveEightCorners) {
  OccupancyGrid grid = RoomMap(80, 160, cv::Rect(20, 20, 40, 30));
  const OccupancyGrid second = RoomMap(80, 160, cv::Rect(100, 30, 30, 35));
  for (std::size_t i = 0; i < grid.cells.size(); ++i) {
    if (!OccupancyGrid::IsUnknown(second.cells[i])) grid.cells[i] = second.cells[i];
  }
  EXPECT_EQ(ComputeCornerCount(grid).corners, 8);
}

TEST(CornerCountTest, MatchesReferenceMaps) {
  SLAMSWEEP_REQUIRE_SHARED(json, "reference/maps/expected_paper_metrics.json");
  for (const std::string& name : testing::ReferenceMapNames()) {
    SCOPED_TRACE(name);
    const CornerCount r = ComputeCornerCount(testing::LoadReferencePgm(json.parent_path() / name));
    EXPECT_EQ(r.corners, testing::ExpectedPaperMetrics(json, name).at("corners").get<std::int64_t>());
    EXPECT_GT(r.structure_blobs_dropped, 0);  // these maps do have small dots to drop
  }
}

TEST(CornerCountTest, NoKnownCellIsAnInputError) {
  try {
    ComputeCornerCount(OccupancyGrid(10, 10, 0.05));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "map has no known cell: nothing to score");
  }
}

TEST(CornerCountTest, BadOptionsNameTheOption) {
  const OccupancyGrid grid(10, 10, 0.05, {}, 0.0f);
  const auto message_for = [&](CornerCountOptions options) {
    try {
      ComputeCornerCount(grid, options);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CornerCountOptions even_kernel;
  even_kernel.gaussian_kernel_cells = 4;
  EXPECT_NE(message_for(even_kernel).find("corners.gaussian_kernel_cells = 4"), std::string::npos);
  CornerCountOptions zero_quality;
  zero_quality.quality_level = 0.0;
  EXPECT_NE(message_for(zero_quality).find("corners.quality_level"), std::string::npos);
  CornerCountOptions bad_aperture;
  bad_aperture.harris_aperture_cells = 9;
  EXPECT_NE(message_for(bad_aperture).find("corners.harris_aperture_cells"), std::string::npos);
  CornerCountOptions no_blob;
  no_blob.min_blob_cells = 0;
  EXPECT_NE(message_for(no_blob).find("corners.min_blob_cells"), std::string::npos);
  CornerCountOptions negative_distance;
  negative_distance.min_distance_cells = -1.0;
  EXPECT_NE(message_for(negative_distance).find("corners.min_distance_cells"), std::string::npos);
}

}  // namespace
}  // namespace slamsweep::evaluator
