#include "orchestrator/process/group_memory.h"

#include <unistd.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace slamsweep::orchestrator {
namespace {

// A /proc/PID/stat line (proc(5)): pid, (comm), then fields 3..52; ppid is field 4, pgrp field 5,
// num_threads field 20, rss field 24.
std::string StatLine(const std::string& comm, const std::string& pgrp, int rss_pages) {
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on literal + std::string chains.
  std::string line = "4321 (";
  line.append(comm).append(") S 1 ").append(pgrp);
  for (int field = 6; field <= 52; ++field) {
    line.append(" ").append(std::to_string(field == 24 ? rss_pages : field == 20 ? 3 : field * 10));
  }
  line.append("\n");
  return line;
}

TEST(ParseProcStatTest, ReadsGroupAndRss) {
  const auto stat = ParseProcStat(StatLine("icp-slam", "77", 1500));
  ASSERT_TRUE(stat.has_value());
  EXPECT_EQ(stat->pid, 4321);
  EXPECT_EQ(stat->parent, 1);
  EXPECT_EQ(stat->process_group, 77);
  EXPECT_EQ(stat->threads, 3);
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

TEST(GroupUsageTest, OwnGroupUsesMemoryAndUnknownGroupNone) {
  const pid_t own = ::getpgrp();
  const auto usage = GroupUsageOf({own, 999999999});
  ASSERT_EQ(usage.size(), 2u);
  EXPECT_GT(usage.at(own).rss_kb, 1000);  // this test binary alone holds more than 1 MB
  EXPECT_GE(usage.at(own).tasks, 1);
  EXPECT_EQ(usage.at(999999999).rss_kb, 0);
  EXPECT_EQ(usage.at(999999999).tasks, 0);
}

ProcStat Process(pid_t pid, pid_t parent, pid_t group, std::int64_t threads, std::int64_t rss_pages) {
  return ProcStat{pid, parent, group, threads, rss_pages};
}

TEST(GroupUsageTest, DescendantsThatLeftTheGroupStillCountForTheirLeader) {
  // 100 leads group 100; 101 is its child in the group; 102 left with setsid, 103 is 102's child
  // (a sandbox's process 1 and its program); 200 leads another group; 300 belongs to neither.
  const std::vector<ProcStat> processes = {Process(100, 1, 100, 1, 10),   Process(101, 100, 100, 2, 20),
                                           Process(102, 100, 102, 1, 30), Process(103, 102, 102, 4, 40),
                                           Process(200, 1, 200, 1, 50),   Process(201, 200, 200, 1, 60),
                                           Process(300, 1, 300, 9, 70)};
  const auto usage = GroupUsageOf({100, 200}, processes, 4);
  EXPECT_EQ(usage.at(100).rss_kb, (10 + 20 + 30 + 40) * 4);
  EXPECT_EQ(usage.at(100).tasks, 1 + 2 + 1 + 4);
  EXPECT_EQ(usage.at(200).rss_kb, (50 + 60) * 4);
  EXPECT_EQ(usage.at(200).tasks, 2);
}

}  // namespace
}  // namespace slamsweep::orchestrator
