// The five mutated MRPT rawlogs of ../shared/fuzz/rawlog-mutants, which once made `slamsweep data info`
// allocate 2.3-2.5 GB and run 12-16 s: each is rejected (exit 2) with a message naming the file and the
// object MRPT could not read, and the whole process tree stays far below the gigabytes it took before
// (a generous ceiling on peak RSS measured by wait4; the < 1 s and < 100 MB targets are measured by
// bench/hostile/rawlog_mutants.sh, not here).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tests/support/shared_data.h"

namespace slamsweep {
namespace {

struct Finished {
  int exit_code = -1;
  long peak_rss_kb = 0;
  std::string stderr_text;
};

/// Runs `argv` with stdout and stderr to files in `dir`, waits, and returns its exit code and the peak RSS
/// of it and the children it waited for.
Finished RunToEnd(const std::vector<std::string>& argv, const std::filesystem::path& dir) {
  const std::filesystem::path err = dir / "stderr.txt";
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int out_fd = ::open((dir / "stdout.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err_fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out_fd, 1);
    ::dup2(err_fd, 2);
    std::vector<char*> args;
    for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
    args.push_back(nullptr);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  Finished finished;
  int status = 0;
  rusage usage{};
  ::wait4(pid, &status, 0, &usage);
  finished.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  finished.peak_rss_kb = usage.ru_maxrss;
  std::ifstream in(err);
  finished.stderr_text.assign(std::istreambuf_iterator<char>(in), {});
  return finished;
}

class RawlogMutantsTest : public ::testing::TestWithParam<const char*> {};

TEST_P(RawlogMutantsTest, IsRejectedWithAClearMessageWithoutGigabytes) {
  const std::string relative = std::string("fuzz/rawlog-mutants/") + GetParam();
  SLAMSWEEP_REQUIRE_SHARED(mutant, relative);
  testing::TempDir dir;
  const Finished finished = RunToEnd({SLAMSWEEP_BINARY, "data", "info", mutant.string(), "--json"}, dir.path());
  EXPECT_EQ(finished.exit_code, 2) << finished.stderr_text;
  EXPECT_NE(finished.stderr_text.find(mutant.string()), std::string::npos) << finished.stderr_text;
  EXPECT_NE(finished.stderr_text.find("cannot be read"), std::string::npos) << finished.stderr_text;
  // 400 MB: a sixth of what these files took before, well above what reading them takes now.
  EXPECT_LT(finished.peak_rss_kb, 400 * 1024) << finished.stderr_text;
}

INSTANTIATE_TEST_SUITE_P(Mutants, RawlogMutantsTest,
                         ::testing::Values("mutant-2.rawlog", "mutant-10.rawlog", "mutant-19.rawlog",
                                           "mutant-33.rawlog", "mutant-36.rawlog"));

}  // namespace
}  // namespace slamsweep
