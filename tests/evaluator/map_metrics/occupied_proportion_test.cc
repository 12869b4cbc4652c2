#include "evaluator/map_metrics/occupied_proportion.h"

#include <gtest/gtest.h>

#include <string>

#include "evaluator/core/input_error.h"
#include "tests/evaluator/map_metrics/map_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using testing::GridFromText;

TEST(OccupiedProportionTest, TinyGridByHand) {
  // p: 1, 0, ?, 0.5, 0, ?. With unknown as 0 the mean is 1.5 / 6 = 0.25, so the two cells
  // above it (1 and 0.5) are occupied; 2 free, 2 unknown.
  const OccupiedProportion r = ComputeOccupiedProportion(GridFromText({"#.?", "5.?"}));
  EXPECT_DOUBLE_EQ(r.threshold, 0.25);
  EXPECT_EQ(r.occupied_cells, 2);
  EXPECT_EQ(r.free_cells, 2);
  EXPECT_EQ(r.unknown_cells, 2);
  EXPECT_EQ(r.total_cells, 6);
  EXPECT_DOUBLE_EQ(r.occupied_to_free_unknown, 2.0 / 4.0);
  EXPECT_DOUBLE_EQ(r.occupied_to_all, 2.0 / 6.0);
  EXPECT_DOUBLE_EQ(r.unknown_to_all, 2.0 / 6.0);
}

TEST(OccupiedProportionTest, CellAtTheMeanIsNotOccupied) {
  const OccupiedProportion r = ComputeOccupiedProportion(GridFromText({"55", "55"}));
  EXPECT_FLOAT_EQ(static_cast<float>(r.threshold), 0.5f);
  EXPECT_EQ(r.occupied_cells, 0);
  EXPECT_EQ(r.occupied_to_free_unknown, 0.0);
}

TEST(OccupiedProportionTest, UnknownOccupancyOptionEntersMeanAndComparison) {
  // Unknown as 0.9: mean = (1 + 0.5 + 2 * 0.9) / 6 = 0.55, so 1 and both unknown cells are
  // occupied, 0.5 is not.
  OccupiedProportionOptions options;
  options.unknown_occupancy = 0.9;
  const OccupiedProportion r = ComputeOccupiedProportion(GridFromText({"#.?", "5.?"}), options);
  EXPECT_NEAR(r.threshold, 0.55, 1e-15);
  EXPECT_EQ(r.occupied_cells, 3);
  EXPECT_DOUBLE_EQ(r.occupied_to_free_unknown, 1.0);
}

TEST(OccupiedProportionTest, BadInputIsAnInputError) {
  EXPECT_THROW(ComputeOccupiedProportion(GridFromText({"??", "??"})), InputError);
  OccupiedProportionOptions options;
  options.unknown_occupancy = 1.5;
  try {
    ComputeOccupiedProportion(GridFromText({"#."}), options);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("occupied.unknown_occupancy"), std::string::npos) << e.what();
  }
}

TEST(OccupiedProportionTest, MatchesReferenceMaps) {
  SLAMSWEEP_REQUIRE_SHARED(json, "reference/maps/expected_paper_metrics.json");
  for (const std::string& name : testing::ReferenceMapNames()) {
    SCOPED_TRACE(name);
    const nlohmann::json expected = testing::ExpectedPaperMetrics(json, name);
    const OccupancyGrid grid = testing::LoadReferencePgm(json.parent_path() / name);
    const OccupiedProportion r = ComputeOccupiedProportion(grid);
    // The grid stores p as float, (255 - v) / 255 rounded to 24 bits, while the reference
    // averaged exact doubles: the means differ by ~1e-9 (1.1e-9 on telecom_icp). The ratios
    // are ratios of cell counts and agree to 1e-9.
    EXPECT_NEAR(r.threshold, expected.at("threshold").get<double>(), 1e-8);
    EXPECT_EQ(r.occupied_cells, expected.at("occupied").get<std::int64_t>());
    EXPECT_NEAR(r.occupied_to_free_unknown, expected.at("occupied_to_free_unknown").get<double>(), 1e-9);
    EXPECT_NEAR(r.occupied_to_all, expected.at("occupied_to_all").get<double>(), 1e-9);
    EXPECT_NEAR(r.unknown_to_all, expected.at("unknown_to_all").get<double>(), 1e-9);
  }
}

}  // namespace
}  // namespace slamsweep::evaluator
