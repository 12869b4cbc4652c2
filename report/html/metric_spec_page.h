#pragma once

#include <string>

#include "report/html/site_data.h"

namespace slamsweep::report::inline html {

/// metrics.html: the report's metric specification. Every metric a page of the report shows (flat
/// metric names as in result.json, summary.json and the CSV files), its unit, which direction is
/// better and its definition, then the statistics of the validity page. Linked from every page's footer.
std::string RenderMetricSpecPage(const SiteData& site);

}  // namespace slamsweep::report::inline html
