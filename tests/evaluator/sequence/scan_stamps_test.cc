#include "evaluator/sequence/scan_stamps.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::ElementsAre;

TEST(ScanStampsTest, StrictlyIncreasingStampsAreKept) {
  const std::vector<double> recorded = {0.5, 0.75, 2.0, 2.000001};
  const ScanStamps stamps = ChooseScanStamps(recorded, {});
  EXPECT_EQ(stamps.outcome, StampOutcome::kRecorded);
  EXPECT_EQ(stamps.stamps_s, recorded);
  EXPECT_TRUE(stamps.non_increasing.empty());
}

TEST(ScanStampsTest, AnIsolatedBackwardStepIsLiftedAboveItsPredecessor) {
  // 200 stamps 1 s apart, record 50 jumps back half a second: 1 of 200 = 0.5 % <= 1 %.
  std::vector<double> recorded;
  for (int i = 0; i < 200; ++i) recorded.push_back(i);
  recorded[50] = 48.5;
  const ScanStamps stamps = ChooseScanStamps(recorded, {});
  EXPECT_EQ(stamps.outcome, StampOutcome::kRepaired);
  EXPECT_THAT(stamps.non_increasing, ElementsAre(50u));
  EXPECT_DOUBLE_EQ(stamps.stamps_s[50], 49.001);  // predecessor 49 + the default 1 ms step
  EXPECT_EQ(stamps.stamps_s[49], 49.0);
  EXPECT_EQ(stamps.stamps_s[51], 51.0);
}

TEST(ScanStampsTest, ALiftCascadesThroughStampsItOvertakes) {
  StampOptions options;
  options.max_repaired_fraction = 0.5;
  options.repair_step_s = 0.25;
  // 10, 10 (equal), 10.1 (now behind the lifted 10.25), 11.
  const ScanStamps stamps = ChooseScanStamps(std::vector<double>{10.0, 10.0, 10.1, 11.0}, options);
  EXPECT_EQ(stamps.outcome, StampOutcome::kRepaired);
  EXPECT_THAT(stamps.non_increasing, ElementsAre(1u, 2u));
  EXPECT_THAT(stamps.stamps_s, ElementsAre(10.0, 10.25, 10.5, 11.0));
}

TEST(ScanStampsTest, ConstantStampsFallBackToRecordOrder) {
  const std::vector<double> recorded(5, 1018930000.0);
  const ScanStamps stamps = ChooseScanStamps(recorded, {});
  EXPECT_EQ(stamps.outcome, StampOutcome::kRecordOrder);
  EXPECT_THAT(stamps.stamps_s, ElementsAre(0.0, 1.0, 2.0, 3.0, 4.0));
  EXPECT_EQ(stamps.non_increasing.size(), 4u);
}

TEST(ScanStampsTest, DecreasingStampsFallBackAtTheChosenPeriod) {
  StampOptions options;
  options.record_order_period_s = 0.1;
  const ScanStamps stamps = ChooseScanStamps(std::vector<double>{-0.4, -0.9, -1.3}, options);
  EXPECT_EQ(stamps.outcome, StampOutcome::kRecordOrder);
  EXPECT_THAT(stamps.stamps_s, ElementsAre(0.0, 0.1, 0.2));
}

TEST(ScanStampsTest, RecordOrderPolicyIgnoresGoodStamps) {
  StampOptions options;
  options.policy = StampPolicy::kRecordOrder;
  const ScanStamps stamps = ChooseScanStamps(std::vector<double>{5.0, 6.0}, options);
  EXPECT_EQ(stamps.outcome, StampOutcome::kRecordOrder);
  EXPECT_THAT(stamps.stamps_s, ElementsAre(0.0, 1.0));
}

TEST(ScanStampsTest, RecordedPolicyReportsButDoesNotChange) {
  StampOptions options;
  options.policy = StampPolicy::kRecorded;
  const ScanStamps stamps = ChooseScanStamps(std::vector<double>{1.0, 3.0, 2.0}, options);
  EXPECT_EQ(stamps.outcome, StampOutcome::kRecorded);
  EXPECT_THAT(stamps.stamps_s, ElementsAre(1.0, 3.0, 2.0));
  EXPECT_THAT(stamps.non_increasing, ElementsAre(2u));
}

TEST(ScanStampsTest, EmptyAndSingleRecordsNeedNoChoice) {
  EXPECT_TRUE(ChooseScanStamps(std::vector<double>{}, {}).stamps_s.empty());
  EXPECT_THAT(ChooseScanStamps(std::vector<double>{0.0}, {}).stamps_s, ElementsAre(0.0));
}

TEST(ScanStampsTest, NonFiniteStampIsAnError) {
  const std::vector<double> recorded = {1.0, std::numeric_limits<double>::quiet_NaN()};
  EXPECT_THROW(ChooseScanStamps(recorded, {}), InputError);
}

TEST(ScanStampsTest, BadOptionsNameTheOption) {
  StampOptions options;
  options.record_order_period_s = 0.0;
  try {
    CheckStampOptions(options);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("record_order_period_s"), std::string::npos) << error.what();
  }
  options = {};
  options.max_repaired_fraction = 1.5;
  EXPECT_THROW(CheckStampOptions(options), InputError);
  options = {};
  options.repair_step_s = -1.0;
  EXPECT_THROW(CheckStampOptions(options), InputError);
}

TEST(ScanStampsTest, PolicyNamesRoundTrip) {
  for (StampPolicy policy : {StampPolicy::kAuto, StampPolicy::kRecorded, StampPolicy::kRecordOrder}) {
    EXPECT_EQ(ParseStampPolicy(StampPolicyName(policy)), policy);
  }
  try {
    ParseStampPolicy("sorted", "--stamps");
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("--stamps"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("record_order"), std::string::npos) << error.what();
  }
}

StampOptions Retiming() {
  StampOptions options;
  options.repair = StampRepair::kRetime;
  return options;
}

// A late stamp (the record's arrival delayed) moves alone, between its neighbours; lifting would instead
// drag the three records after it to a millisecond apart.
TEST(ScanStampsTest, RetimingMovesALateStampAloneBetweenItsNeighbours) {
  const std::vector<double> recorded{0.0, 1.0, 2.0, 3.8, 3.0, 4.0, 5.0};
  const ScanStamps stamps = ChooseScanStamps(recorded, Retiming());
  EXPECT_EQ(stamps.outcome, StampOutcome::kRetimed);
  EXPECT_THAT(stamps.retimed, ElementsAre(3u));
  EXPECT_THAT(stamps.non_increasing, ElementsAre(4u));
  EXPECT_THAT(stamps.stamps_s, ElementsAre(0.0, 1.0, 2.0, 2.5, 3.0, 4.0, 5.0));
  const StampFacts facts = DescribeStamps(recorded, stamps);
  EXPECT_EQ(facts.steps_back, 1u);
  EXPECT_EQ(facts.duplicates, 0u);
  EXPECT_DOUBLE_EQ(facts.largest_step_back_s, 0.8);
  EXPECT_EQ(facts.changed, 1u);
  EXPECT_DOUBLE_EQ(facts.largest_change_s, 1.3);
}

// An early stamp is the one outside the longest increasing run, and repeated stamps are re-timed too.
TEST(ScanStampsTest, RetimingHandlesEarlyStampsDuplicatesAndTheEnds) {
  const std::vector<double> recorded{0.5, 0.0, 1.0, 1.0, 2.0, 0.2, 4.0, 3.9};
  StampOptions options = Retiming();
  options.max_retimed_fraction = 0.5;  // 4 of these 8 move
  const ScanStamps stamps = ChooseScanStamps(recorded, options);
  EXPECT_EQ(stamps.outcome, StampOutcome::kRetimed);
  // Kept: 0.0, 1.0, 2.0, 3.9 (indices 1, 2, 4, 7): of the two 1.0 the first, of the runs of length 4
  // the one ending lowest.
  EXPECT_THAT(stamps.retimed, ElementsAre(0u, 3u, 5u, 6u));
  // Before the first kept stamp the kept spacing continues (1 s per record there); between kept ones,
  // linear by record index.
  using ::testing::DoubleNear;
  EXPECT_THAT(stamps.stamps_s, ElementsAre(DoubleNear(-1.0, 1e-12), 0.0, 1.0, DoubleNear(1.5, 1e-12), 2.0,
                                           DoubleNear(2.0 + 1.9 / 3, 1e-12), DoubleNear(2.0 + 3.8 / 3, 1e-12), 3.9));
  const StampFacts facts = DescribeStamps(recorded, stamps);
  EXPECT_EQ(facts.steps_back, 3u);
  EXPECT_EQ(facts.duplicates, 1u);
  EXPECT_DOUBLE_EQ(facts.largest_step_back_s, 1.8);
  EXPECT_EQ(facts.changed, 4u);
  EXPECT_NEAR(facts.largest_change_s, 2.0 + 1.9 / 3 - 0.2, 1e-12);
}

TEST(ScanStampsTest, RetimingFallsBackToRecordOrderWhenMostStampsWouldMove) {
  const std::vector<double> recorded{5.0, 4.0, 3.0, 2.0, 1.0};
  const ScanStamps stamps = ChooseScanStamps(recorded, Retiming());
  EXPECT_EQ(stamps.outcome, StampOutcome::kRecordOrder);
  EXPECT_THAT(stamps.stamps_s, ElementsAre(0.0, 1.0, 2.0, 3.0, 4.0));
  EXPECT_TRUE(stamps.retimed.empty());
  EXPECT_EQ(DescribeStamps(recorded, stamps).changed, 5u);
}

TEST(ScanStampsTest, RetimingUnderTheRecordedPolicyReportsButDoesNotChange) {
  StampOptions options = Retiming();
  options.policy = StampPolicy::kRecorded;
  const std::vector<double> recorded{0.0, 2.0, 1.0, 3.0};
  const ScanStamps stamps = ChooseScanStamps(recorded, options);
  EXPECT_EQ(stamps.outcome, StampOutcome::kRecorded);
  EXPECT_THAT(stamps.non_increasing, ElementsAre(2u));
  EXPECT_THAT(stamps.stamps_s, ElementsAre(0.0, 2.0, 1.0, 3.0));
}

TEST(ScanStampsTest, StampFactsJsonNamesEveryFact) {
  StampFacts facts;
  facts.outcome = StampOutcome::kRetimed;
  facts.records = 9;
  facts.steps_back = 2;
  facts.order_check = RecordOrderCheck{2, 2, 0, 1, 1};
  const nlohmann::json json = StampFactsJson(facts);
  EXPECT_EQ(json.at("outcome"), "retimed");
  EXPECT_EQ(json.at("records"), 9);
  EXPECT_EQ(json.at("steps_back"), 2);
  EXPECT_EQ(json.at("order_check").at("scans_closer_in_file_order"), 2);
  EXPECT_EQ(json.at("order_check").at("odometry_shorter_in_stamp_order"), 1);
}

}  // namespace
}  // namespace slamsweep::evaluator
