#pragma once

#include "report/images/map_comparison_types.h"

namespace slamsweep::report::inline images {

/// Draws one table's "Maps compared" figures: every panel (and the reference map, when the job names
/// one) of the same world window at the same metres per pixel (report/images/map_panels.h), with a scale
/// bar, as PNGs; and per panel with a reference map the difference image of its walls. The window is the
/// reference map's known area, else the union of the maps' known areas. A map that cannot be read or
/// drawn is left out with its reason in the result; throws evaluator::InputError only when no map at all
/// has a known cell.
MapComparisonDrawn WriteMapComparison(const MapComparisonJob& job);

}  // namespace slamsweep::report::inline images
