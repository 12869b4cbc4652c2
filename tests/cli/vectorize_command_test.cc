#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/cli/run_cli.h"
#include "tests/support/shared_data.h"

namespace slamsweep {
namespace {

using ::testing::HasSubstr;
using testing::RunCli;

/// A 10x10 map_server map (0.5 m/cell, origin (10, 20)) with one 4x4 occupied block.
std::filesystem::path WriteBlockMap(const testing::TempDir& dir) {
  std::string pixels(100, static_cast<char>(254));
  for (int row = 3; row < 7; ++row) {
    for (int col = 2; col < 6; ++col) pixels[row * 10 + col] = 0;
  }
  testing::WriteFile(dir / "block.pgm", "P5\n10 10\n255\n" + pixels);
  return testing::WriteFile(dir / "block.yaml",
                            "image: block.pgm\nresolution: 0.5\norigin: [10.0, 20.0, 0.0]\nnegate: 0\n"
                            "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
}

TEST(VectorizeCommandTest, WritesGeoJsonInWorldMetres) {
  testing::TempDir dir;
  const auto yaml = WriteBlockMap(dir);
  const auto run =
      RunCli({"vectorize", yaml.string(), "--threshold", "75", "-o", (dir / "out.geojson").string(), "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json stats = nlohmann::json::parse(run.out);
  EXPECT_EQ(stats.at("obstacle_count"), 1);
  std::ifstream in(dir / "out.geojson");
  const nlohmann::json geojson = nlohmann::json::parse(in);
  EXPECT_EQ(geojson.at("type"), "FeatureCollection");
  ASSERT_EQ(geojson.at("features").size(), 1u);
  // Every vertex is a cell centre of the block: x in [11.25, 12.75], y in [21.75, 23.25].
  const auto& ring = geojson.at("features")[0].at("geometry").at("coordinates")[0];
  ASSERT_GE(ring.size(), 4u);
  for (const auto& point : ring) {
    EXPECT_GE(point[0].get<double>(), 11.25 - 1e-9);
    EXPECT_LE(point[0].get<double>(), 12.75 + 1e-9);
    EXPECT_GE(point[1].get<double>(), 21.75 - 1e-9);
    EXPECT_LE(point[1].get<double>(), 23.25 + 1e-9);
  }
}

TEST(VectorizeCommandTest, WritesSvg) {
  testing::TempDir dir;
  const auto yaml = WriteBlockMap(dir);
  const auto run = RunCli({"vectorize", yaml.string(), "--threshold", "75", "-o", (dir / "out.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::ifstream in(dir / "out.svg");
  const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_THAT(svg, HasSubstr("<svg"));
  EXPECT_THAT(svg, HasSubstr("<path"));
}

TEST(VectorizeCommandTest, RejectsUnknownOutputExtension) {
  testing::TempDir dir;
  const auto yaml = WriteBlockMap(dir);
  const auto run = RunCli({"vectorize", yaml.string(), "--threshold", "75", "-o", (dir / "out.txt").string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("out.txt"));
}

TEST(VectorizeCommandTest, ThresholdIsRequired) {
  EXPECT_EQ(RunCli({"vectorize", "map.yaml", "-o", "x.svg"}).exit_code, 2);
}

}  // namespace
}  // namespace slamsweep
