#include "orchestrator/matrix/shard.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "evaluator/core/input_error.h"
#include "orchestrator/matrix/expand_matrix.h"
#include "tests/orchestrator/matrix/test_config.h"

namespace slamsweep::orchestrator {
namespace {

using ::testing::HasSubstr;

TEST(ShardTest, ParsesIOfN) {
  const Shard shard = ParseShard("2/4");
  EXPECT_EQ(shard.index, 2u);
  EXPECT_EQ(shard.count, 4u);
  EXPECT_EQ(ParseShard("1/1").count, 1u);
}

std::string ErrorOf(std::string_view text) {
  try {
    ParseShard(text);
  } catch (const evaluator::InputError& error) {
    return error.what();
  }
  return "";
}

TEST(ShardTest, RejectsMalformedShardsNamingTheOption) {
  for (const char* text : {"", "2", "/4", "2/", "a/b", "2/4x", "-1/4", "2 /4", "1.5/4"}) {
    EXPECT_THAT(ErrorOf(text), HasSubstr("--shard: expected I/N with whole numbers")) << text;
  }
  for (const char* text : {"0/4", "5/4", "1/0", "0/0"}) {
    EXPECT_THAT(ErrorOf(text), HasSubstr("--shard: expected 1 <= I <= N in I/N")) << text;
  }
  EXPECT_THROW(SelectShard({}, 0, 3), evaluator::InputError);
  EXPECT_THROW(SelectShard({}, 4, 3), evaluator::InputError);
}

TEST(ShardTest, SharesAreDisjointAndCoverEveryRun) {
  const std::vector<RunSpec> runs = ExpandMatrix(testing::TwoByTwo());
  for (std::size_t count = 1; count <= 6; ++count) {
    std::multiset<std::string> seen;
    for (std::size_t index = 1; index <= count; ++index) {
      const std::vector<RunSpec> share = SelectShard(runs, index, count);
      for (const RunSpec& run : share) seen.insert(run.run_id);
    }
    ASSERT_EQ(seen.size(), runs.size()) << count;
    for (const RunSpec& run : runs) EXPECT_EQ(seen.count(run.run_id), 1u) << run.run_id;
  }
}

TEST(ShardTest, KeepsTheOriginalOrderWithinAShare) {
  const std::vector<RunSpec> runs = ExpandMatrix(testing::TwoByTwo());
  const std::vector<RunSpec> share = SelectShard(runs, 1, 3);
  std::size_t position = 0;
  for (const RunSpec& run : share) {
    while (position < runs.size() && runs[position].run_id != run.run_id) ++position;
    ASSERT_LT(position, runs.size()) << "out of order: " << run.run_id;
  }
}

TEST(ShardTest, AddingRunsDoesNotMoveExistingOnes) {
  const std::vector<RunSpec> before = ExpandMatrix(testing::TwoByTwo());
  SweepConfig grown = testing::TwoByTwo();
  grown.sequences.push_back(testing::Sequence("seq3"));
  const std::vector<RunSpec> after = ExpandMatrix(grown);
  std::map<std::string, std::size_t> share_before;
  for (std::size_t index = 1; index <= 4; ++index) {
    for (const RunSpec& run : SelectShard(before, index, 4)) share_before[run.run_id] = index;
  }
  for (std::size_t index = 1; index <= 4; ++index) {
    for (const RunSpec& run : SelectShard(after, index, 4)) {
      if (share_before.contains(run.run_id)) {
        EXPECT_EQ(share_before[run.run_id], index) << run.run_id;
      }
    }
  }
}

TEST(ShardTest, SpreadsRunsOverEveryShare) {
  SweepConfig config = testing::TwoByTwo();
  config.iterations = 10;  // 200 runs
  const std::vector<RunSpec> runs = ExpandMatrix(config);
  for (std::size_t index = 1; index <= 4; ++index) {
    // A hash share: not exact, but no share should be empty or hold most of the runs.
    const std::size_t size = SelectShard(runs, index, 4).size();
    EXPECT_GT(size, runs.size() / 8) << index;
    EXPECT_LT(size, runs.size() / 2) << index;
  }
}

}  // namespace
}  // namespace slamsweep::orchestrator
