#include "orchestrator/sweep/worker_environment.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "orchestrator/sweep/local_executor.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

TEST(WorkerEnvironmentTest, HugePagesAreAskedForAndTheUsersTunablesKeptAfterThem) {
  EXPECT_EQ(WorkerGlibcTunables(nullptr), "glibc.malloc.hugetlb=1");
  EXPECT_EQ(WorkerGlibcTunables(""), "glibc.malloc.hugetlb=1");
  // glibc applies tunables left to right: the user's own hugetlb=0 comes last and wins.
  EXPECT_EQ(WorkerGlibcTunables("glibc.malloc.hugetlb=0:glibc.malloc.tcache_count=0"),
            "glibc.malloc.hugetlb=1:glibc.malloc.hugetlb=0:glibc.malloc.tcache_count=0");
}

TEST(WorkerEnvironmentTest, TheLocalExecutorStartsWorkersWithIt) {
  const testing::TempDir dir;
  // A stand-in for `slamsweep worker RUN_DIR` that records the environment it was given.
  const std::filesystem::path worker = dir / "worker.sh";
  std::ofstream(worker) << "#!/bin/sh\nprintf '%s' \"$GLIBC_TUNABLES\" > \"$2/tunables.txt\"\n";
  ::chmod(worker.c_str(), 0755);
  const std::filesystem::path run_dir = dir / "run";
  std::filesystem::create_directories(run_dir);

  LocalExecutor executor(worker);
  RunSpec run;
  run.run_id = "env-check";
  run.algorithm.timeout_s = 30;
  executor.Start(run, run_dir);
  const std::vector<WorkerEnding> endings = executor.Wait();
  ASSERT_EQ(endings.size(), 1u);
  std::ifstream recorded(run_dir / "tunables.txt");
  std::stringstream text;
  text << recorded.rdbuf();
  EXPECT_EQ(text.str(), WorkerEnvironment().front().second);
  EXPECT_NE(text.str().find("glibc.malloc.hugetlb=1"), std::string::npos);
}

}  // namespace
}  // namespace slamsweep::orchestrator
