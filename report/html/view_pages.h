#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "report/html/site_data.h"
#include "report/plots/figure_types.h"

namespace slamsweep::report::inline html {

// The report's views beyond the tables: per table (sequence x noise)
// - sequences/<table>/segments.html: drift over segment lengths (segment RPE): boxplots of the
//   translation and rotation error per length with one box per row, drift (%) against length, and
//   the mean drift per row and length with the best marked;
// - sequences/<table>/parameters.html, when an algorithm's rows differ in parameter values: each metric
//   against the parameter value (one varying parameter), an annotated heatmap (two), one heatmap per
//   combination of the others (three or more), and the best value per metric among comparable rows.

/// Builds the segment and parameter models of every table into site.views, makes their folders
/// under `out_dir` and appends their figures to `figures` (drawn later by the Artwork). Every figure
/// and page uses site.palette, which must be set.
void PlanViewPages(const std::filesystem::path& out_dir, SiteData& site, std::vector<FigureJob>& figures);

/// After drawing: marks the figures whose PNG exists, keeps `error` as the reason of the others
/// (empty: "the figure file is missing"; `drawing` false: images were not requested), and returns
/// {made, missing}.
std::pair<std::size_t, std::size_t> MarkViewFigures(const std::filesystem::path& out_dir, bool drawing,
                                                    const std::string& error, SiteData& site);

/// Writes every planned page; returns how many.
std::size_t WriteViewPages(const SiteData& site, const std::filesystem::path& out_dir);

std::string RenderSegmentPage(const SiteData& site, const SequenceModel& sequence, const TableViews& views);
std::string RenderParametersPage(const SiteData& site, const SequenceModel& sequence, const TableViews& views);

/// The id of a figure in TableViews::figures: "segments/<what>" or "parameters/<sweep>/<slice>/<column>".
std::string SegmentFigureId(std::string_view what);
std::string ParameterFigureId(std::size_t sweep, std::size_t slice, std::size_t column);

/// How row `row` of `sequence` is drawn: its algorithm's colour and marker, and as variant the number
/// of rows of the same algorithm before it in the table.
SeriesStyle RowStyle(const SiteData& site, const SequenceModel& sequence, std::size_t row);

/// "sequences/<table>/": the folder of a table's extra pages and figures, beside its page
/// "sequences/<table>.html" (a folder and a .html file never share a name, and <table> is unique).
std::string TableFolder(const ReportLayout& layout, const std::string& table_key);

/// Adds a figure to a table's views: its artefact (not made until drawn) and its job.
void AddFigure(TableViews& views, std::vector<FigureJob>& figures, const std::filesystem::path& out_dir,
               const std::string& id, const std::string& path, ViewFigure figure);

/// The style sheet rules of these pages and of the palette, appended to style.css.
std::string ViewStyleSheet();

/// "12 m", "2.5 m".
std::string LengthLabel(double length_m);

}  // namespace slamsweep::report::inline html
