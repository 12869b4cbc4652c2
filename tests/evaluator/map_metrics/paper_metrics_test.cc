#include "evaluator/map_metrics/paper_metrics.h"

#include <gtest/gtest.h>
#include <sched.h>

#include <array>
#include <vector>

#include <cmath>
#include <limits>
#include <string>

#include "evaluator/core/input_error.h"
#include "tests/evaluator/map_metrics/map_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

/// `score()` with this thread allowed one core (the metrics then use no helper thread).
template <typename Score>
nlohmann::json OnOneCore(Score&& score) {
  cpu_set_t before;
  EXPECT_EQ(sched_getaffinity(0, sizeof before, &before), 0);
  int first = 0;
  while (first < CPU_SETSIZE && !CPU_ISSET(first, &before)) ++first;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(first, &one);
  EXPECT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
  nlohmann::json j = score();
  EXPECT_EQ(sched_setaffinity(0, sizeof before, &before), 0);
  return j;
}

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

/// Every number of `expected` (one map of a reference JSON) against the metrics computed with `options`.
void ExpectReferenceValues(const std::filesystem::path& json, const PaperMetricsOptions& options) {
  for (const std::string& name : testing::ReferenceMapNames()) {
    SCOPED_TRACE(json.filename().string() + ": " + name);
    const nlohmann::json expected = testing::ExpectedPaperMetrics(json, name);
    const OccupancyGrid grid = testing::LoadReferencePgm(json.parent_path() / name);
    ASSERT_EQ(grid.width, expected.at("width").get<int>());
    ASSERT_EQ(grid.height, expected.at("height").get<int>());
    const nlohmann::json j = ComputePaperMetrics(grid, options).ToJson();
    // The overload that crops the grid in place and reuses its cells gives the same JSON, on two
    // cores (the enclosed areas on a helper thread) and on one.
    EXPECT_EQ(ComputePaperMetrics(OccupancyGrid(grid), options).ToJson(), j);
    EXPECT_EQ(OnOneCore([&] { return ComputePaperMetrics(OccupancyGrid(grid), options).ToJson(); }), j);
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
    if (expected.contains("cropped_width")) {
      EXPECT_EQ(j.at("cropped_width"), expected.at("cropped_width"));
      EXPECT_EQ(j.at("cropped_height"), expected.at("cropped_height"));
    } else {
      EXPECT_EQ(j.at("cropped_width"), expected.at("width"));  // --no-crop scores the whole grid
    }
  }
}

TEST(PaperMetricsTest, DefaultCropMatchesTheCroppedReferenceValues) {
  SLAMSWEEP_REQUIRE_SHARED(json, "reference/maps/expected_paper_metrics_cropped.json");
  ExpectReferenceValues(json, PaperMetricsOptions{});
}

TEST(PaperMetricsTest, NoCropMatchesTheRawGridReferenceValues) {
  SLAMSWEEP_REQUIRE_SHARED(json, "reference/maps/expected_paper_metrics.json");
  PaperMetricsOptions options;
  options.canvas.crop = false;
  ExpectReferenceValues(json, options);
}

/// `grid` inside a larger canvas of unknown cells: `left`, `top`, `right`, `bottom` cells added.
OccupancyGrid Padded(const OccupancyGrid& grid, int left, int top, int right, int bottom) {
  GridOrigin origin = grid.origin;
  origin.x_m -= left * grid.resolution_m;
  origin.y_m -= bottom * grid.resolution_m;
  OccupancyGrid padded(grid.width + left + right, grid.height + top + bottom, grid.resolution_m, origin);
  for (int row = 0; row < grid.height; ++row) {
    for (int col = 0; col < grid.width; ++col) padded.at(row + top, col + left) = grid.at(row, col);
  }
  return padded;
}

TEST(PaperMetricsTest, PaddingAMapWithUnknownCellsChangesNoMetric) {
  SLAMSWEEP_REQUIRE_SHARED(json, "reference/maps/expected_paper_metrics_cropped.json");
  const OccupancyGrid map = testing::LoadReferencePgm(json.parent_path() / "telecom_rbpf.pgm");
  const nlohmann::json original = ComputePaperMetrics(map).ToJson();
  const auto same_numbers = [&](const nlohmann::json& padded) {
    for (const char* key : {"occupied_to_free_unknown", "occupied_to_all", "unknown_to_all", "corners",
                            "enclosed_areas", "cropped_width", "cropped_height"}) {
      EXPECT_EQ(padded.at(key), original.at(key)) << key;  // bit for bit
    }
  };
  // Any width on any side, including a canvas several times the map (a program's 170 m square).
  for (const auto& [left, top, right, bottom] :
       std::vector<std::array<int, 4>>{{1, 0, 0, 0}, {0, 7, 0, 0}, {0, 0, 33, 0}, {0, 0, 0, 2}, {250, 400, 1000, 3}}) {
    SCOPED_TRACE(std::to_string(left) + "," + std::to_string(top) + "," + std::to_string(right) + "," +
                 std::to_string(bottom));
    same_numbers(ComputePaperMetrics(Padded(map, left, top, right, bottom)).ToJson());
  }
  // Without the crop the ratios follow the canvas: the reason for the rule.
  PaperMetricsOptions raw;
  raw.canvas.crop = false;
  EXPECT_NE(ComputePaperMetrics(Padded(map, 0, 0, 500, 0), raw).occupied.occupied_to_all,
            ComputePaperMetrics(map, raw).occupied.occupied_to_all);
}

TEST(PaperMetricsTest, CropKeepsEveryCellWhereItWasInTheWorld) {
  OccupancyGrid grid(10, 8, 0.5, {-3.0, 2.0, 0.0});
  grid.at(2, 3) = 0.9f;  // row 2 from the top, col 3
  grid.at(5, 6) = 0.1f;
  const CellWindow window = KnownCellsWindow(grid, 1);
  EXPECT_EQ(window, (CellWindow{2, 1, 6, 6}));
  const OccupancyGrid cropped = CropGrid(grid, window);
  EXPECT_FLOAT_EQ(cropped.at(1, 1), 0.9f);
  EXPECT_DOUBLE_EQ(cropped.CellCenterXM(1), grid.CellCenterXM(3));
  EXPECT_DOUBLE_EQ(cropped.CellCenterYM(1), grid.CellCenterYM(2));
  EXPECT_DOUBLE_EQ(cropped.CellCenterYM(4), grid.CellCenterYM(5));
  // Nothing known: nothing to crop to.
  EXPECT_EQ(KnownCellsWindow(OccupancyGrid(4, 3, 0.1), 2), (CellWindow{0, 0, 4, 3}));
  EXPECT_THROW(KnownCellsWindow(grid, -1), InputError);
}

}  // namespace
}  // namespace slamsweep::evaluator
