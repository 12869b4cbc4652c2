#include "evaluator/formats/trajectory/relations_format.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <random>

#include "evaluator/core/text_file.h"
#include "tests/evaluator/formats/trajectory/trajectory_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using testing_util::ExpectInputError;

/// Relation lines counted without the parser: newlines, minus comment and blank lines.
std::size_t CountDataLines(const std::string& content) {
  std::size_t count = static_cast<std::size_t>(std::count(content.begin(), content.end(), '\n'));
  if (!content.empty() && content.back() != '\n') ++count;  // a last line without newline
  std::size_t start = 0;
  while (start < content.size()) {
    std::size_t end = content.find('\n', start);
    if (end == std::string::npos) end = content.size();
    const std::string line = content.substr(start, end - start);
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t\r")] == '#') {
      --count;
    }
    start = end + 1;
  }
  return count;
}

TEST(RelationsFormatTest, ReadsAPlanarRelation) {
  const Relations relations =
      ParseRelations("1216.630413 1217.490267 0.407950 -0.016330 0.000000 0.000000 0.000000 -0.069620\n", "r");
  ASSERT_EQ(relations.size(), 1u);
  EXPECT_EQ(relations[0].t1_s, 1216.630413);
  EXPECT_EQ(relations[0].t2_s, 1217.490267);
  EXPECT_TRUE(testing_util::SamePose(Pose::Planar(0.40795, -0.01633, -0.06962), relations[0].delta, 1e-15));
}

TEST(RelationsFormatTest, AnglesAreRollPitchYawAboutFixedAxes) {
  // roll = pitch = yaw = 90 deg: R = Rz Ry Rx sends x -> (Rx) x -> (Ry) -z -> (Rz) -z.
  const double q = std::numbers::pi / 2;
  const Relations relations =
      ParseRelations("0 1 0 0 0 " + std::to_string(q) + " " + std::to_string(q) + " " + std::to_string(q) + "\n", "r");
  EXPECT_TRUE((relations[0].delta.orientation * Eigen::Vector3d::UnitX()).isApprox(-Eigen::Vector3d::UnitZ(), 1e-6));
  // y -> (Rx) z -> (Ry) x -> (Rz) y.
  EXPECT_TRUE((relations[0].delta.orientation * Eigen::Vector3d::UnitY()).isApprox(Eigen::Vector3d::UnitY(), 1e-6));
}

TEST(RelationsFormatTest, RoundTripKeepsStampsAndDeltas) {
  std::mt19937 random(31);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  Relations original;
  for (int i = 0; i < 300; ++i) {
    Relation relation;
    relation.t1_s = 976052896.784509 + i;
    relation.t2_s = relation.t1_s + 0.5 + 0.001 * i;
    relation.delta.position = {gaussian(random), gaussian(random), gaussian(random)};
    relation.delta.orientation =
        Eigen::Quaterniond(gaussian(random), gaussian(random), gaussian(random), gaussian(random)).normalized();
    original.push_back(relation);
  }
  testing::TempDir dir;
  WriteRelations(original, dir / "r.relations");
  const Relations read = ReadRelations(dir / "r.relations");
  ASSERT_EQ(read.size(), original.size());
  for (std::size_t i = 0; i < read.size(); ++i) {
    EXPECT_EQ(read[i].t1_s, original[i].t1_s);
    EXPECT_EQ(read[i].t2_s, original[i].t2_s);
    EXPECT_TRUE(testing_util::SamePose(original[i].delta, read[i].delta, 1e-12)) << i;
  }
}

TEST(RelationsFormatTest, SharedRelationFilesReadWithTheirLineCounts) {
  for (const char* relative : {"datasets/intel/intel.relations", "datasets/fr079/fr079.relations",
                               "datasets/mit-killian/mit-killian.relations"}) {
    SLAMSWEEP_REQUIRE_SHARED(path, relative);
    const std::string content = ReadTextFile(path);
    const Relations relations = ReadRelations(path);
    EXPECT_EQ(relations.size(), CountDataLines(content)) << relative;
    EXPECT_GT(relations.size(), 1000u) << relative;
  }
}

TEST(RelationsFormatTest, BadInputNamesFileAndLine) {
  ExpectInputError([] { ParseRelations("1 2 0.1 0.2 0 0 0 0.3\n1 2 0.1 0.2 0 0\n", "r.rel"); },
                   {"r.rel:2", "8 fields", "got 6"});
  ExpectInputError([] { ParseRelations("1 2 0.1 0.2 0 0 0 yaw\n", "r.rel"); }, {"r.rel:1", "(yaw)", "'yaw'"});
  ExpectInputError([] { ParseRelations("1 nan 0.1 0.2 0 0 0 0.3\n", "r.rel"); }, {"r.rel:1", "t2"});
  ExpectInputError([] { ParseRelations("# nothing\n\n", "r.rel"); }, {"r.rel", "no relations"});
}

}  // namespace
}  // namespace slamsweep::evaluator
