#include "evaluator/map/paper_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "evaluator/core/input_error.h"
#include "tests/evaluator/map/map_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using testing::GridFromText;

std::string ErrorOf(const OccupancyGrid& grid, const PaperMetricsOptions& options = {}) {
  try {
    ComputePaperMetrics(grid, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(PaperMetricsTest, JsonCarriesValuesParametersAndDetails) {
  const PaperMetrics m = ComputePaperMetrics(GridFromText({
      "??????????",
      "?########?",
      "?#......#?",
      "?#......#?",
      "?########?",
      "??????????",
  }));
  const nlohmann::json j = m.ToJson();
  for (const char* key : {"occupied_to_free_unknown", "occupied_to_all", "unknown_to_all", "corners", "enclosed_areas",
                          "parameters", "details"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j.at("enclosed_areas"), 1);
  EXPECT_EQ(j.at("parameters").at("profile"), "paper");
  EXPECT_EQ(j.at("parameters").at("corners").at("min_blob_cells"), 5);
  EXPECT_EQ(j.at("parameters").at("corners").at("min_distance_cells"), 10.0);
  EXPECT_EQ(j.at("parameters").at("corners").at("harris_k"), 0.04);
  EXPECT_EQ(j.at("parameters").at("enclosed").at("unknown_value_step"), 5);
  EXPECT_EQ(j.at("parameters").at("enclosed").at("min_area_cells"), 4);
  EXPECT_EQ(j.at("parameters").at("occupied").at("unknown_occupancy"), 0.0);
  EXPECT_EQ(j.at("details").at("occupied").at("occupied_cells"), 20);  // the walls
  EXPECT_TRUE(j.at("details").at("enclosed").contains("at_unknown_value"));
  EXPECT_EQ(j.at("details").at("enclosed").at("sweep").size(), 51u);
}

TEST(PaperMetricsTest, NoKnownCellIsAnInputError) {
  EXPECT_EQ(ErrorOf(OccupancyGrid(30, 20, 0.05)), "map has no known cell: nothing to score");
}

TEST(PaperMetricsTest, MalformedGridsAreInputErrors) {
  OccupancyGrid ragged(4, 4, 0.05, {}, 0.0f);
  ragged.cells.pop_back();
  EXPECT_NE(ErrorOf(ragged).find("expected width x height"), std::string::npos);

  OccupancyGrid bad_cell(4, 3, 0.05, {}, 0.0f);
  bad_cell.at(2, 1) = 1.5f;
  EXPECT_NE(ErrorOf(bad_cell).find("(row 2, col 1)"), std::string::npos) << ErrorOf(bad_cell);
  bad_cell.at(2, 1) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(ErrorOf(bad_cell).find("(row 2, col 1)"), std::string::npos);

  EXPECT_NE(ErrorOf(OccupancyGrid()).find("map is empty"), std::string::npos);
}

TEST(PaperMetricsTest, MapWithoutStructureScoresZero) {
  const PaperMetrics m = ComputePaperMetrics(OccupancyGrid(200, 150, 0.05, {}, 0.0f));
  EXPECT_EQ(m.corners.corners, 0);
  EXPECT_EQ(m.enclosed.enclosed_areas, 0);
  EXPECT_EQ(m.occupied.occupied_cells, 0);
}

TEST(PaperMetricsTest, BadOptionIsNamed) {
  PaperMetricsOptions options;
  options.corners.harris_block_cells = 0;
  EXPECT_NE(ErrorOf(GridFromText({"#."}), options).find("corners.harris_block_cells"), std::string::npos);
}

TEST(PaperMetricsTest, MatchesReferenceMaps) {
  SLAMSWEEP_REQUIRE_SHARED(json, "reference/maps/expected_paper_metrics.json");
  for (const std::string& name : testing::ReferenceMapNames()) {
    SCOPED_TRACE(name);
    const nlohmann::json expected = testing::ExpectedPaperMetrics(json, name);
    const OccupancyGrid grid = testing::LoadReferencePgm(json.parent_path() / name);
    ASSERT_EQ(grid.width, expected.at("width").get<int>());
    ASSERT_EQ(grid.height, expected.at("height").get<int>());
    const nlohmann::json j = ComputePaperMetrics(grid).ToJson();
    EXPECT_EQ(j.at("corners"), expected.at("corners"));
    EXPECT_EQ(j.at("enclosed_areas"), expected.at("enclosed_areas"));
    EXPECT_EQ(j.at("details").at("enclosed").at("at_unknown_value"), expected.at("at_unknown_value"));
    EXPECT_EQ(j.at("details").at("occupied").at("occupied_cells"), expected.at("occupied"));
    for (const char* ratio : {"occupied_to_free_unknown", "occupied_to_all", "unknown_to_all"}) {
      EXPECT_NEAR(j.at(ratio).get<double>(), expected.at(ratio).get<double>(), 1e-9) << ratio;
    }
    // p is stored as float: the mean carries ~1e-9 of representation error (see
    // occupied_proportion_test.cc).
    EXPECT_NEAR(j.at("details").at("occupied").at("threshold").get<double>(), expected.at("threshold").get<double>(),
                1e-8);
  }
}

}  // namespace
}  // namespace slamsweep::evaluator
