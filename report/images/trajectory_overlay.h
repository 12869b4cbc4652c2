#pragma once

#include <filesystem>
#include <string>

namespace slamsweep::report::inline images {

struct OverlayOptions {
  /// Longer side of the map part of the picture, pixels (small maps are enlarged to it).
  int max_side_px = 800;
  /// The evaluator's alignment of the estimate onto the reference (none, origin, se2, se3, sim2,
  /// sim3); its inverse places the reference on the map. Use the run's evaluation.align.
  std::string align = "se2";
  /// Association tolerance for that alignment, seconds.
  double t_max_diff_s = 0.01;
};

/// Colours of the overlay (B, G, R as OpenCV stores them), public so that tests and the report's
/// captions can name them: estimate in blue (#0072B2), reference in vermillion (#D55E00).
inline constexpr unsigned char kEstimateBgr[3] = {0xB2, 0x72, 0x00};
inline constexpr unsigned char kReferenceBgr[3] = {0x00, 0x5E, 0xD5};

/// Draws the estimated trajectory over its map as a PNG:
/// - the map (evaluator ReadMap, any format it reads) in map_saver's greys: free white, occupied
///   black, p as 255 (1 - p), unknown 205; cropped to its known cells and the paths (plus a 5 %
///   margin, never beyond the map and paths nor more than half a map beyond the map), scaled so
///   the longer side is max_side_px;
/// - the reference (when `reference_tum` is not empty), aligned ONTO the estimate with the
///   inverse of the evaluator's alignment (AlignReferenceOntoEstimate), 6 px wide, under
/// - the estimate, in the map frame as the SLAM program wrote it, 2 px wide;
/// - start (circle) and end (square) markers on each path, and a legend strip below the map
///   saying what each colour is and how the reference was aligned (or why it is missing).
/// World (x, y) goes to the map cell (x - origin_x, y - origin_y) / resolution (rotated by the
/// origin's yaw), row 0 at the top.
/// Throws evaluator::InputError naming the file for an unreadable map or trajectory, an estimate
/// without poses, an unknown `align`, max_side_px below 64 or a PNG that cannot be written.
void WriteTrajectoryOverlay(const std::filesystem::path& map_yaml, const std::filesystem::path& estimate_tum,
                            const std::filesystem::path& reference_tum, const std::filesystem::path& png,
                            const OverlayOptions& options);

}  // namespace slamsweep::report::inline images
