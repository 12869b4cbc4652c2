#pragma once

#include <filesystem>

#include "report/html/report_layout.h"
#include "report/html/site_data.h"
#include "report/model/sweep_model.h"

namespace slamsweep::report::inline html {

/// Writes the paper service's text files per algorithm x sequence under `out_dir`
/// (files/<algorithm>/<sequence>/: rmse.txt, corners.txt, occupied_ratio.txt, and pose_log.tum from the
/// row's median run, recorded in site.pose_logs). Rows without runs (reference lines) get none.
void WritePaperFiles(const SweepModel& model, const ReportLayout& layout, const std::filesystem::path& out_dir,
                     SiteData& site);

}  // namespace slamsweep::report::inline html
