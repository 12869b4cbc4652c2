#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::evaluator::inline formats::inline map {

/// map_server's `mode` key: how grey levels become cell values.
enum class MapServerMode { kTrinary, kScale, kRaw };

/// The content of a ROS map_server map YAML (ROS 1 map_server/src/main.cpp).
struct MapServerMetadata {
  /// `image`, resolved against the YAML's folder unless absolute (as map_server does).
  std::filesystem::path image;
  /// Line of the `image` key, so that a missing image can be reported at its place.
  std::size_t image_line = 0;
  double resolution_m = 0.0;
  GridOrigin origin;  ///< `origin: [x, y, yaw]`
  bool negate = false;
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  MapServerMode mode = MapServerMode::kTrinary;  ///< optional key, trinary when absent
};

/// Parses map_server YAML text. Every key but `mode` is required, as in map_server; an unknown
/// or repeated key is an error too, so that a typo cannot pass silently. Errors are InputErrors
/// located at the YAML line: "map.yaml:2: field 'resolution': expected a positive number, got '-1'".
/// Checks: resolution > 0; origin a list of three numbers; negate 0/1 (or false/true);
/// thresholds in [0, 1] with free_thresh <= occupied_thresh (strictly below in scale mode, whose
/// ratio divides by their difference); mode trinary, scale or raw; image a non-empty string.
/// Does not look at the image file.
MapServerMetadata ParseMapServerYaml(std::string_view content, const std::filesystem::path& yaml_path);

/// map_server's name of a mode ("trinary", "scale", "raw").
std::string_view MapServerModeName(MapServerMode mode);

}  // namespace slamsweep::evaluator::inline formats::inline map
