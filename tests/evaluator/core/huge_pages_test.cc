// Transparent huge pages for large trajectories: the kernel records the advice as the "hg" flag of the
// mapping (/proc/self/smaps, VmFlags), whether or not it then finds huge pages to give.
#include "evaluator/core/huge_pages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator {
namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;

// The VmFlags line of the mapping that holds `address`, or "" when none does.
std::string VmFlagsAt(std::uintptr_t address) {
  std::ifstream smaps("/proc/self/smaps");
  EXPECT_TRUE(smaps) << "/proc/self/smaps cannot be read: the test needs Linux's /proc";
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t begin = 0;
    std::uintptr_t end = 0;
    char dash = 0;
    std::istringstream header(line);
    if (header >> std::hex >> begin >> dash >> end && dash == '-') {
      inside = begin <= address && address < end;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return line + " ";
    }
  }
  return "";
}

std::uintptr_t FirstHugePageBoundary(const void* data) {
  return (reinterpret_cast<std::uintptr_t>(data) + kHugePage - 1) & ~(kHugePage - 1);
}

TEST(HugePagesTest, AReservedLongTrajectoryIsAdvised) {
  Trajectory trajectory;
  trajectory.Reserve(100'000);  // 6.4 MB of poses, 0.8 MB of stamps
  const std::string flags = VmFlagsAt(FirstHugePageBoundary(trajectory.poses().data()));
  EXPECT_NE(flags.find(" hg "), std::string::npos) << flags;
}

TEST(HugePagesTest, TheContentsStayAsWritten) {
  Trajectory trajectory;
  trajectory.Reserve(100'000);
  for (int i = 0; i < 100'000; ++i) trajectory.Add(0.1 * i, Pose::Planar(i, -i, 0.001 * i));
  ASSERT_EQ(trajectory.size(), 100'000u);
  EXPECT_EQ(trajectory.stamps_s()[77'777], 0.1 * 77'777);
  EXPECT_EQ(trajectory.poses()[77'777].position.x(), 77'777.0);
  EXPECT_EQ(trajectory.poses()[99'999].position.y(), -99'999.0);
}

TEST(HugePagesTest, SmallAndEmptyRangesAreLeftAlone) {
  AdviseHugePages(nullptr, 1 << 30);  // no memory: nothing to advise, and no crash
  std::vector<double> small(1000, 1.5);
  AdviseHugePages(small);
  EXPECT_EQ(small[999], 1.5);
}

}  // namespace
}  // namespace slamsweep::evaluator
