#include "orchestrator/process/run_to_exit.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "tests/orchestrator/process/process_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

using ::slamsweep::testing::TempDir;
using ::slamsweep::testing::WriteFile;
using testing::ReadAll;

/// An open file descriptor, closed at the end of the test.
class OpenFile {
 public:
  OpenFile(const std::filesystem::path& path, int flags) : fd_(::open(path.c_str(), flags | O_CLOEXEC, 0600)) {}
  ~OpenFile() {
    if (fd_ >= 0) ::close(fd_);
  }
  OpenFile(const OpenFile&) = delete;
  OpenFile& operator=(const OpenFile&) = delete;
  int fd() const { return fd_; }

 private:
  int fd_;
};

TEST(RunToExitTest, FeedsStdinAndCapturesStderrWhileStdoutIsDiscarded) {
  TempDir dir;
  const OpenFile input(WriteFile(dir / "input.txt", "first line\nsecond line\n"), O_RDONLY);
  const OpenFile errors(dir / "stderr.txt", O_WRONLY | O_CREAT | O_TRUNC);
  ASSERT_GE(input.fd(), 0);
  ASSERT_GE(errors.fd(), 0);
  ChildStreams streams;
  streams.stdin_fd = input.fd();
  streams.stderr_fd = errors.fd();
  streams.discard_stdout = true;
  const ExitStatus exit = RunToExit(
      {"/bin/sh", "-c", "echo to-stdout; while read -r line; do echo \"got $line\" >&2; done; exit 3"}, streams);
  EXPECT_EQ(exit.start_error, "");
  EXPECT_EQ(exit.exit_code, 3);
  EXPECT_EQ(ReadAll(dir / "stderr.txt"), "got first line\ngot second line\n");
}

TEST(RunToExitTest, SignalIsReportedAs128PlusItsNumber) {
  TempDir dir;
  const OpenFile errors(dir / "stderr.txt", O_WRONLY | O_CREAT | O_TRUNC);
  ChildStreams streams;
  streams.stderr_fd = errors.fd();
  streams.discard_stdout = true;
  EXPECT_EQ(RunToExit({"/bin/sh", "-c", "kill -TERM $$"}, streams).exit_code, 128 + SIGTERM);
}

TEST(RunToExitTest, MissingProgramIsAStartErrorNotAnException) {
  TempDir dir;
  const OpenFile errors(dir / "stderr.txt", O_WRONLY | O_CREAT | O_TRUNC);
  ChildStreams streams;
  streams.stderr_fd = errors.fd();
  streams.discard_stdout = true;
  const ExitStatus exit = RunToExit({"/nonexistent/program", "-d"}, streams);
  EXPECT_EQ(exit.start_error, "No such file or directory");
}

TEST(RunToExitTest, OutputLeftInThePipeIsRefused) {
  EXPECT_THROW(RunToExit({"/bin/true"}, ChildStreams{}), std::invalid_argument);
}

}  // namespace
}  // namespace slamsweep::orchestrator
