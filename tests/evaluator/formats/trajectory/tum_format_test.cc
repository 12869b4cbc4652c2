#include "evaluator/formats/trajectory/tum_format.h"

#include <array>
#include <charconv>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <sstream>

#include "tests/evaluator/formats/trajectory/trajectory_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using testing_util::ExpectInputError;

TEST(TumFormatTest, RoundTripKeepsStampsAndPoses) {
  for (bool planar : {true, false}) {
    const Trajectory original = testing_util::RandomTrajectory(200, planar, planar ? 1 : 2);
    testing::TempDir dir;
    WriteTum(original, dir / "t.tum");
    testing_util::ExpectSameTrajectory(original, ReadTum(dir / "t.tum"));
  }
}

TEST(TumFormatTest, ReadsAHandWrittenLine) {
  const Trajectory t = ParseTum("# comment\n1.5 1 2 3 0 0 0.7071067811865476 0.7071067811865476\n", "mem.tum");
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t.stamps_s()[0], 1.5);
  EXPECT_TRUE(testing_util::SamePose(Pose{{1, 2, 3}, Eigen::Quaterniond(0.7071067811865476, 0, 0, 0.7071067811865476)},
                                     t.poses()[0], 1e-12));
}

TEST(TumFormatTest, ReadsEveryNumberExactlyWhateverTheSpacing) {
  // Shortest round-trip decimal text of random doubles (std::to_chars), separated by any mix of
  // spaces, tabs and CRs: reading gives back exactly those doubles.
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> value(-1e4, 1e4);
  const std::array<std::string, 4> separators = {" ", "\t", "  \t ", " \r "};
  std::string text = "# timestamp tx ty tz qx qy qz qw\r\n";
  std::vector<std::array<double, 8>> expected;
  for (int line = 0; line < 200; ++line) {
    std::array<double, 8> fields{};
    for (double& field : fields) field = value(random);
    fields[0] = std::abs(fields[0]) * (line % 2 == 0 ? 1e-3 : 1e5);  // plain and exponent notation
    expected.push_back(fields);
    text += line % 3 == 0 ? "  " : "";
    for (std::size_t i = 0; i < fields.size(); ++i) {
      std::array<char, 32> buffer{};
      const auto end = std::to_chars(buffer.data(), buffer.data() + buffer.size(), fields[i]).ptr;
      if (i > 0) text += separators[(static_cast<std::size_t>(line) + i) % separators.size()];
      text.append(buffer.data(), end);
    }
    text += line % 4 == 0 ? "\r\n" : "\n";
  }
  const Trajectory t = ParseTum(text, "mem.tum");
  ASSERT_EQ(t.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const std::array<double, 8>& f = expected[k];
    EXPECT_EQ(t.stamps_s()[k], f[0]);
    EXPECT_EQ(t.poses()[k].position, Eigen::Vector3d(f[1], f[2], f[3]));
    EXPECT_EQ(t.poses()[k].orientation.coeffs(), Eigen::Quaterniond(f[7], f[4], f[5], f[6]).normalized().coeffs());
  }
}

TEST(TumFormatTest, LinesTheQuickReaderRefusesGetTheFieldByFieldMessage) {
  ExpectInputError([] { ParseTum("0 1 2 3 0 0 0 1 9\n", "t.tum"); }, {"t.tum:1", "expected 8 fields", "got 9"});
  ExpectInputError([] { ParseTum("0 1 2 3 0 0 0 0\n", "t.tum"); }, {"t.tum:1", "zero norm"});
  ExpectInputError([] { ParseTum("0 1 2 3 0 0 0 1x\n", "t.tum"); }, {"t.tum:1", "qw", "1x"});
  ExpectInputError([] { ParseTum("0 1 2 1e999 0 0 0 1\n", "t.tum"); }, {"t.tum:1", "tz"});
  ExpectInputError([] { ParseTum("0 1 2 3 0 0 0 1\ninf 1 2 3 0 0 0 1\n", "t.tum"); }, {"t.tum:2", "timestamp"});
}

TEST(TumFormatTest, BadInputNamesFileAndLine) {
  ExpectInputError([] { ParseTum("0 1 2 3 0 0 0 1\n1 1 2 3 0 0\n", "t.tum"); }, {"t.tum:2", "expected 8 fields"});
  ExpectInputError([] { ParseTum("0 1 2 abc 0 0 0 1\n", "t.tum"); }, {"t.tum:1", "tz", "abc"});
  ExpectInputError([] { ParseTum("0 1 nan 3 0 0 0 1\n", "t.tum"); }, {"t.tum:1", "ty"});
  ExpectInputError([] { ParseTum("", "t.tum"); }, {"t.tum", "no poses"});
}

}  // namespace
}  // namespace slamsweep::evaluator
