#pragma once

// What the "Maps compared" figures of one table are made from and what drawing them gave: plain values
// (no OpenCV), shared by the pages that plan them (report/html) and the code that draws them.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace slamsweep::report::inline images {

/// A map's place in the table's common frame: world (x, y) of the map goes to
/// (x_m, y_m) + scale * R(yaw_rad) (x, y). The identity draws a map as recorded.
struct MapPlacement {
  double x_m = 0.0;
  double y_m = 0.0;
  double yaw_rad = 0.0;
  double scale = 1.0;
};

/// The thresholds and match radius of the run's map-vs-reference scores (result.json
/// map_compare.specification), so the difference image shows what the scores counted.
struct WallMatchOptions {
  double occupied_threshold = 0.65;
  double free_threshold = 0.196;
  int match_radius_cells = 2;
};

/// One run's panel: its map placed in the common frame and, with a reference map, its difference image.
struct MapPanelRequest {
  std::filesystem::path map_file;  ///< anything evaluator ReadMap reads (map.yaml)
  MapPlacement placement;
  std::filesystem::path png;
  /// Empty: no difference image (no reference map for this run).
  std::filesystem::path reference_map_file;
  std::filesystem::path difference_png;
  WallMatchOptions match;
};

/// Every panel of one table, drawn at one scale into one world window.
struct MapComparisonJob {
  std::vector<MapPanelRequest> panels;
  /// The table's reference map (may be empty): drawn as a panel of its own into `reference_png`, and its
  /// known area is the window all panels share; without one the window is the union of the maps' known areas.
  std::filesystem::path reference_map_file;
  std::filesystem::path reference_png;
  int max_side_px = 480;  ///< longer side of every panel
};

/// Cells of a difference image: occupied in the run only, in the reference only, in both (an occupied
/// cell with an occupied cell of the other map within the match radius counts as in both).
struct WallCounts {
  std::size_t run_only = 0;
  std::size_t reference_only = 0;
  std::size_t both = 0;
};

struct MapPanelDrawn {
  bool made = false;
  std::string note;  ///< why not
  bool difference_made = false;
  std::string difference_note;
  std::optional<WallCounts> counts;
};

/// What drawing a MapComparisonJob gave: the one scale of all its panels.
struct MapComparisonDrawn {
  double metres_per_pixel = 0.0;
  double window_width_m = 0.0;
  double window_height_m = 0.0;
  bool reference_made = false;
  std::vector<MapPanelDrawn> panels;  ///< parallel to MapComparisonJob::panels
};

}  // namespace slamsweep::report::inline images
