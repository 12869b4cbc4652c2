#include "evaluator/borders/vector_map_export.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstddef>
#include <sstream>
#include <string>

#include "tests/evaluator/borders/grid_text.h"

namespace slamsweep::evaluator {
namespace {

using ::slamsweep::evaluator::testing::OccupancyFromRows;
using ::testing::HasSubstr;

// Cells of 0.5 m, lower-left corner at (10, -2): see vector_map_test.cc for the hand values.
VectorMap SquareAndLineMap() {
  return Vectorize(OccupancyFromRows(
                       {
                           ".......",  // Y = 6
                           ".###...",  // Y = 5
                           ".###...",  // Y = 4
                           ".###...",  // Y = 3
                           ".......",  // Y = 2
                           "..####.",  // Y = 1
                           ".......",  // Y = 0
                       },
                       0.5, GridOrigin{10.0, -2.0, 0.0}),
                   VectorizeOptions{});
}

std::size_t CountOccurrences(const std::string& text, const std::string& needle) {
  std::size_t count = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++count;
  return count;
}

nlohmann::json ParseGeoJson(const VectorMap& map) {
  std::ostringstream out;
  WriteGeoJson(map, out);
  return nlohmann::json::parse(out.str());
}

TEST(VectorMapExportTest, GeoJsonParsesBackWithWorldCoordinates) {
  const nlohmann::json geo = ParseGeoJson(SquareAndLineMap());
  EXPECT_EQ(geo.at("type"), "FeatureCollection");
  EXPECT_EQ(geo.at("bbox"), nlohmann::json({10.0, -2.0, 13.5, 1.5}));
  const nlohmann::json& features = geo.at("features");
  ASSERT_EQ(features.size(), 2u);

  const nlohmann::json& square = features[0];
  EXPECT_EQ(square.at("type"), "Feature");
  EXPECT_EQ(square.at("geometry").at("type"), "Polygon");
  const nlohmann::json& ring = square.at("geometry").at("coordinates").at(0);
  // Cells (1,5) (1,3) (3,3) (3,5), then the first again to close the ring.
  ASSERT_EQ(ring.size(), 5u);
  EXPECT_EQ(ring[0], nlohmann::json({10.75, 0.75}));
  EXPECT_EQ(ring[1], nlohmann::json({10.75, -0.25}));
  EXPECT_EQ(ring[2], nlohmann::json({11.75, -0.25}));
  EXPECT_EQ(ring[3], nlohmann::json({11.75, 0.75}));
  EXPECT_EQ(ring[4], ring[0]);
  EXPECT_EQ(square.at("properties").at("kind"), "outer");
  EXPECT_EQ(square.at("properties").at("vertex_count"), 4);
  EXPECT_DOUBLE_EQ(square.at("properties").at("border_length_m").get<double>(), 4.0);
  EXPECT_EQ(square.at("properties").at("traced_cell_count"), 8);

  // The one-cell-wide wall, cells (2,1)..(5,1): two distinct vertices -> a LineString.
  const nlohmann::json& wall = features[1];
  EXPECT_EQ(wall.at("geometry").at("type"), "LineString");
  EXPECT_EQ(wall.at("geometry").at("coordinates"), nlohmann::json({{11.25, -1.25}, {12.75, -1.25}}));
  EXPECT_DOUBLE_EQ(wall.at("properties").at("border_length_m").get<double>(), 3.0);
}

TEST(VectorMapExportTest, SingleDistinctVertexIsAPoint) {
  VectorMap map;
  map.polygons.push_back(Polygon{BorderKind::kOuter, {{1.5, 2.5}, {1.5, 2.5}}, 2, 0.0});
  const nlohmann::json geo = ToGeoJson(map);
  ASSERT_EQ(geo.at("features").size(), 1u);
  EXPECT_EQ(geo.at("features")[0].at("geometry"), nlohmann::json({{"type", "Point"}, {"coordinates", {1.5, 2.5}}}));
}

TEST(VectorMapExportTest, CoordinatesAreRoundedToTheMicrometre) {
  VectorMap map;
  // 0.05 m cells from an origin of -13.65 m: floating point puts the corner at 1.1750000000000007.
  const double corner = -13.65 + 0.05 * 296.5;
  ASSERT_NE(corner, 1.175);
  map.polygons.push_back(
      Polygon{BorderKind::kOuter, {{corner, 2.0000004}, {corner, 2.0000004}}, 2, 0.1000000000000001});
  const nlohmann::json geo = ToGeoJson(map);
  EXPECT_EQ(geo.at("features")[0].at("geometry").at("coordinates"), nlohmann::json({1.175, 2.0}));
  EXPECT_EQ(geo.at("features")[0].at("properties").at("border_length_m"), 0.1);
}

TEST(VectorMapExportTest, EmptyMapIsAnEmptyCollection) {
  const nlohmann::json geo = ParseGeoJson(VectorMap{});
  EXPECT_EQ(geo.at("type"), "FeatureCollection");
  EXPECT_TRUE(geo.at("features").empty());
}

TEST(VectorMapExportTest, SvgUsesWorldMetresWithNorthUp) {
  std::ostringstream out;
  WriteSvg(SquareAndLineMap(), out);
  const std::string svg = out.str();
  // Extent x 10..13.5, y -2..1.5; SVG's y axis points down, so the top edge is at -1.5.
  EXPECT_THAT(svg, HasSubstr("viewBox=\"10 -1.5 3.5 3.5\""));
  EXPECT_THAT(svg, HasSubstr("stroke-width=\"0.5\""));
  // One path per border; the square's top-left cell (10.75, 0.75) is drawn at y = -0.75.
  EXPECT_EQ(CountOccurrences(svg, "<path "), 2u);
  EXPECT_THAT(svg, HasSubstr("d=\"M10.75,-0.75 L10.75,0.25 L11.75,0.25 L11.75,-0.75 Z\""));
  EXPECT_THAT(svg, HasSubstr("d=\"M11.25,1.25 L12.75,1.25 Z\""));
  EXPECT_THAT(svg, ::testing::Not(HasSubstr("style=")));
  EXPECT_THAT(svg, HasSubstr("</svg>"));
}

}  // namespace
}  // namespace slamsweep::evaluator
