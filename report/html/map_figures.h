#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "report/html/html.h"
#include "report/html/site_data.h"
#include "report/images/map_comparison_types.h"

namespace slamsweep::report::inline html {

/// One table's maps to draw (Artwork::MapComparison), with the key of its table in SiteData::maps_compared.
struct PlannedMapComparison {
  std::string table_key;
  MapComparisonJob job;
};

/// Plans, per table, the "Maps compared" figures: each row's median run (AlgorithmRow::median_run, the run
/// of the gallery and the trajectory figure) as a map panel, placed in the reference's frame by the transform
/// its map scores used (result.json map_compare.transform), else by its ATE alignment (ape_trans.alignment),
/// else as recorded; and, where the run was scored against a reference map (map_compare.reference_map.file),
/// a difference image with the thresholds and match radius of those scores. Fills site.maps_compared and
/// makes the tables' folders under `out_dir`.
std::vector<PlannedMapComparison> PlanMapComparisons(const std::filesystem::path& out_dir, SiteData& site,
                                                     int max_side_px = 480);

/// The sequence page's "Maps compared" section (empty for a table without maps).
Html MapsComparedSection(const SiteData& site, const SequenceModel& sequence, std::string_view root);

/// The style sheet rules of that section, appended to style.css.
std::string_view MapsComparedStyleSheet();

}  // namespace slamsweep::report::inline html
