#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "report/html/artwork.h"
#include "report/html/site_data.h"
#include "report/plots/figure_types.h"

namespace slamsweep::report::inline html {

/// How a run's trajectory is aligned for pictures: the run's own evaluation settings (run.json `evaluation`:
/// align, t_max_diff_s), so a picture agrees with the ATE it illustrates.
OverlaySettings OverlaySettingsOf(const RunRecord& run);

/// The id of a table's figure of every row's trajectory over the reference, in TableViews::figures.
inline constexpr const char* kTrajectoriesFigureId = "trajectories/together";

/// The id of one row's error-along-the-path figure.
std::string PathErrorFigureId(std::size_t row);

/// Plans, per table with a reference, one figure of every row's median run (by ATE) aligned onto the reference
/// as the table's ATE aligns it (the run's evaluation align and t_max_diff_s), drawn over the reference in the
/// algorithm palette, and per row one figure of that run coloured by its translation error along the path.
/// Figures go to TableViews::figures (drawn by Artwork::Figures with the other view figures).
void PlanTrajectoryFigures(const std::filesystem::path& out_dir, SiteData& site, std::vector<FigureJob>& figures);

/// Plans, for every successful run with a reference trajectory, its trajectory coloured by its translation error
/// along the path (site.runs[i].path_error): a row's median run reuses its table's figure (planned by
/// PlanTrajectoryFigures, which must run first); other runs get RunDir/path-error.png, appended to `figures` to
/// be drawn in the same batch. With `every_run` false (a sweep beyond the report's every-run figure limit) only
/// the median runs get one.
void PlanRunPathErrorFigures(const std::filesystem::path& out_dir, SiteData& site, std::vector<FigureJob>& figures,
                             bool every_run);

/// After drawing: marks the runs' path-error figures whose PNG exists, notes why the others are missing
/// (`error` from the figure batch), and returns how many were drawn for runs alone and how many are missing.
std::pair<std::size_t, std::size_t> MarkRunPathErrorFigures(const std::filesystem::path& out_dir, bool drawing,
                                                            const std::string& error, SiteData& site);

/// The sequence page's "Trajectories" section: the figures planned above (with why one is missing).
Html TrajectoriesSection(const SiteData& site, const SequenceModel& sequence, std::string_view root);

}  // namespace slamsweep::report::inline html
