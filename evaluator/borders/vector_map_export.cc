#include "evaluator/borders/vector_map_export.h"

#include <fmt/format.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace slamsweep::evaluator::inline borders {
namespace {

const char* KindName(BorderKind kind) { return kind == BorderKind::kOuter ? "outer" : "hole"; }

// The distinct vertices in order of first appearance, up to `limit` of them (enough to tell
// a Point or a LineString from a Polygon without a quadratic scan of long rings).
std::vector<PointM> FirstDistinct(const std::vector<PointM>& vertices, std::size_t limit) {
  std::vector<PointM> distinct;
  for (const PointM& vertex : vertices) {
    bool seen = false;
    for (const PointM& known : distinct) seen = seen || known == vertex;
    if (seen) continue;
    distinct.push_back(vertex);
    if (distinct.size() == limit) break;
  }
  return distinct;
}

// Metres to the micrometre: cell corners computed in floating point would otherwise print as
// 1.1750000000000007 for 1.175, a third of a map's file for digits below any map's resolution.
double Micrometres(double metres) { return std::round(metres * 1e6) / 1e6; }

nlohmann::json Coordinates(const PointM& point) {
  return nlohmann::json::array({Micrometres(point.x_m), Micrometres(point.y_m)});
}

nlohmann::json Geometry(const Polygon& polygon) {
  const std::vector<PointM> distinct = FirstDistinct(polygon.vertices, 3);
  if (distinct.size() == 1) return {{"type", "Point"}, {"coordinates", Coordinates(distinct[0])}};
  if (distinct.size() == 2) {
    return {{"type", "LineString"},
            {"coordinates", nlohmann::json::array({Coordinates(distinct[0]), Coordinates(distinct[1])})}};
  }
  nlohmann::json ring = nlohmann::json::array();
  for (const PointM& vertex : polygon.vertices) ring.push_back(Coordinates(vertex));
  ring.push_back(Coordinates(polygon.vertices.front()));
  return {{"type", "Polygon"}, {"coordinates", nlohmann::json::array({std::move(ring)})}};
}

// -y so that north is up in SVG's y-down frame; 0.0 - y avoids printing "-0".
std::string SvgPoint(const PointM& point) { return fmt::format("{},{}", point.x_m, 0.0 - point.y_m); }

}  // namespace

nlohmann::json ToGeoJson(const VectorMap& map) {
  nlohmann::json features = nlohmann::json::array();
  for (const Polygon& polygon : map.polygons) {
    if (polygon.vertices.empty()) continue;
    features.push_back({{"type", "Feature"},
                        {"geometry", Geometry(polygon)},
                        {"properties",
                         {{"kind", KindName(polygon.kind)},
                          {"vertex_count", polygon.vertices.size()},
                          {"border_length_m", Micrometres(polygon.border_length_m)},
                          {"traced_cell_count", polygon.traced_cell_count}}}});
  }
  return {{"type", "FeatureCollection"},
          {"bbox",
           {Micrometres(map.bounds.min_x_m), Micrometres(map.bounds.min_y_m), Micrometres(map.bounds.max_x_m),
            Micrometres(map.bounds.max_y_m)}},
          {"features", std::move(features)}};
}

void WriteGeoJson(const VectorMap& map, std::ostream& out) { out << ToGeoJson(map).dump() << '\n'; }

void WriteSvg(const VectorMap& map, std::ostream& out) {
  const WorldBoundsM& b = map.bounds;
  const double width_m = b.max_x_m - b.min_x_m;
  const double height_m = b.max_y_m - b.min_y_m;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out << fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{} {} {} {}\">\n", b.min_x_m, 0.0 - b.max_y_m,
                     width_m, height_m);
  out << fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"white\"/>\n", b.min_x_m,
                     0.0 - b.max_y_m, width_m, height_m);
  out << fmt::format("<g fill=\"none\" stroke-width=\"{}\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n",
                     map.resolution_m);
  std::string d;
  for (const Polygon& polygon : map.polygons) {
    if (polygon.vertices.empty()) continue;
    d.clear();
    for (std::size_t i = 0; i < polygon.vertices.size(); ++i) {
      d += i == 0 ? "M" : " L";
      d += SvgPoint(polygon.vertices[i]);
    }
    d += " Z";  // a one-vertex path "M p Z" still draws a dot thanks to the round caps
    out << fmt::format("<path class=\"{}\" stroke=\"{}\" d=\"{}\"/>\n", KindName(polygon.kind),
                       polygon.kind == BorderKind::kOuter ? "black" : "dimgray", d);
  }
  out << "</g>\n</svg>\n";
}

}  // namespace slamsweep::evaluator::inline borders
