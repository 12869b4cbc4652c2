#pragma once

#include <optional>

namespace slamsweep::evaluator::inline formats::inline map {

/// Which reader ReadMap uses. kAuto decides from the file name (see ReadMap).
enum class MapFormat {
  kAuto,
  kRosMapServer,  ///< ROS map_server YAML + PGM/PNG
  kMrptGridmap,   ///< MRPT COccupancyGridMap2D bitmap + `<stem>_limits.txt`
  kBareImage,     ///< a PGM/PNG with no metadata
};

/// Options of ReadMap. Only a bare image uses all of them; a ROS map's YAML fixes resolution,
/// origin and unknown space itself.
struct MapReadOptions {
  /// Bare image: the grey level that means "unknown" (205 for maps written by map_saver); without
  /// it every cell is known. MRPT bitmap: replaces MRPT's own unknown value 127.
  std::optional<int> unknown_value;
  /// Bare image: metres per cell (there is no metadata to take it from). The origin is (0, 0, 0).
  double default_resolution_m = 0.05;
  MapFormat format = MapFormat::kAuto;
};

/// Options of WriteMapServer.
struct MapWriteOptions {
  enum class Mode {
    /// map_saver's default: a P5 PGM of 0 (occupied), 254 (free) and 205 (unknown); YAML without `mode`.
    kTrinary,
    /// Grey levels kept: value = round(255 * (1 - p)) in an RGBA PNG whose alpha is 0 for unknown
    /// cells (map_server's scale mode can only mark unknown through alpha, which PGM lacks),
    /// YAML with `mode: scale`. map_server reads it back with its scale rules (99 * ratio).
    kScale,
  };
  Mode mode = Mode::kTrinary;
  /// Trinary mode: the image as map_saver's P5 PGM, or as an 8-bit grey PNG of the same values (a few
  /// kilobytes instead of one byte per cell; map_server reads both).
  bool trinary_png = false;
  /// Trinary mode, map_saver's `--occ` and `--free`: a cell whose map_server value
  /// v = round(100 * p) is >= occupied_threshold_percent is occupied, one with 0 <= v <=
  /// free_threshold_percent is free, anything else unknown.
  int occupied_threshold_percent = 65;
  int free_threshold_percent = 25;
};

}  // namespace slamsweep::evaluator::inline formats::inline map
