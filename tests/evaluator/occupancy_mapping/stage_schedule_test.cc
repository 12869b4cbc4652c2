#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "evaluator/core/input_error.h"
#include "evaluator/occupancy_mapping/occupancy_mapper.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(StageScheduleTest, EveryKScansEndsWithTheLastScan) {
  EXPECT_THAT(StagesEveryKScans(10, 3), ElementsAre(3, 6, 9, 10));
  EXPECT_THAT(StagesEveryKScans(9, 3), ElementsAre(3, 6, 9));
  EXPECT_THAT(StagesEveryKScans(2, 5), ElementsAre(2));
  EXPECT_TRUE(StagesEveryKScans(0, 5).empty());
  EXPECT_THROW(StagesEveryKScans(10, 0), InputError);
}

TEST(StageScheduleTest, EvenlySpacedStagesRoundAndDropDuplicates) {
  // k * 10 / 4 rounded: 2.5 -> 3, 5, 7.5 -> 8, 10.
  EXPECT_THAT(EvenlySpacedStages(10, 4), ElementsAre(3, 5, 8, 10));
  // More stages than scans: one stage per scan.
  EXPECT_THAT(EvenlySpacedStages(3, 5), ElementsAre(1, 2, 3));
  EXPECT_THAT(EvenlySpacedStages(5000, 50).back(), 5000u);
  EXPECT_EQ(EvenlySpacedStages(5000, 50).size(), 50u);
  EXPECT_THROW(EvenlySpacedStages(10, 0), InputError);
}

TEST(StageScheduleTest, RenderStagesRejectsStageEndsThatDoNotIncrease) {
  LaserScan scan;
  scan.ranges_m = {1.0f};
  scan.range_max_m = 5.0;
  const std::vector<LaserScan> scans(3, scan);
  const std::vector<PlacedScan> placed = PlaceScans(scans, std::vector<Pose>(3));
  const OccupancyMapper mapper;
  const auto ignore = [](const MapStage&) {};
  const std::vector<std::size_t> decreasing = {2, 1};
  EXPECT_THAT([&] { mapper.RenderStages(placed, decreasing, ignore); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("stage 1 ends after scan 1")));
  const std::vector<std::size_t> too_far = {4};
  EXPECT_THAT([&] { mapper.RenderStages(placed, too_far, ignore); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("at most 3")));
  std::size_t calls = 0;
  const std::vector<std::size_t> ends = {1, 3};
  mapper.RenderStages(placed, ends, [&](const MapStage&) { ++calls; });
  EXPECT_EQ(calls, 2u);
}

}  // namespace
}  // namespace slamsweep::evaluator
