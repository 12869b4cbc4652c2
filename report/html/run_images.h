#pragma once

#include <filesystem>
#include <vector>

#include "report/html/image_jobs.h"
#include "report/html/report_layout.h"
#include "report/html/site_data.h"
#include "report/html/write_report.h"
#include "report/model/sweep_model.h"

namespace slamsweep::report::inline html {

/// Appends the jobs that draw each run's own figures (thumbnail, trajectory over the map, stages GIF) with
/// options.artwork, which must be set; their `done` records the result in site.runs. Every run's figures are
/// drawn up to options.figures_for_every_run_up_to runs (or with run_figures_for_every_run); above it only
/// those of the runs the galleries show (each row's median run) and of failed runs, the others marked as
/// left out.
void PlanRunImages(const SweepModel& model, const ReportLayout& layout, const std::filesystem::path& out_dir,
                   const ReportOptions& options, SiteData& site, std::vector<ImageJob>& jobs);

/// Appends a job that traces map.geojson for each run folder without one, among the runs whose own figures
/// are drawn (as PlanRunImages chooses them); `slamsweep vectorize` traces any other run's. Its `done` adds the
/// download or notes why it is missing.
void PlanVectorMaps(const SweepModel& model, const ReportLayout& layout, const std::filesystem::path& out_dir,
                    const ReportOptions& options, SiteData& site, std::vector<ImageJob>& jobs);

}  // namespace slamsweep::report::inline html
