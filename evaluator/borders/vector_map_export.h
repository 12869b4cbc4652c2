#pragma once

#include <nlohmann/json.hpp>
#include <ostream>

#include "evaluator/borders/vector_map.h"

namespace slamsweep::evaluator::inline borders {

/// GeoJSON FeatureCollection with one feature per border, coordinates [x, y] in the map's
/// world metres (a local frame, not WGS84 longitude/latitude) and a "bbox" of the grid.
/// Geometry: a Polygon with one closed ring (first vertex repeated at the end) in the traced
/// orientation -- counter-clockwise for outer borders as RFC 7946 recommends, clockwise for
/// holes, which are separate features; a border with 2 distinct vertices is a LineString and
/// one with a single distinct vertex a Point. Properties: "kind" ("outer" / "hole"),
/// "vertex_count" (of the simplified ring, closing vertex not counted), "border_length_m"
/// (traced length, see VectorMap) and "traced_cell_count". Coordinates, bbox and lengths are rounded to
/// the micrometre.
nlohmann::json ToGeoJson(const VectorMap& map);
void WriteGeoJson(const VectorMap& map, std::ostream& out);

/// SVG drawing of the borders: the viewBox is the grid's extent in world metres with y
/// negated, so north is up; one <path> per border (class "outer" or "hole"), styled with
/// presentation attributes only; strokes are one cell wide. Coordinates are printed in the
/// shortest form that reads back to the same double.
void WriteSvg(const VectorMap& map, std::ostream& out);

}  // namespace slamsweep::evaluator::inline borders
