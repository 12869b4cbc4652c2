#include "orchestrator/process/outcome_reason.h"

#include <signal.h>

#include <gtest/gtest.h>

#include "orchestrator/process/process_outcome.h"
#include "orchestrator/process/signal_name.h"

namespace slamsweep::orchestrator {
namespace {

TEST(OutcomeReasonTest, Sentences) {
  EXPECT_EQ(ExitReason(3), "exit code 3");
  EXPECT_EQ(SignalReason(SIGSEGV), "killed by SIGSEGV (signal 11)");
  EXPECT_EQ(TimeoutReason(2.0, true, 5.0), "timed out after 2.0 s (SIGTERM, then SIGKILL after 5 s grace)");
  EXPECT_EQ(TimeoutReason(1.5, false, 5.0), "timed out after 1.5 s (SIGTERM)");
  EXPECT_EQ(MemoryReason(2202010, 2048), "peak memory 2.1 GB above the 2048 MB limit");
  EXPECT_EQ(MemoryReason(307200, 100), "peak memory 300 MB above the 100 MB limit");
  EXPECT_EQ(InterruptReason(SIGINT, false, 5), "interrupted by SIGINT (SIGTERM)");
  EXPECT_EQ(InterruptReason(0, true, 2.5), "stopped by the supervisor (SIGTERM, then SIGKILL after 2.5 s grace)");
  EXPECT_EQ(StartFailureReason("foo", "No such file or directory"), "cannot start 'foo': No such file or directory");
}

TEST(SignalNameTest, StandardNamesAndNumbers) {
  EXPECT_EQ(SignalName(SIGKILL), "SIGKILL");
  EXPECT_EQ(SignalName(SIGTERM), "SIGTERM");
  EXPECT_EQ(SignalName(SIGSEGV), "SIGSEGV");
  EXPECT_EQ(SignalName(0), "signal 0");
  EXPECT_EQ(SignalName(1000), "signal 1000");
}

TEST(ProcessOutcomeTest, OkOnlyForCleanExit) {
  ProcessOutcome outcome;
  outcome.ending = ProcessEnding::kExited;
  outcome.exit_code = 0;
  EXPECT_TRUE(outcome.ok());
  outcome.exit_code = 1;
  EXPECT_FALSE(outcome.ok());
  outcome.ending = ProcessEnding::kTimedOut;
  outcome.exit_code = 0;
  EXPECT_FALSE(outcome.ok());
  EXPECT_EQ(EndingName(ProcessEnding::kMemoryLimit), "memory_limit");
}

}  // namespace
}  // namespace slamsweep::orchestrator
