#include "report/images/frame_selection.h"

#include <gtest/gtest.h>

namespace slamsweep::report {
namespace {

using Indices = std::vector<std::size_t>;

TEST(EvenlySpacedIndicesTest, KeepsFirstAndLast) {
  // round(i * 9 / 3) for i = 0..3.
  EXPECT_EQ(EvenlySpacedIndices(10, 4), (Indices{0, 3, 6, 9}));
  // round(i * 199 / 9): 0, 22.1, 44.2, 66.3, 88.4, 110.6, 132.7, 154.8, 176.9, 199.
  EXPECT_EQ(EvenlySpacedIndices(200, 10), (Indices{0, 22, 44, 66, 88, 111, 133, 155, 177, 199}));
}

TEST(EvenlySpacedIndicesTest, EdgeCases) {
  EXPECT_EQ(EvenlySpacedIndices(5, 5), (Indices{0, 1, 2, 3, 4}));
  EXPECT_EQ(EvenlySpacedIndices(3, 7), (Indices{0, 1, 2}));
  EXPECT_EQ(EvenlySpacedIndices(24, 2), (Indices{0, 23}));
  EXPECT_EQ(EvenlySpacedIndices(24, 1), (Indices{23}));
  EXPECT_TRUE(EvenlySpacedIndices(24, 0).empty());
  EXPECT_TRUE(EvenlySpacedIndices(0, 3).empty());
}

TEST(EvenlySpacedIndicesTest, AlwaysAscendingAndDistinct) {
  for (std::size_t count = 1; count < 60; ++count) {
    for (std::size_t keep = 2; keep <= count; ++keep) {
      const Indices indices = EvenlySpacedIndices(count, keep);
      ASSERT_EQ(indices.size(), keep);
      EXPECT_EQ(indices.front(), 0u);
      EXPECT_EQ(indices.back(), count - 1);
      for (std::size_t i = 1; i < indices.size(); ++i) EXPECT_LT(indices[i - 1], indices[i]);
    }
  }
}

}  // namespace
}  // namespace slamsweep::report
