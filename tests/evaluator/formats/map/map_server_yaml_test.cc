#include "evaluator/formats/map/map_server_yaml.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/evaluator/formats/map/map_test_helpers.h"

namespace slamsweep::evaluator {
namespace {

using map_test::InputErrorOf;
using ::testing::HasSubstr;
using ::testing::StartsWith;

constexpr const char* kMapSaverYaml =
    "image: map.pgm\n"
    "resolution: 0.050000\n"
    "origin: [-12.200000, -7.500000, 0.000000]\n"
    "negate: 0\n"
    "occupied_thresh: 0.65\n"
    "free_thresh: 0.196\n"
    "\n";

std::string Replaced(std::string yaml, const std::string& line, const std::string& by) {
  const std::size_t at = yaml.find(line);
  if (at != std::string::npos) yaml.replace(at, line.size(), by);
  return yaml;
}

TEST(MapServerYamlTest, ReadsWhatMapSaverWrites) {
  const MapServerMetadata metadata = ParseMapServerYaml(kMapSaverYaml, "/maps/site/map.yaml");
  EXPECT_EQ(metadata.image, std::filesystem::path("/maps/site/map.pgm"));
  EXPECT_EQ(metadata.image_line, 1u);
  EXPECT_DOUBLE_EQ(metadata.resolution_m, 0.05);
  EXPECT_DOUBLE_EQ(metadata.origin.x_m, -12.2);
  EXPECT_DOUBLE_EQ(metadata.origin.y_m, -7.5);
  EXPECT_DOUBLE_EQ(metadata.origin.yaw_rad, 0.0);
  EXPECT_FALSE(metadata.negate);
  EXPECT_DOUBLE_EQ(metadata.occupied_thresh, 0.65);
  EXPECT_DOUBLE_EQ(metadata.free_thresh, 0.196);
  EXPECT_EQ(metadata.mode, MapServerMode::kTrinary);  // no mode key: trinary, as map_server assumes
}

TEST(MapServerYamlTest, ModesNegateCommentsBlockListsAndAbsoluteImage) {
  const std::string yaml =
      "# written by hand\n"
      "image: /data/maps/floor.png\n"
      "resolution: 0.1\n"
      "origin:\n  - 1\n  - +2.5\n  - 0.5\n"
      "negate: 1\n"
      "occupied_thresh: 0.7\n"
      "free_thresh: 0.2\n"
      "mode: scale\n";
  const MapServerMetadata metadata = ParseMapServerYaml(yaml, "relative/dir/floor.yaml");
  EXPECT_EQ(metadata.image, std::filesystem::path("/data/maps/floor.png"));
  EXPECT_EQ(metadata.image_line, 2u);
  EXPECT_DOUBLE_EQ(metadata.origin.y_m, 2.5);
  EXPECT_DOUBLE_EQ(metadata.origin.yaw_rad, 0.5);
  EXPECT_TRUE(metadata.negate);
  EXPECT_EQ(metadata.mode, MapServerMode::kScale);
  EXPECT_EQ(ParseMapServerYaml(std::string(kMapSaverYaml) + "mode: raw\n", "m.yaml").mode, MapServerMode::kRaw);
  EXPECT_EQ(ParseMapServerYaml(std::string(kMapSaverYaml) + "mode: trinary\n", "m.yaml").mode, MapServerMode::kTrinary);
  EXPECT_TRUE(ParseMapServerYaml(Replaced(kMapSaverYaml, "negate: 0", "negate: true"), "m.yaml").negate);
  // A YAML without a folder resolves its image against the working directory, like map_server's dirname ".".
  EXPECT_EQ(ParseMapServerYaml(kMapSaverYaml, "map.yaml").image, std::filesystem::path("map.pgm"));
}

TEST(MapServerYamlTest, NegativeResolutionIsReportedAtItsLine) {
  const std::string message =
      InputErrorOf([] { ParseMapServerYaml(Replaced(kMapSaverYaml, "0.050000", "-0.05"), "site.yaml"); });
  EXPECT_THAT(message, StartsWith("site.yaml:2: field 'resolution': expected a positive number"));
  EXPECT_THAT(message, HasSubstr("got '-0.05'"));
  EXPECT_THAT(InputErrorOf([] { ParseMapServerYaml(Replaced(kMapSaverYaml, "0.050000", "fine"), "s.yaml"); }),
              StartsWith("s.yaml:2: field 'resolution': expected a positive number, got 'fine'"));
  EXPECT_THAT(InputErrorOf([] { ParseMapServerYaml(Replaced(kMapSaverYaml, "0.050000", ".nan"), "s.yaml"); }),
              StartsWith("s.yaml:2: field 'resolution'"));
}

TEST(MapServerYamlTest, UnknownKeyIsAnErrorAtItsLine) {
  const std::string message =
      InputErrorOf([] { ParseMapServerYaml(std::string(kMapSaverYaml) + "ocupied_thresh: 0.6\n", "t.yaml"); });
  EXPECT_THAT(message, StartsWith("t.yaml:8: unknown key 'ocupied_thresh'"));
  EXPECT_THAT(message, HasSubstr("occupied_thresh"));  // lists the valid keys
}

TEST(MapServerYamlTest, RepeatedKeyIsAnError) {
  const std::string message =
      InputErrorOf([] { ParseMapServerYaml(std::string(kMapSaverYaml) + "resolution: 0.1\n", "t.yaml"); });
  EXPECT_THAT(message, StartsWith("t.yaml:8: key 'resolution' appears twice (first on line 2)"));
}

TEST(MapServerYamlTest, EveryKeyButModeIsRequired) {
  for (const std::string key : {"image", "resolution", "origin", "negate", "occupied_thresh", "free_thresh"}) {
    std::string yaml = kMapSaverYaml;
    const std::size_t at = yaml.find(key + ":");
    yaml.erase(at, yaml.find('\n', at) - at + 1);
    EXPECT_THAT(InputErrorOf([&] { ParseMapServerYaml(yaml, "r.yaml"); }),
                StartsWith("r.yaml: field '" + key + "' is missing"))
        << key;
  }
}

TEST(MapServerYamlTest, InvalidValuesNameFieldLineAndExpectation) {
  const auto error = [](const std::string& line, const std::string& by) {
    return InputErrorOf([&] { ParseMapServerYaml(Replaced(kMapSaverYaml, line, by), "v.yaml"); });
  };
  EXPECT_THAT(error("origin: [-12.200000, -7.500000, 0.000000]", "origin: [1, 2]"),
              StartsWith("v.yaml:3: field 'origin': expected [x, y, yaw]"));
  EXPECT_THAT(error("origin: [-12.200000, -7.500000, 0.000000]", "origin: [1, x, 0]"),
              StartsWith("v.yaml:3: field 'origin': expected [x, y, yaw]"));
  EXPECT_THAT(error("negate: 0", "negate: 2"), StartsWith("v.yaml:4: field 'negate': expected 0 or 1, got '2'"));
  EXPECT_THAT(error("occupied_thresh: 0.65", "occupied_thresh: 65"),
              StartsWith("v.yaml:5: field 'occupied_thresh': expected a number in [0, 1], got '65'"));
  EXPECT_THAT(error("free_thresh: 0.196", "free_thresh: 0.8"),
              StartsWith("v.yaml:6: field 'free_thresh': expected a number not above occupied_thresh"));
  EXPECT_THAT(error("image: map.pgm", "image: \"\""), StartsWith("v.yaml:1: field 'image'"));
  EXPECT_THAT(error("image: map.pgm", "image:"), StartsWith("v.yaml:1: field 'image'"));
  EXPECT_THAT(InputErrorOf([] { ParseMapServerYaml(std::string(kMapSaverYaml) + "mode: Scale\n", "v.yaml"); }),
              StartsWith("v.yaml:8: field 'mode': expected trinary, scale or raw, got 'Scale'"));
  // Scale mode divides by occupied_thresh - free_thresh.
  EXPECT_THAT(InputErrorOf([] {
                ParseMapServerYaml(Replaced(kMapSaverYaml, "free_thresh: 0.196", "free_thresh: 0.65") + "mode: scale\n",
                                   "v.yaml");
              }),
              HasSubstr("below occupied_thresh"));
}

TEST(MapServerYamlTest, EmptyScalarAndBrokenYaml) {
  EXPECT_THAT(InputErrorOf([] { ParseMapServerYaml("", "e.yaml"); }), StartsWith("e.yaml: empty map YAML"));
  EXPECT_THAT(InputErrorOf([] { ParseMapServerYaml("# only a comment\n", "e.yaml"); }),
              StartsWith("e.yaml: empty map YAML"));
  EXPECT_THAT(InputErrorOf([] { ParseMapServerYaml("map.pgm\n", "s.yaml"); }),
              StartsWith("s.yaml:1: expected a mapping"));
  EXPECT_THAT(InputErrorOf([] { ParseMapServerYaml("image: a.pgm\norigin: [1, 2\n", "b.yaml"); }),
              StartsWith("b.yaml:"));
  EXPECT_THAT(InputErrorOf([] { ParseMapServerYaml("image: a.pgm\norigin: [1, 2\n", "b.yaml"); }),
              HasSubstr("invalid YAML"));
}

}  // namespace
}  // namespace slamsweep::evaluator
