#include "orchestrator/matrix/run_id.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "orchestrator/matrix/expand_matrix.h"
#include "tests/orchestrator/matrix/test_config.h"
#include "orchestrator/run/run_json.h"

namespace slamsweep::orchestrator {
namespace {

TEST(RunIdTest, Fnv1aMatchesThePublishedTestVectors) {
  // Test vectors of the FNV reference (Fowler, Noll, Vo), 64-bit FNV-1a.
  EXPECT_EQ(Fnv1a64(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(Fnv1a64("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(Fnv1a64("foobar"), 0x85944171f73967e8ULL);
}

TEST(RunIdTest, SanitizesHostileNames) {
  EXPECT_EQ(SanitizeIdPart("icp-slam_2.0"), "icp-slam_2.0");
  EXPECT_EQ(SanitizeIdPart("../../x"), "_.._x");
  EXPECT_EQ(SanitizeIdPart("<script>"), "_script_");
  EXPECT_EQ(SanitizeIdPart("..."), "_");
  EXPECT_EQ(SanitizeIdPart(""), "_");
  EXPECT_EQ(SanitizeIdPart("a b/c\\d"), "a_b_c_d");
  EXPECT_EQ(SanitizeIdPart(std::string(40, 'z')), std::string(32, 'z'));
  EXPECT_EQ(SanitizeIdPart("\xc3\xa9t\xc3\xa9"), "__t__");  // "été": each UTF-8 byte becomes '_'
}

RunSpec Spec(const std::string& algorithm, const std::string& sequence, const std::string& noise) {
  RunSpec spec;
  spec.algorithm.name = algorithm;
  spec.algorithm.adapter = "odometry";
  spec.sequence = testing::Sequence(sequence);
  spec.noise = testing::Noise(noise, 0.0);
  spec.iteration = 3;
  spec.seed = 7;
  return spec;
}

TEST(RunIdTest, HasTheDesignedShape) {
  const std::string id = MakeRunId(Spec("icp-slam", "mrpt-telecom", "clean"));
  EXPECT_TRUE(std::regex_match(id, std::regex("icp-slam-mrpt-telecom-clean-i3-[0-9a-f]{8}"))) << id;
}

TEST(RunIdTest, HostileNamesGiveSafeFolderNames) {
  const std::regex safe("[A-Za-z0-9_.-]+");
  for (const std::string name : {"../../x", "<script>alert(1)</script>", ".hidden", "/etc/passwd", "a\nb", ".."}) {
    const std::string id = MakeRunId(Spec(name, name, name));
    SCOPED_TRACE(id);
    EXPECT_EQ(id.find('/'), std::string::npos);
    EXPECT_NE(id.front(), '.');
    EXPECT_TRUE(std::regex_match(id, safe));
  }
}

TEST(RunIdTest, IsStableAndChangesWithEveryInput) {
  const RunSpec base = Spec("icp", "seq", "clean");
  EXPECT_EQ(MakeRunId(base), MakeRunId(base));
  std::set<std::string> ids = {MakeRunId(base)};
  RunSpec changed = base;
  changed.seed = 8;
  ids.insert(MakeRunId(changed));
  changed = base;
  changed.algorithm.parameters = {{"p", 1}};
  ids.insert(MakeRunId(changed));
  changed = base;
  changed.sequence.max_scans = 10;
  ids.insert(MakeRunId(changed));
  changed = base;
  changed.noise.odometry = evaluator::OdometryNoise{0.1, 0, 0, 0, 0, 0};
  ids.insert(MakeRunId(changed));
  changed = base;
  changed.algorithm.adapter = "mrpt-icp-slam";
  ids.insert(MakeRunId(changed));
  EXPECT_EQ(ids.size(), 6u);
  // Not part of the identity: the timeout and the scoring options.
  changed = base;
  changed.algorithm.timeout_s = 5;
  changed.evaluation.rpe_delta_m = 3;
  EXPECT_EQ(MakeRunId(changed), MakeRunId(base));
}

TEST(RunIdTest, AChangedAdaptersRevisionIsPartOfTheIdentityUnchangedAdaptersKeepTheirs) {
  RunSpec icp = Spec("icp", "seq", "clean");
  icp.algorithm.adapter = "mrpt-icp-slam";
  EXPECT_EQ(AdapterRevision("mrpt-icp-slam"), 2);
  EXPECT_EQ(RunIdentity(icp)["algorithm"]["adapter_revision"], 2);
  EXPECT_EQ(AdapterRevision("odometry"), 2);
  EXPECT_EQ(AdapterRevision("mrpt-rbpf-slam"), 2);  // seeded through RANDOM_SEED since revision 2
  // Revision 1 adds nothing: the ids of earlier sweeps of these adapters stay valid.
  for (const char* adapter : {"command"}) {
    RunSpec other = Spec("x", "seq", "clean");
    other.algorithm.adapter = adapter;
    EXPECT_EQ(AdapterRevision(adapter), 1) << adapter;
    EXPECT_FALSE(RunIdentity(other)["algorithm"].contains("adapter_revision")) << adapter;
  }
}

TEST(RunIdTest, NamesThatSanitizeAlikeStayDistinct) {
  SweepConfig config = testing::TwoByTwo();
  config.algorithms = {testing::Algorithm("a/b", "odometry"), testing::Algorithm("a<b", "odometry"),
                       testing::Algorithm("a_b", "odometry")};
  const std::vector<RunSpec> runs = ExpandMatrix(config);
  std::set<std::string> ids;
  for (const RunSpec& run : runs) {
    EXPECT_TRUE(run.run_id.starts_with("a_b-")) << run.run_id;
    ids.insert(run.run_id);
  }
  EXPECT_EQ(ids.size(), runs.size());
  EXPECT_EQ(runs.size(), 3u * 2 * 2 * 2);
}

}  // namespace
}  // namespace slamsweep::orchestrator
