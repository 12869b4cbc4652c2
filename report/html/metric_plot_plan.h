#pragma once

#include <filesystem>
#include <vector>

#include "report/html/artwork.h"
#include "report/html/report_layout.h"
#include "report/html/site_data.h"
#include "report/model/sweep_model.h"

namespace slamsweep::report::inline html {

/// The metric plots of every sequence: ATE translation, then each map metric, one plot per column that
/// has values, in the rows' styles. Each plot's artefact is added to site.plots (not made until drawn);
/// its request names its PNG under `out_dir`.
std::vector<PlotRequest> PlanPlots(const SweepModel& model, const ReportLayout& layout,
                                   const std::filesystem::path& out_dir, SiteData& site);

}  // namespace slamsweep::report::inline html
