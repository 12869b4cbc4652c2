#pragma once

#include <map>
#include <optional>
#include <set>
#include <utility>
#include <string>
#include <vector>

#include "report/html/html.h"
#include "report/html/report_layout.h"
#include "report/images/map_comparison_types.h"
#include "report/model/parameter_model.h"
#include "report/model/segment_model.h"
#include "report/model/across_data_sets.h"
#include "report/model/significance.h"
#include "report/model/sweep_model.h"
#include "report/plots/algorithm_palette.h"

namespace slamsweep::report::inline html {

/// What WriteReport made for one run, for its page: which images exist and why others do not.
struct RunArtifacts {
  bool thumbnail = false;  ///< RunDir/thumbnail.png
  bool overlay = false;    ///< RunDir/trajectory.png
  bool gif = false;        ///< RunDir/stages.gif
  std::string animation;   ///< RunDir/<name>: the worker's stage animation (an animated PNG), linked as it is
  /// The run's own figures (overlay, thumbnail, GIF) were not drawn because the sweep has this many runs
  /// (0: nothing left out).
  std::size_t figures_left_out = 0;
  /// The run's trajectory coloured by its translation error along the path (path relative to the report root;
  /// empty without one): a median run shows its table's figure, other runs get their own.
  std::string path_error;
  bool path_error_made = false;
  std::vector<std::string> notes;      ///< why an image or file is missing
  std::vector<std::string> downloads;  ///< file names copied into RunDir, in display order
  std::string log_tail;                ///< last lines of log.txt (raw text)
  bool log_truncated = false;
};

/// One metric plot of a sequence.
struct PlotArtifact {
  std::string metric;
  std::string title;
  std::string path;  ///< relative to the report root
  bool made = false;
  std::string note;  ///< why it is missing
};

/// The extra pages of one table (report/html/view_pages.h): drift over segment lengths and
/// parameter sweeps. A page path is empty when the table has no such page.
struct TableViews {
  std::optional<SegmentTable> segments;
  std::string segments_page;
  std::optional<ParameterTable> parameters;
  std::string parameters_page;
  /// The figures of both pages, by figure id (ViewFigureId).
  std::map<std::string, PlotArtifact> figures;
};

/// A run's map-vs-reference scores from result.json (metric_details.map_compare), absent when not scored.
struct MapScores {
  std::optional<double> f1, accuracy, completeness, chamfer_m, iou_occupied, iou_free;
};

/// One row's panel of a table's "Maps compared" (report/html/map_figures.h).
struct MapPanelShown {
  std::size_t row = 0;          ///< in SequenceModel::rows
  std::size_t run = 0;          ///< in SweepModel::runs: the row's median run
  std::string path;             ///< the map panel, relative to the report root
  std::string difference_path;  ///< the difference image; empty without a reference map
  std::string placement;        ///< how the map was placed in the common frame, for the caption
  MapScores scores;
  int match_radius_cells = 0;
  /// result.json says its map scores were computed on the run's map file (the file the counts are read
  /// from); older results scored the program's map before it was written.
  bool scored_on_map_file = false;
};

/// A table's "Maps compared": the median runs' maps at one scale and, where a reference map exists, their
/// differences from it.
struct MapsCompared {
  std::string reference_path;    ///< the reference map's panel; empty without a reference map
  std::string reference_source;  ///< result.json reference_map.source ("rendered", "file", ...)
  std::vector<MapPanelShown> panels;
  MapComparisonDrawn drawn;
  bool attempted = false;  ///< the drawing ran (else `error` says why not)
  std::string error;
};

/// Everything the page renderers read. Pages are pure functions of it.
struct SiteData {
  const SweepModel* model = nullptr;
  const ReportLayout* layout = nullptr;
  /// Per table (parallel to model->sequences): the ranking and the significance of its best row.
  std::vector<TableSignificance> significance;
  /// Per noise setting and odometry mode: the verdict across data sets (BuildAcrossDataSets).
  std::vector<DataSetVerdict> across_data_sets;
  std::string title;               ///< the sweep's name ("slamsweep report — <result dir name>" without one)
  std::vector<RunArtifacts> runs;  ///< parallel to model->runs
  std::map<std::string, std::vector<PlotArtifact>> plots;  ///< by table key (SequenceModel::key)
  /// Files copied from the result directory into the report.
  bool has_summary_json = false;
  bool has_summary_csv = false;
  bool has_runs_csv = false;
  /// (row label, table key) with files/.../pose_log.tum
  std::set<std::pair<std::string, std::string>> pose_logs;
  Html history_section;            ///< the index's nightly-history section (SiteExtension), empty without one
  bool has_validity_page = false;  ///< validity.html ("Which metrics can be trusted?") was written
  /// One colour and marker per algorithm in every plot and table of the report.
  const AlgorithmPalette* palette = nullptr;
  std::map<std::string, TableViews> views;            ///< by table key (SequenceModel::key)
  std::map<std::string, MapsCompared> maps_compared;  ///< by table key, tables with at least one map
};

/// The pages. `root` is the relative path back to the report root ("" or "../").
std::string RenderIndexPage(const SiteData& site);
std::string RenderSequencePage(const SiteData& site, const SequenceModel& sequence);
std::string RenderRunPage(const SiteData& site, std::size_t run);
/// style.css: the only styling of the site (no inline styles: Jenkins' CSP forbids them).
std::string_view StyleSheet();

/// The frame every page shares (title, style sheet, navigation, a footer linking metrics.html); `root`
/// leads back to the report root ("" or "../").
std::string RenderPage(std::string_view title, std::string_view root, const Html& body);
/// `<img class="..." src="..." alt="...">`, every value escaped.
Html ImageElement(std::string_view src, std::string_view alt, std::string_view css_class);
/// The algorithm's marker in its colour (a style sheet class), before its name in tables and legends;
/// empty without a palette.
Html AlgorithmSwatch(const SiteData& site, std::string_view algorithm);

}  // namespace slamsweep::report::inline html
