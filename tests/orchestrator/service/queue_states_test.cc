// The queue's state names: the text the SQLite file and the HTTP API hold, read back to the same state.
#include "orchestrator/run/run_status.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "evaluator/core/input_error.h"
#include "orchestrator/service/queue_store.h"
#include "orchestrator/store/sqlite_db.h"
#include "tests/orchestrator/service/queued_sweep_fixture.h"
#include "tests/support/shared_data.h"

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

TEST(QueueStatesTest, TheQueueFileHoldsTheNames) {
  testing::TempDir dir;
  {
    QueueStore queue = QueueStore::Open(dir / "queue.sqlite");
    const QueuedSweep sweep = SweepNamedS();
    queue.AddSweep(sweep, {{{"run_id", "a"}}, {{"run_id", "b"}}, {{"run_id", "c"}}}, dir / "sweeps");
    queue.AddSweep(sweep, {}, dir / "sweeps");
    queue.SetRunState(1, "a", QueuedRunState::kReused, false, std::nullopt, "", 7);
    queue.SetRunState(1, "b", QueuedRunState::kCancelled);
    queue.SetSweepState(1, QueuedSweepState::kCancelled, "m");
  }
  SqliteDb db = SqliteDb::Open(dir / "queue.sqlite", false);
  std::vector<std::string> texts;
  auto runs = db.Prepare("SELECT state FROM runs ORDER BY position");
  while (runs.Step()) texts.push_back(runs.Text(0));
  auto sweeps = db.Prepare("SELECT state, started_at <> '', finished_at <> '' FROM sweeps ORDER BY id");
  while (sweeps.Step()) texts.push_back(sweeps.Text(0) + " " + sweeps.Text(1) + " " + sweeps.Text(2));
  EXPECT_EQ(texts, (std::vector<std::string>{"reused", "cancelled", "queued", "cancelled 1 1", "queued 0 0"}));
}

}  // namespace
}  // namespace slamsweep::orchestrator::service
