// The sbatch request and the batch script. The script is run for real with /bin/sh and a fake
// worker that records its arguments, so the test checks behaviour, not text.

#include "orchestrator/slurm/array_job.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>

#include "orchestrator/slurm/slurm_command.h"
#include "orchestrator/sweep/worker_environment.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

namespace fs = std::filesystem;
using ::testing::Contains;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

std::string ReadText(const fs::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(TimeLimitMinutes, RoundsUpToWholeMinutesAndNeverBelowOne) {
  EXPECT_EQ(TimeLimitMinutes(300, 600), 15);  // 900 s
  EXPECT_EQ(TimeLimitMinutes(301, 600), 16);  // 901 s -> 15.02 min -> 16
  EXPECT_EQ(TimeLimitMinutes(1, 0), 1);
  EXPECT_EQ(TimeLimitMinutes(0, 0), 1);
  EXPECT_EQ(TimeLimitMinutes(-5, 0), 1);
}

TEST(TaskMemoryMb, AddsTheWorkerOverheadOnlyWhenThereIsALimit) {
  EXPECT_EQ(TaskMemoryMb(4096, 1024), 5120u);
  EXPECT_EQ(TaskMemoryMb(0, 1024), 0u);
}

ArrayJobRequest Request() {
  ArrayJobRequest request;
  request.job_name = "slamsweep";
  request.task_count = 18;
  request.time_limit_min = 15;
  request.script_path = "/out/slurm/array-1-0.sh";
  request.slurm_output_pattern = "/out/slurm/array-1-0-%a.out";
  return request;
}

TEST(SbatchArgv, OneArrayWithTimeAndOutputAndTheScriptLast) {
  const std::vector<std::string> argv = SbatchArgv(Request());
  EXPECT_EQ(argv.front(), "sbatch");
  EXPECT_THAT(argv, Contains("--parsable"));
  EXPECT_THAT(argv, Contains("--array=0-17"));
  EXPECT_THAT(argv, Contains("--time=15"));
  EXPECT_THAT(argv, Contains("--output=/out/slurm/array-1-0-%a.out"));
  EXPECT_EQ(argv.back(), "/out/slurm/array-1-0.sh");
  for (const std::string& arg : argv) {
    EXPECT_THAT(arg, ::testing::Not(HasSubstr("--mem"))) << "no memory limit -> no --mem";
    EXPECT_THAT(arg, ::testing::Not(HasSubstr("--partition")));
  }
}

TEST(SbatchArgv, ThrottleMemoryPartitionAndExtraArgumentsBeforeTheScript) {
  ArrayJobRequest request = Request();
  request.max_parallel = 4;
  request.memory_mb = 5120;
  request.partition = "gpu";
  request.extra_args = {"--account=slam", "--qos=low"};
  const std::vector<std::string> argv = SbatchArgv(request);
  EXPECT_THAT(argv, Contains("--array=0-17%4"));
  EXPECT_THAT(argv, Contains("--mem=5120M"));
  EXPECT_THAT(argv, Contains("--partition=gpu"));
  ASSERT_GE(argv.size(), 3u);
  EXPECT_THAT(std::vector<std::string>(argv.end() - 3, argv.end()),
              ElementsAre("--account=slam", "--qos=low", "/out/slurm/array-1-0.sh"));
}

TEST(ShellQuote, SurvivesQuotesAndSpacesThroughARealShell) {
  const std::string nasty = "it's a \"path\" with $HOME and `x`";
  const CommandOutput echoed = RunSlurmCommand({"/bin/sh", "-c", "printf %s " + ShellQuote(nasty)});
  ASSERT_TRUE(echoed.ok()) << echoed.output;
  EXPECT_EQ(echoed.output, nasty);
}

TEST(ParseSbatchJobId, ReadsPlainAndClusterFormsAfterWarnings) {
  EXPECT_EQ(ParseSbatchJobId("42\n"), 42);
  EXPECT_EQ(ParseSbatchJobId("42;cluster\n"), 42);
  EXPECT_EQ(ParseSbatchJobId("sbatch: warning: something\n77\n"), 77);
  EXPECT_EQ(ParseSbatchJobId("sbatch: error: Batch job submission failed\n"), -1);
  EXPECT_EQ(ParseSbatchJobId(""), -1);
}

class BatchScriptTest : public ::testing::Test {
 protected:
  void SetUp() override {
    worker_ = dir_ / "fake worker";  // a space in the path: quoting must hold
    std::ofstream(worker_) << "#!/bin/sh\necho \"args: $1 | $2\"\nexit 5\n";
    ::chmod(worker_.c_str(), 0755);
    fs::create_directories(dir_ / "runs" / "a");
    fs::create_directories(dir_ / "runs" / "b c");
    manifest_ = dir_ / "manifest.runs";
    std::ofstream(manifest_) << (dir_ / "runs" / "a").string() << "\n" << (dir_ / "runs" / "b c").string() << "\n";
    script_ = dir_ / "array.sh";
    std::ofstream(script_) << BatchScript(worker_, manifest_);
    ::chmod(script_.c_str(), 0755);
  }

  CommandOutput RunTask(int task_id) {
    return RunSlurmCommand({"/usr/bin/env", "SLURM_ARRAY_TASK_ID=" + std::to_string(task_id), script_.string()});
  }

  slamsweep::testing::TempDir dir_;
  fs::path worker_, manifest_, script_;
};

TEST_F(BatchScriptTest, TaskNExecsTheWorkerOnLineNPlusOneWithItsOutputInWorkerLog) {
  const CommandOutput second = RunTask(1);
  EXPECT_EQ(second.exit_code, 5) << "the worker's exit code is the task's: " << second.output;
  EXPECT_EQ(ReadText(dir_ / "runs" / "b c" / "worker.log"),
            "args: worker | " + (dir_ / "runs" / "b c").string() + "\n");
  EXPECT_FALSE(fs::exists(dir_ / "runs" / "a" / "worker.log"));
  EXPECT_EQ(RunTask(0).exit_code, 5);
  EXPECT_TRUE(fs::exists(dir_ / "runs" / "a" / "worker.log"));
}

TEST_F(BatchScriptTest, ATaskWithoutARunFolderExitsTwoAndSaysWhy) {
  const CommandOutput missing = RunTask(2);
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_THAT(missing.output, HasSubstr("no run folder for array task 2"));
}

TEST_F(BatchScriptTest, TheWorkerGetsTheWorkerEnvironment) {
  std::ofstream(worker_) << "#!/bin/sh\nprintf '%s' \"$GLIBC_TUNABLES\"\n";
  ASSERT_EQ(RunTask(0).exit_code, 0);
  EXPECT_EQ(ReadText(dir_ / "runs" / "a" / "worker.log"), WorkerEnvironment().front().second);
}

TEST(RunSlurmCommand, AMissingProgramIsAnExitCodeNotAnException) {
  const CommandOutput missing = RunSlurmCommand({"/nonexistent/sbatch", "--parsable"});
  EXPECT_FALSE(missing.ok());
  EXPECT_THAT(missing.output, HasSubstr("/nonexistent/sbatch"));
}

TEST(RunSlurmCommand, AHangingCommandIsKilledAfterItsTimeout) {
  const CommandOutput hung = RunSlurmCommand({"/bin/sleep", "30"}, 0.5);
  EXPECT_EQ(hung.exit_code, -1);
  EXPECT_THAT(hung.output, HasSubstr("killed after"));
}

}  // namespace
}  // namespace slamsweep::orchestrator
