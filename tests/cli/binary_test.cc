// The real executable, as Jenkins calls it: exit codes and stdout/stderr separation.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace slamsweep {
namespace {

struct ProcessResult {
  int exit_code = -1;
  std::string out;
};

ProcessResult RunBinary(const std::string& args) {
  const std::string command = std::string(SLAMSWEEP_BINARY) + " " + args + " 2>/dev/null";
  ProcessResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) result.out += buffer.data();
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

TEST(BinaryTest, HelpExitsZeroAndListsCommands) {
  const ProcessResult result = RunBinary("--help");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_THAT(result.out, ::testing::HasSubstr("eval"));
  EXPECT_THAT(result.out, ::testing::HasSubstr("vectorize"));
}

TEST(BinaryTest, UsageErrorsExitTwoWithNothingOnStdout) {
  const ProcessResult unknown = RunBinary("frobnicate");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_EQ(unknown.out, "");
  EXPECT_EQ(RunBinary("").exit_code, 2);
  EXPECT_EQ(RunBinary("eval map /nonexistent/map.yaml").exit_code, 2);
}

}  // namespace
}  // namespace slamsweep
