// The queue's state names: the text the SQLite file and the HTTP API hold, read back to the same state.
#include "orchestrator/service/queue_states.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator::service {
namespace {

using ::testing::HasSubstr;

TEST(QueueStatesTest, NamesAreTheQueuesAndTheApisText) {
  std::vector<std::string> runs, sweeps;
  for (const QueuedRunState state : kRunStates) runs.emplace_back(ToString(state));
  for (const QueuedSweepState state : kSweepStates) sweeps.emplace_back(ToString(state));
  EXPECT_EQ(runs, (std::vector<std::string>{"queued", "running", "ok", "failed", "reused", "cancelled"}));
  EXPECT_EQ(sweeps, (std::vector<std::string>{"queued", "running", "ok", "failed", "cancelled"}));
  EXPECT_EQ(ToString(ReportState::kNone), "none");
  EXPECT_EQ(ToString(ReportState::kWriting), "writing");
  EXPECT_EQ(ToString(ReportState::kReady), "ready");
  EXPECT_EQ(ToString(ReportState::kFailed), "failed");
  EXPECT_EQ(CancellingStateName(), "cancelling");
}

TEST(QueueStatesTest, EveryNameReadsBackToItsState) {
  for (const QueuedRunState state : kRunStates) {
    EXPECT_EQ(ParseRunState(ToString(state)), state);
    EXPECT_EQ(FindRunState(ToString(state)), state);
  }
  for (const QueuedSweepState state : kSweepStates) {
    EXPECT_EQ(ParseSweepState(ToString(state)), state);
    EXPECT_EQ(FindSweepState(ToString(state)), state);
  }
  for (const ReportState state :
       {ReportState::kNone, ReportState::kWriting, ReportState::kReady, ReportState::kFailed}) {
    EXPECT_EQ(FindReportState(ToString(state)), state);
  }
}

TEST(QueueStatesTest, AnUnknownNameIsAnErrorNamingIt) {
  EXPECT_EQ(FindRunState("Running"), std::nullopt);
  EXPECT_EQ(FindSweepState("reused"), std::nullopt) << "a run state, not a sweep's";
  EXPECT_EQ(FindReportState(""), std::nullopt);
  try {
    ParseRunState("paused");
    FAIL() << "no error";
  } catch (const evaluator::InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("'paused'"));
  }
  try {
    ParseSweepState("cancelling");
    FAIL() << "no error";
  } catch (const evaluator::InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("'cancelling'"));
  }
}

}  // namespace
}  // namespace slamsweep::orchestrator::service
