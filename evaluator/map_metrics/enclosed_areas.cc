#include "evaluator/map_metrics/enclosed_areas.h"

#include <algorithm>
#include <array>
#include <set>
#include <string>
#include <utility>

#include "evaluator/core/input_error.h"
#include "evaluator/map_metrics/free_region_sweep.h"
#include "evaluator/map_metrics/level_runs.h"
#include "evaluator/map_metrics/otsu.h"

// The spec fixes the image, the sweep of u and Otsu's threshold; how regions are delimited and
// measured is read as follows, the one reading that reproduces the reference values
// (reference/maps/expected_paper_metrics.json, an independent Python + OpenCV implementation)
// exactly on all three maps:
//   * a region is an 8-connected component of free cells (value > threshold), i.e. one outer
//     border of Suzuki-Abe border following (findContours RETR_CCOMP / RETR_TREE, top-level).
//     Not RETR_EXTERNAL, which skips a free region nested in a hole of another (a room seen
//     inside a building outline);
//   * its area is its number of cells ("at least 4 cells"), not the area of its border polygon,
//     which is 0 for a one-cell-wide region;
//   * it touches the border when one of its cells lies in the first or last row or column.
// Regions are labelled from runs with a union-find (free_region_sweep.h): the same regions as
// border following at a fraction of the cost. A test checks every step of the sweep against
// cv::threshold and cv::findContours on the reference maps.

namespace slamsweep::evaluator::inline map_metrics {

void Validate(const EnclosedAreasOptions& options) {
  auto fail = [](const std::string& name, std::int64_t value, const std::string& expected) {
    throw InputError("option enclosed." + name + " = " + std::to_string(value) + ": expected " + expected);
  };
  if (options.first_unknown_value < 0 || options.first_unknown_value > 255) {
    fail("first_unknown_value", options.first_unknown_value, "an 8-bit image value in [0, 255]");
  }
  if (options.unknown_value_step < 1) fail("unknown_value_step", options.unknown_value_step, "a step >= 1");
  if (options.unknown_value_limit <= options.first_unknown_value || options.unknown_value_limit > 256) {
    fail("unknown_value_limit", options.unknown_value_limit,
         "an exclusive bound in (first_unknown_value, 256], so that the sweep holds at least one value");
  }
  if (options.min_area_cells < 1) fail("min_area_cells", options.min_area_cells, "at least 1 cell");
}

EnclosedAreas ComputeEnclosedAreas(const OccupancyGrid& grid, const EnclosedAreasOptions& options) {
  Validate(options);
  return ComputeEnclosedAreas(ScorableGrid::Check(grid), options);
}

EnclosedAreas ComputeEnclosedAreas(const ScorableGrid& scorable, const EnclosedAreasOptions& options) {
  Validate(options);
  return ComputeEnclosedAreas(BuildLevelRuns(scorable.grid()), options);
}

EnclosedAreas ComputeEnclosedAreas(const LevelRuns& levels, const EnclosedAreasOptions& options) {
  Validate(options);

  // Otsu's threshold for every u, from the histogram alone: the unknown cells all move to u.
  // Unknown cells are free when u is above the threshold.
  std::vector<EnclosedAreasStep> steps;
  std::vector<int> thresholds[2];  // [unknown free]: the thresholds that family needs
  for (int u = options.first_unknown_value; u < options.unknown_value_limit; u += options.unknown_value_step) {
    Histogram256 histogram = levels.known_histogram;
    histogram[u] += levels.unknown_cells;
    const int threshold = OtsuThreshold(histogram);
    steps.push_back({u, threshold, 0});
    thresholds[u > threshold ? 1 : 0].push_back(threshold);
  }
  std::vector<int> all_thresholds = thresholds[0];
  all_thresholds.insert(all_thresholds.end(), thresholds[1].begin(), thresholds[1].end());
  for (std::vector<int>* list : {&thresholds[0], &thresholds[1], &all_thresholds}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }

  // Each family (unknown occupied, unknown free) is one pass over the image, however many
  // thresholds it holds: every distinct binarisation is counted once, none is redone.
  const FreeRegionSweep sweep(levels, all_thresholds);
  std::vector<std::int64_t> counts[2];
  for (int unknown_free = 0; unknown_free < 2; ++unknown_free) {
    if (thresholds[unknown_free].empty()) continue;
    // The pass can stop at the family's lowest threshold: lower ones belong to the other.
    const int lowest = static_cast<int>(
        std::lower_bound(all_thresholds.begin(), all_thresholds.end(), thresholds[unknown_free].front()) -
        all_thresholds.begin());
    counts[unknown_free] = sweep.Count(unknown_free == 1, options.min_area_cells, lowest);
  }

  // known_at_or_below[t]: known cells with value <= t. Two thresholds with the same count free
  // the same known cells, so (that count, unknown free) names a distinct binarisation.
  std::array<std::int64_t, 256> known_at_or_below{};
  std::int64_t running = 0;
  for (int value = 0; value < 256; ++value) {
    running += levels.known_histogram[value];
    known_at_or_below[value] = running;
  }
  std::set<std::pair<std::int64_t, bool>> binarisations;

  EnclosedAreas result;
  for (EnclosedAreasStep& step : steps) {
    const bool unknown_free = step.unknown_value > step.otsu_threshold;
    const auto index =
        std::lower_bound(all_thresholds.begin(), all_thresholds.end(), step.otsu_threshold) - all_thresholds.begin();
    step.enclosed_areas = counts[unknown_free ? 1 : 0][static_cast<std::size_t>(index)];
    binarisations.emplace(known_at_or_below[step.otsu_threshold], unknown_free);
    if (result.sweep.empty() || step.enclosed_areas > result.enclosed_areas) {
      result.enclosed_areas = step.enclosed_areas;
      result.at_unknown_value = step.unknown_value;
      result.otsu_threshold = step.otsu_threshold;
    }
    result.sweep.push_back(step);
  }
  result.distinct_binarisations = static_cast<int>(binarisations.size());
  return result;
}

void to_json(nlohmann::json& out, const EnclosedAreasOptions& options) {
  out = nlohmann::json{{"first_unknown_value", options.first_unknown_value},
                       {"unknown_value_step", options.unknown_value_step},
                       {"unknown_value_limit", options.unknown_value_limit},
                       {"min_area_cells", options.min_area_cells}};
}

void to_json(nlohmann::json& out, const EnclosedAreas& result) {
  nlohmann::json sweep = nlohmann::json::array();
  for (const EnclosedAreasStep& step : result.sweep) {
    sweep.push_back({{"unknown_value", step.unknown_value},
                     {"otsu_threshold", step.otsu_threshold},
                     {"enclosed_areas", step.enclosed_areas}});
  }
  out = nlohmann::json{{"enclosed_areas", result.enclosed_areas},
                       {"at_unknown_value", result.at_unknown_value},
                       {"otsu_threshold", result.otsu_threshold},
                       {"distinct_binarisations", result.distinct_binarisations},
                       {"sweep", std::move(sweep)}};
}

}  // namespace slamsweep::evaluator::inline map_metrics
