// Parsing of Slurm's own reports and the state -> reason mapping. The scontrol and sacct lines are
// the formats Slurm 22.05 prints (the scontrol ones copied from a one-node cluster, shortened).

#include "orchestrator/slurm/slurm_states.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace slamsweep::orchestrator {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(ParseArrayTaskIds, ReadsSinglesRangesListsAndIgnoresTheThrottle) {
  EXPECT_THAT(ParseArrayTaskIds("7"), ElementsAre(7));
  EXPECT_THAT(ParseArrayTaskIds("2-5%4"), ElementsAre(2, 3, 4, 5));
  EXPECT_THAT(ParseArrayTaskIds("1,3,5-6"), ElementsAre(1, 3, 5, 6));
  EXPECT_THAT(ParseArrayTaskIds("[4-5]"), ElementsAre(4, 5));
  EXPECT_TRUE(ParseArrayTaskIds("").empty());
  EXPECT_TRUE(ParseArrayTaskIds("N/A").empty());
  EXPECT_TRUE(ParseArrayTaskIds("5-2").empty());
  EXPECT_TRUE(ParseArrayTaskIds("x-3").empty());
}

TEST(ParseScontrolJobs, ExpandsThePendingRemainderAndReadsExitCodesAndSignals) {
  const std::string text =
      "JobId=1 ArrayJobId=1 ArrayTaskId=3-5%4 JobName=t.sh JobState=PENDING Reason=Resources ExitCode=0:0\n"
      "JobId=4 ArrayJobId=1 ArrayTaskId=2 JobName=t.sh JobState=FAILED Reason=JobLaunchFailure ExitCode=0:11\n"
      "JobId=3 ArrayJobId=1 ArrayTaskId=1 JobName=t.sh JobState=FAILED Reason=NonZeroExitCode ExitCode=3:0\n"
      "JobId=2 ArrayJobId=1 ArrayTaskId=0 JobName=t.sh JobState=COMPLETED Reason=None ExitCode=0:0\n"
      "JobId=9 JobName=not-an-array JobState=RUNNING\n";
  const std::vector<SlurmTaskState> tasks = ParseScontrolJobs(text);
  ASSERT_EQ(tasks.size(), 6u);
  std::map<int, SlurmTaskState> by_id;
  for (const SlurmTaskState& task : tasks) by_id[task.task_id] = task;
  EXPECT_EQ(by_id[4].state, "PENDING");
  EXPECT_EQ(by_id[2].state, "FAILED");
  EXPECT_EQ(by_id[2].exit_code, 0);
  EXPECT_EQ(by_id[2].signal, 11);
  EXPECT_EQ(by_id[1].exit_code, 3);
  EXPECT_EQ(by_id[1].signal, 0);
  EXPECT_EQ(by_id[0].state, "COMPLETED");
}

TEST(ParseSacct, SkipsStepsStripsDecorationAndExpandsPendingRanges) {
  const std::string text =
      "12_0|COMPLETED|0:0\n12_0.batch|COMPLETED|0:0\n12_1|CANCELLED by 0|0:15\n12_2|TIMEOUT|0:0\n"
      "12_[3-4]|PENDING|0:0\n12_5|OUT_OF_MEMORY|0:125\ngarbage line\n";
  const std::vector<SlurmTaskState> tasks = ParseSacct(text);
  ASSERT_EQ(tasks.size(), 6u);
  EXPECT_EQ(tasks[0].state, "COMPLETED");
  EXPECT_EQ(tasks[1].state, "CANCELLED");
  EXPECT_EQ(tasks[1].signal, 15);
  EXPECT_EQ(tasks[2].state, "TIMEOUT");
  EXPECT_EQ(tasks[3].task_id, 3);
  EXPECT_EQ(tasks[4].task_id, 4);
  EXPECT_EQ(tasks[4].state, "PENDING");
  EXPECT_EQ(tasks[5].state, "OUT_OF_MEMORY");
}

TEST(IsFinalState, OnlyStatesAfterWhichNothingRuns) {
  for (const char* state : {"COMPLETED", "FAILED", "TIMEOUT", "OUT_OF_MEMORY", "CANCELLED", "NODE_FAIL"}) {
    EXPECT_TRUE(IsFinalState(state)) << state;
  }
  for (const char* state : {"PENDING", "RUNNING", "COMPLETING", "CONFIGURING", "SUSPENDED", "REQUEUED", ""}) {
    EXPECT_FALSE(IsFinalState(state)) << state;
  }
}

SlurmTaskState Task(const std::string& state, int exit_code, int signal) {
  SlurmTaskState task;
  task.state = state;
  task.exit_code = exit_code;
  task.signal = signal;
  return task;
}

TEST(EndingForState, MapsSlurmStatesOntoReasons) {
  EXPECT_EQ(EndingForState(Task("TIMEOUT", 0, 0), false).reason, "Slurm TIMEOUT (--time limit)");
  EXPECT_THAT(EndingForState(Task("OUT_OF_MEMORY", 0, 125), false).reason, HasSubstr("--mem"));
  EXPECT_THAT(EndingForState(Task("NODE_FAIL", -1, 0), false).reason, HasSubstr("NODE_FAIL"));
  EXPECT_EQ(EndingForState(Task("FAILED", 2, 0), false).reason, "Slurm FAILED: worker exit code 2");
  EXPECT_EQ(EndingForState(Task("FAILED", 0, 11), false).reason, "Slurm FAILED: worker killed by SIGSEGV (signal 11)");
  EXPECT_EQ(EndingForState(Task("COMPLETED", 0, 0), false).reason, "Slurm COMPLETED: worker exit code 0");
  for (const char* state : {"TIMEOUT", "OUT_OF_MEMORY", "FAILED", "NODE_FAIL", "COMPLETED"}) {
    EXPECT_FALSE(EndingForState(Task(state, 1, 0), false).interrupted) << state;
  }
}

TEST(EndingForState, CancelledIsAnInterruptionOnlyWhenWeCancelled) {
  const SlurmTaskEnding ours = EndingForState(Task("CANCELLED", 0, 15), true);
  EXPECT_TRUE(ours.interrupted);
  EXPECT_THAT(ours.reason, HasSubstr("interrupted"));
  const SlurmTaskEnding theirs = EndingForState(Task("CANCELLED", 0, 15), false);
  EXPECT_FALSE(theirs.interrupted);
  EXPECT_THAT(theirs.reason, HasSubstr("scancel"));
  // A task that timed out before we cancelled keeps its real reason.
  EXPECT_FALSE(EndingForState(Task("TIMEOUT", 0, 0), true).interrupted);
}

}  // namespace
}  // namespace slamsweep::orchestrator
