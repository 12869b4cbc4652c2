// Vectorize on a real SLAM map (the shared telecom_icp.pgm): no exact reference exists for the
// handout's trace, so this checks properties that must hold for any correct result, on data
// with noise, thin walls and thousands of holes (and gives AddressSanitizer a realistic input).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <fstream>
#include <iterator>
#include <string>

#include "evaluator/borders/vector_map.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

// Binary PGM (P5, maxval 255) with the shared maps' encoding: 205 = unknown, p = (255 - v) / 255.
OccupancyGrid ReadSharedPgm(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int width = 0;
  int height = 0;
  int maxval = 0;
  in >> magic >> width >> height >> maxval;
  in.get();  // the single whitespace byte before the pixels
  EXPECT_EQ(magic, "P5");
  EXPECT_EQ(maxval, 255);
  const std::string pixels((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(pixels.size(), static_cast<std::size_t>(width) * height);
  OccupancyGrid grid(width, height, 0.05, GridOrigin{-40.0, -52.0, 0.0});
  for (std::size_t i = 0; i < grid.cells.size() && i < pixels.size(); ++i) {
    const int v = static_cast<unsigned char>(pixels[i]);
    grid.cells[i] = v == 205 ? OccupancyGrid::kUnknown : static_cast<float>(255 - v) / 255.0f;
  }
  return grid;
}

double PerimeterM(const Polygon& polygon) {
  double length_m = 0.0;
  for (std::size_t i = 0; i < polygon.vertices.size(); ++i) {
    const PointM& a = polygon.vertices[i];
    const PointM& b = polygon.vertices[(i + 1) % polygon.vertices.size()];
    length_m += std::hypot(b.x_m - a.x_m, b.y_m - a.y_m);
  }
  return length_m;
}

TEST(ReferenceMapTest, TelecomIcpVectorMapIsConsistent) {
  SLAMSWEEP_REQUIRE_SHARED(pgm, "reference/maps/telecom_icp.pgm");
  const OccupancyGrid grid = ReadSharedPgm(pgm);
  for (const double threshold : {0.0, 1.0, 75.0}) {
    SCOPED_TRACE(::testing::Message() << "threshold " << threshold);
    const VectorMap map = Vectorize(grid, VectorizeOptions{threshold, 1.0});
    ASSERT_FALSE(map.polygons.empty());
    EXPECT_EQ(map.obstacle_count + map.hole_count, map.polygons.size());
    EXPECT_EQ(map.raster_bytes, 1500u * 1760u * 4u);
    std::size_t vertices = 0;
    double traced_m = 0.0;
    for (const Polygon& polygon : map.polygons) {
      ASSERT_GE(polygon.vertices.size(), 2u);
      // Simplification keeps a subset of the traced cells.
      EXPECT_LE(polygon.vertices.size(), polygon.traced_cell_count);
      // A polygon through a subset of a closed walk's points is no longer than the walk
      // (triangle inequality).
      EXPECT_LE(PerimeterM(polygon), polygon.border_length_m + 1e-9);
      for (const PointM& vertex : polygon.vertices) {
        EXPECT_GT(vertex.x_m, map.bounds.min_x_m);
        EXPECT_LT(vertex.x_m, map.bounds.max_x_m);
        EXPECT_GT(vertex.y_m, map.bounds.min_y_m);
        EXPECT_LT(vertex.y_m, map.bounds.max_y_m);
      }
      vertices += polygon.vertices.size();
      traced_m += polygon.border_length_m;
    }
    EXPECT_EQ(map.vertex_count, vertices);
    EXPECT_NEAR(map.border_length_m, traced_m, 1e-6);
    EXPECT_EQ(map.vector_bytes, vertices * 8 + map.polygons.size() * 4);
  }
}

}  // namespace
}  // namespace slamsweep::evaluator
