#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/formats/map/map_server_format.h"
#include "tests/cli/run_cli.h"
#include "tests/support/shared_data.h"

namespace slamsweep {
namespace {

using ::testing::HasSubstr;
using testing::RunCli;

/// `slamsweep eval map` of the reference rbpf map against one of the independent implementation's files.
void ExpectRbpfValues(const std::string& reference_json, const std::vector<std::string>& extra_args) {
  SLAMSWEEP_REQUIRE_SHARED(expected_path, "reference/maps/" + reference_json);
  std::ifstream in(expected_path);
  const nlohmann::json all = nlohmann::json::parse(in);
  nlohmann::json expected;
  for (const auto& entry : all.at("maps")) {
    if (entry.at("map") == "telecom_rbpf.pgm") expected = entry;
  }
  ASSERT_FALSE(expected.is_null());
  std::vector<std::string> args = {
      "eval", "map", (expected_path.parent_path() / "telecom_rbpf.pgm").string(), "--unknown-value", "205", "--json"};
  args.insert(args.end(), extra_args.begin(), extra_args.end());
  const auto run = RunCli(args);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json result = nlohmann::json::parse(run.out);
  for (const char* key : {"occupied_to_free_unknown", "occupied_to_all", "unknown_to_all"}) {
    EXPECT_NEAR(result.at(key).get<double>(), expected.at(key).get<double>(), 1e-9) << key;
  }
  EXPECT_EQ(result.at("corners"), expected.at("corners"));
  EXPECT_EQ(result.at("enclosed_areas"), expected.at("enclosed_areas"));
  EXPECT_EQ(result.at("cropped_width"), expected.value("cropped_width", expected.at("width")));
  EXPECT_EQ(result.at("cropped_height"), expected.value("cropped_height", expected.at("height")));
  EXPECT_TRUE(result.contains("parameters"));
}

TEST(EvalMapCommandTest, DefaultsMatchTheIndependentImplementationWithTheCanvasRule) {
  ExpectRbpfValues("expected_paper_metrics_cropped.json", {});
}

TEST(EvalMapCommandTest, NoCropMatchesTheIndependentRawGridProfile) {
  ExpectRbpfValues("expected_paper_metrics.json", {"--no-crop"});
}

TEST(EvalMapCommandTest, YamlPointingAtMissingImageExitsTwoNamingBoth) {
  testing::TempDir dir;
  testing::WriteFile(dir / "map.yaml",
                     "image: missing.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n"
                     "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const auto run = RunCli({"eval", "map", (dir / "map.yaml").string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("map.yaml"));
  EXPECT_THAT(run.err, HasSubstr("missing.pgm"));
}

TEST(EvalMapCommandTest, MapWithNoKnownCellExitsTwo) {
  testing::TempDir dir;
  // A 4x4 binary PGM where every cell has the unknown value.
  std::string pgm = "P5\n4 4\n255\n" + std::string(16, static_cast<char>(205));
  testing::WriteFile(dir / "unknown.pgm", pgm);
  const auto run = RunCli({"eval", "map", (dir / "unknown.pgm").string(), "--unknown-value", "205"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("known"));
}

TEST(EvalMapCommandTest, UnknownValueOutOfRangeIsAUsageError) {
  EXPECT_EQ(RunCli({"eval", "map", "x.pgm", "--unknown-value", "300"}).exit_code, 2);
}

}  // namespace
}  // namespace slamsweep

namespace slamsweep {
namespace {

/// A 100 x 60-cell room with an inner wall, written as a map_server map whose origin is shifted.
std::string WriteRoom(const std::filesystem::path& yaml, double origin_x) {
  evaluator::OccupancyGrid grid(100, 60, 0.05, {origin_x, 0.0, 0.0});
  for (int r = 5; r < 55; ++r) {
    for (int c = 5; c < 95; ++c)
      grid.at(r, c) = (r == 5 || r == 54 || c == 5 || c == 94 || (c == 40 && r < 35)) ? 1.0f : 0.0f;
  }
  evaluator::WriteMapServer(grid, yaml);
  return yaml.string();
}

TEST(EvalMapCommandTest, ResolutionScoresTheMapOnOtherCellsAndSaysBoth) {
  slamsweep::testing::TempDir dir;
  const std::string room = WriteRoom(dir / "room.yaml", 0.0);
  const auto own = RunCli({"eval", "map", room, "--json"});
  ASSERT_EQ(own.exit_code, 0) << own.err;
  const auto coarse = RunCli({"eval", "map", room, "--resolution", "0.1", "--json"});
  ASSERT_EQ(coarse.exit_code, 0) << coarse.err;
  const nlohmann::json a = nlohmann::json::parse(own.out), b = nlohmann::json::parse(coarse.out);
  EXPECT_EQ(a["resolution_m"], 0.05);
  EXPECT_EQ(b["resolution_m"], 0.1);
  EXPECT_EQ(b["map_resolution_m"], 0.05);
  EXPECT_EQ(b["width"], 50);  // 100 cells of 0.05 m on 0.1 m cells
  EXPECT_EQ(RunCli({"eval", "map", room, "--resolution", "0"}).exit_code, 2);
}

TEST(EvalMapCompareCommandTest, ScoresAMapAgainstAReferenceAndFindsTheOffset) {
  testing::TempDir dir;
  const std::string reference = WriteRoom(dir / "reference.yaml", 0.0);
  const std::string shifted = WriteRoom(dir / "shifted.yaml", 0.2);
  const auto self = RunCli({"eval", "map-compare", reference, reference, "--json"});
  ASSERT_EQ(self.exit_code, 0) << self.err;
  const nlohmann::json same = nlohmann::json::parse(self.out);
  EXPECT_DOUBLE_EQ(same.at("chamfer_m").get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(same.at("f1").get<double>(), 1.0);

  const auto as_given = RunCli({"eval", "map-compare", shifted, reference, "--json"});
  ASSERT_EQ(as_given.exit_code, 0) << as_given.err;
  EXPECT_NEAR(nlohmann::json::parse(as_given.out).at("estimate_to_reference").at("max_m").get<double>(), 0.2, 0.05);

  const auto aligned = RunCli({"eval", "map-compare", shifted, reference, "--align", "se2", "--json"});
  ASSERT_EQ(aligned.exit_code, 0) << aligned.err;
  const nlohmann::json result = nlohmann::json::parse(aligned.out);
  EXPECT_LT(result.at("chamfer_m").get<double>(), 0.01);
  EXPECT_NEAR(result.at("transform").at("x_m").get<double>(), -0.2, 0.02);
  EXPECT_EQ(result.at("specification").at("alignment"), "icp");

  const auto bad = RunCli({"eval", "map-compare", shifted, (dir / "missing.yaml").string()});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.err, ::testing::HasSubstr("missing.yaml"));
}

}  // namespace
}  // namespace slamsweep
