#include "orchestrator/process/capped_log.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "tests/orchestrator/process/process_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

using ::slamsweep::testing::TempDir;
using testing::ReadAll;

// Distinct bytes at every position, so a misplaced slice cannot pass by accident.
std::string Pattern(std::size_t n) {
  std::string text;
  for (std::size_t i = 0; i < n; ++i) text.push_back(static_cast<char>('a' + (i * 7 + i / 26) % 26));
  return text;
}

TEST(CappedLogTest, ShortOutputIsWrittenVerbatim) {
  TempDir dir;
  CappedLog log(1000);
  ASSERT_EQ(log.Open(dir / "log.txt"), "");
  log.Append("hello ");
  log.Append("world\n");
  log.Finish();
  EXPECT_EQ(ReadAll(dir / "log.txt"), "hello world\n");
  EXPECT_EQ(log.bytes_written(), 12u);
  EXPECT_EQ(log.bytes_received(), 12u);
  EXPECT_FALSE(log.truncated());
}

TEST(CappedLogTest, OutputThatFitsHeadPlusTailIsNotTruncated) {
  // cap 1000: head 500, tail 1000 - 500 - 64 = 436, so 936 bytes fit exactly.
  TempDir dir;
  const std::string input = Pattern(936);
  CappedLog log(1000);
  ASSERT_EQ(log.Open(dir / "log.txt"), "");
  log.Append(input);
  log.Finish();
  EXPECT_EQ(ReadAll(dir / "log.txt"), input);
  EXPECT_FALSE(log.truncated());
}

TEST(CappedLogTest, LongOutputKeepsHeadAndTailWithMarker) {
  TempDir dir;
  const std::string input = Pattern(5000);
  // Hand-built from the contract: head = cap / 2, tail = cap - head - 64.
  const std::string expected = input.substr(0, 500) + "\n... 4064 bytes omitted ...\n" + input.substr(5000 - 436);
  for (const std::size_t chunk : {std::size_t{1}, std::size_t{7}, std::size_t{499}, std::size_t{5000}}) {
    CappedLog log(1000);
    ASSERT_EQ(log.Open(dir / "log.txt"), "");
    for (std::size_t at = 0; at < input.size(); at += chunk) log.Append(std::string_view(input).substr(at, chunk));
    log.Finish();
    const std::string written = ReadAll(dir / "log.txt");
    EXPECT_EQ(written, expected) << "chunk " << chunk;
    EXPECT_LE(written.size(), 1000u);
    EXPECT_EQ(log.bytes_written(), written.size());
    EXPECT_TRUE(log.truncated());
    EXPECT_EQ(log.bytes_omitted(), 4064u);
  }
}

TEST(CappedLogTest, ZeroCapMeansUnlimited) {
  TempDir dir;
  const std::string input = Pattern(100000);
  CappedLog log(0);
  ASSERT_EQ(log.Open(dir / "log.txt"), "");
  log.Append(input);
  log.Finish();
  EXPECT_EQ(ReadAll(dir / "log.txt"), input);
  EXPECT_FALSE(log.truncated());
}

TEST(CappedLogTest, TinyCapIsRaisedToTheMinimum) {
  TempDir dir;
  CappedLog log(10);
  ASSERT_EQ(log.Open(dir / "log.txt"), "");
  log.Append(Pattern(10000));
  log.Finish();
  EXPECT_LE(ReadAll(dir / "log.txt").size(), CappedLog::kMinCapBytes);
  EXPECT_TRUE(log.truncated());
}

TEST(CappedLogTest, EmptyPathCountsButDiscards) {
  CappedLog log(1000);
  ASSERT_EQ(log.Open({}), "");
  log.Append(Pattern(3000));
  log.Finish();
  EXPECT_EQ(log.bytes_received(), 3000u);
  EXPECT_EQ(log.bytes_written(), 0u);
}

TEST(CappedLogTest, UnwritablePathIsReportedWithThePath) {
  CappedLog log(1000);
  const std::string error = log.Open("/nonexistent-dir/log.txt");
  EXPECT_NE(error.find("/nonexistent-dir/log.txt"), std::string::npos) << error;
}

// A finished file cut afterwards holds exactly what CappedLog writes of the same output as it arrives.
TEST(CapLogFileTest, AFileOverTheCapBecomesWhatCappedLogWouldHaveWritten) {
  TempDir dir;
  const std::string input = Pattern(100000);
  CappedLog streamed(1000);
  ASSERT_EQ(streamed.Open(dir / "streamed.txt"), "");
  streamed.Append(input);
  streamed.Finish();
  {
    std::ofstream out(dir / "worker.log", std::ios::binary);
    out << input;
  }
  EXPECT_TRUE(CapLogFile(dir / "worker.log", 1000));
  EXPECT_EQ(ReadAll(dir / "worker.log"), ReadAll(dir / "streamed.txt"));
  EXPECT_LE(ReadAll(dir / "worker.log").size(), 1000u);
  EXPECT_FALSE(std::filesystem::exists(dir / "worker.log.capping"));
}

TEST(CapLogFileTest, AFileWithinTheCapOrWithoutACapIsLeftAlone) {
  TempDir dir;
  for (const auto& [size, cap] : {std::pair<std::size_t, std::uint64_t>{1000, 1000}, {5000, 0}}) {
    {
      std::ofstream out(dir / "worker.log", std::ios::binary | std::ios::trunc);
      out << Pattern(size);
    }
    EXPECT_FALSE(CapLogFile(dir / "worker.log", cap)) << size;
    EXPECT_EQ(ReadAll(dir / "worker.log"), Pattern(size)) << size;
  }
  EXPECT_FALSE(CapLogFile(dir / "missing.log", 1000));
}

}  // namespace
}  // namespace slamsweep::orchestrator
