#pragma once

#include <cstddef>

#include <nlohmann/json.hpp>

#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::evaluator::inline map_compare {

/// A rigid planar transform taking estimate-map world coordinates to reference-map ones.
struct MapTransform {
  double x_m = 0.0;
  double y_m = 0.0;
  double yaw_rad = 0.0;
};

struct MapCompareOptions {
  /// A cell with p >= occupied_threshold is occupied, p <= free_threshold free, anything between
  /// (and unknown) is neither: map_saver's trinary thresholds.
  double occupied_threshold = 0.65;
  double free_threshold = 0.196;
  /// Accuracy/completeness count an occupied cell as matched within this many cells.
  int match_radius_cells = 2;
  /// How the estimate is placed on the reference: as given (`transform`), or refined by ICP of the
  /// occupied cells starting from `transform`.
  bool refine_with_icp = false;
  int icp_iterations = 30;
  MapTransform transform;
};

/// Map-versus-reference scores (evaluator/map_compare/README.md gives every definition).
struct MapComparison {
  /// Mean and max distance (m) from each occupied estimate cell to the nearest occupied reference
  /// cell, and the reverse; chamfer = the mean of the two means.
  double estimate_to_reference_mean_m = 0, estimate_to_reference_max_m = 0;
  double reference_to_estimate_mean_m = 0, reference_to_estimate_max_m = 0;
  double chamfer_m = 0;
  /// Fraction of occupied estimate cells within the radius of a reference one (accuracy, the
  /// precision of walls), of occupied reference cells within the radius of an estimate one
  /// (completeness, the recall), and their harmonic mean.
  double accuracy = 0, completeness = 0, f1 = 0;
  /// Intersection over union of the occupied and of the free cells, over cells known in both maps.
  double iou_occupied = 0, iou_free = 0;
  std::size_t estimate_occupied = 0, reference_occupied = 0, known_in_both = 0;
  /// The transform used (after ICP when asked).
  MapTransform transform;

  nlohmann::json ToJson(const MapCompareOptions& options) const;
};

/// Compares `estimate`, placed on `reference` by the options' transform, on the reference's grid.
/// Throws InputError when either map has no occupied cell or the resolutions differ by more than 1 %.
MapComparison CompareMaps(const OccupancyGrid& estimate, const OccupancyGrid& reference,
                          const MapCompareOptions& options = {});

}  // namespace slamsweep::evaluator::inline map_compare
