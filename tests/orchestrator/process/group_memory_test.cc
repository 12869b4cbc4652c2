#include "orchestrator/process/group_memory.h"

#include <unistd.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace slamsweep::orchestrator {
namespace {

// A /proc/PID/stat line (proc(5)): pid, (comm), then fields 3..52; pgrp is field 5, rss field 24.
std::string StatLine(const std::string& comm, const std::string& pgrp, int rss_pages) {
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on literal + std::string chains.
  std::string line = "4321 (";
  line.append(comm).append(") S 1 ").append(pgrp);
  for (int field = 6; field <= 52; ++field) {
    line.append(" ").append(std::to_string(field == 24 ? rss_pages : field * 10));
  }
  line.append("\n");
  return line;
}

TEST(ParseProcStatTest, ReadsGroupAndRss) {
  const auto stat = ParseProcStat(StatLine("icp-slam", "77", 1500));
  ASSERT_TRUE(stat.has_value());
  EXPECT_EQ(stat->pid, 4321);
  EXPECT_EQ(stat->process_group, 77);
  EXPECT_EQ(stat->rss_pages, 1500);
}

TEST(ParseProcStatTest, CommandNamesWithSpacesAndParenthesesDoNotShiftFields) {
  const auto stat = ParseProcStat(StatLine("a) b (c) 9 9", "12", 34));
  ASSERT_TRUE(stat.has_value());
  EXPECT_EQ(stat->process_group, 12);
  EXPECT_EQ(stat->rss_pages, 34);
}

TEST(ParseProcStatTest, RejectsMalformedContent) {
  EXPECT_FALSE(ParseProcStat("").has_value());
  EXPECT_FALSE(ParseProcStat("garbage").has_value());
  EXPECT_FALSE(ParseProcStat("12 (x) S 1 2 3").has_value());  // too short for rss
  EXPECT_FALSE(ParseProcStat("x12 (x) S 1 2").has_value());
  EXPECT_FALSE(ParseProcStat(StatLine("x", "five", 6)).has_value());
}

TEST(GroupRssKbTest, OwnGroupUsesMemoryAndUnknownGroupNone) {
  const pid_t own = ::getpgrp();
  const auto rss = GroupRssKb({own, 999999999});
  ASSERT_EQ(rss.size(), 2u);
  EXPECT_GT(rss.at(own), 1000);  // this test binary alone holds more than 1 MB
  EXPECT_EQ(rss.at(999999999), 0);
}

}  // namespace
}  // namespace slamsweep::orchestrator
