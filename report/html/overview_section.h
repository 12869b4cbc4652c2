#pragma once

#include <vector>

#include "report/html/html.h"
#include "report/html/site_data.h"
#include "report/model/significance.h"

namespace slamsweep::report::inline html {

/// The index page's first section: per table (sequence x noise) the rows ranked by the headline metric with a
/// 95 % interval, n_ok/n and a dot plot; the rows shown beside the ranking with why; and whether the best row
/// is significantly better than the runner-up and the odometry baseline.
Html OverviewSection(const SiteData& site, const std::vector<TableSignificance>& significance);

}  // namespace slamsweep::report::inline html
