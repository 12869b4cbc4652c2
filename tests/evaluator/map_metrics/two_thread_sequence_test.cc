#include "evaluator/map_metrics/two_thread_sequence.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

namespace slamsweep::evaluator {
namespace {

TEST(TwoThreadSequenceTest, HandsEveryResultOverOnceInOrder) {
  for (const int count : {0, 1, 2, 7, 100}) {
    std::vector<int> seen;
    std::atomic<int> made = 0;
    ForEachInOrderOnTwoThreads<int>(
        count,
        [&](int i) {
          ++made;
          if (i % 3 == 0) std::this_thread::sleep_for(std::chrono::microseconds(200));  // out-of-order finishes
          return i * i;
        },
        [&](int i, int square) {
          EXPECT_EQ(square, i * i);
          seen.push_back(i);
        });
    EXPECT_EQ(made.load(), count);
    ASSERT_EQ(static_cast<int>(seen.size()), count);
    for (int i = 0; i < count; ++i) EXPECT_EQ(seen[static_cast<std::size_t>(i)], i);
  }
}

TEST(TwoThreadSequenceTest, AFailingStepIsRethrownHereAndNothingAfterItIsUsed) {
  std::vector<int> seen;
  EXPECT_THROW(ForEachInOrderOnTwoThreads<int>(
                   50,
                   [](int i) {
                     if (i == 20) throw std::runtime_error("step 20");
                     return i;
                   },
                   [&](int i, int) { seen.push_back(i); }),
               std::runtime_error);
  for (const int i : seen) EXPECT_LT(i, 20);
}

TEST(TwoThreadSequenceTest, AFailingUseStopsTheHelperAndIsRethrown) {
  std::atomic<int> made = 0;
  EXPECT_THROW(ForEachInOrderOnTwoThreads<int>(
                   1000,
                   [&](int i) {
                     ++made;
                     std::this_thread::sleep_for(std::chrono::microseconds(100));
                     return i;
                   },
                   [](int i, int) {
                     if (i == 3) throw std::logic_error("use 3");
                   }),
               std::logic_error);
  EXPECT_LT(made.load(), 1000);  // the helper stopped taking steps
}

}  // namespace
}  // namespace slamsweep::evaluator
