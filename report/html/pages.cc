#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "evaluator/sequence/scan_spacing.h"
#include "report/html/across_data_sets_section.h"
#include "report/html/html.h"
#include "report/html/map_figures.h"
#include "report/html/number_format.h"
#include "report/html/overview_section.h"
#include "report/html/site_data.h"
#include "report/html/trajectory_figures.h"

namespace slamsweep::report::inline html {

namespace {

constexpr std::string_view kPageTemplate = R"(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>{{title}}</title>
<link rel="stylesheet" href="{{root}}style.css">
</head>
<body>
<header><nav><a href="{{root}}index.html">Sweep overview</a></nav><h1>{{title}}</h1></header>
<main>
{{body}}
</main>
<footer>Made by slamsweep report. Metric definitions: <a href="{{root}}metrics.html">metric specification</a>. Lower is better for every metric in the tables; the specification says which direction is better for each metric.</footer>
</body>
</html>
)";

using html_shorthand::E;
using html_shorthand::T;

std::string Page(std::string_view title, std::string_view root, const Html& body) {
  return RenderPage(title, root, body);
}

Html Image(std::string_view src, std::string_view alt, std::string_view css_class) {
  return ImageElement(src, alt, css_class);
}

std::string CountsText(const RunCounts& counts) {
  std::string text = std::to_string(counts.total) + (counts.total == 1 ? " run: " : " runs: ") +
                     std::to_string(counts.ok) + " ok, " + std::to_string(counts.failed) + " failed";
  if (counts.unfinished > 0) text += ", " + std::to_string(counts.unfinished) + " unfinished";
  return text;
}

Html ColumnHeader(const MetricColumn& column) {
  std::string title = column.title;
  if (!column.unit.empty()) title += " (" + column.unit + ")";
  Html header = E(title);
  if (!column.spec.empty()) header += T("<br>") + Element("span", "spec", E(column.spec));
  return Element("th", "", header);
}

Html Cell(const MetricCell& cell) {
  Html content = E(FormatMeanStd(cell.summary));
  if (cell.summary.n > 0) content += T(" ") + Element("span", "n", E("n=" + std::to_string(cell.summary.n)));
  if (cell.best) content += T(" ") + Element("span", "marker", E("▼ best"));
  return Element("td", cell.best ? "best" : "", content);
}

/// What a reader must know before comparing the row's numbers with the others.
Html RowNotes(const AlgorithmRow& row) {
  Html notes;
  if (row.kind == RowKind::kOdometryBaseline) {
    notes += T("<br>") + Element("span", "baseline-note",
                                 E("baseline: the odometry as the robot recorded it (with the table's noise), the line "
                                   "a SLAM program must beat; never ranked"));
  }
  if (row.kind == RowKind::kReferenceFloor) {
    notes += T("<br>") + Element("span", "baseline-note",
                                 E("the reference trajectory itself, scored by the relations exactly as the runs are "
                                   "(same relations, same odometry between its poses): where the reference is a "
                                   "corrected log (GMapping's output) it is a SLAM result too, and this is the error "
                                   "of that result; never ranked"));
  }
  if (row.kind == RowKind::kPublished) {
    notes += T("<br>") + Element("span", "baseline-note", E("published figure, not measured here; never ranked"));
  }
  if (!row.scope_note.empty()) notes += T("<br>") + Element("span", "warning", E(row.scope_note));
  if (row.build_split) {
    notes +=
        T("<br>") + Element("span", "warning",
                            E("build " + row.build + " (" + row.build_description +
                              "): runs of this algorithm by other builds are other rows, never pooled with these"));
  }
  if (row.kind == RowKind::kContestant && row.counts.ok < row.counts.total) {
    notes += T("<br>") + Element("span", "warning",
                                 E("not ranked: " + std::to_string(row.counts.total - row.counts.ok) + " of " +
                                   std::to_string(row.counts.total) +
                                   " runs did not succeed, so its mean rests on the "
                                   "draws it survived"));
  }
  for (const orchestrator::RunFlag flag : row.flags) {
    notes += T("<br>") + Element("span", "warning",
                                 E(std::string(orchestrator::RunFlagLabel(flag)) + ": " +
                                   std::string(orchestrator::RunFlagMeaning(flag))));
  }
  if (row.seeding == "unseeded" || row.seeding == "mixed") {
    notes += T("<br>") + Element("span", "warning",
                                 E("unseeded: the program takes no seed, so its spread includes its own randomness "
                                   "and a rerun gives other numbers"));
  }
  return notes;
}

/// A baseline or reference line is drawn apart from the contestants.
std::string RowClass(const AlgorithmRow& row) {
  switch (row.kind) {
    case RowKind::kContestant:
      return "";
    case RowKind::kOdometryBaseline:
      return "baseline";
    case RowKind::kReferenceFloor:
    case RowKind::kPublished:
      return "reference-line";
  }
  return "";
}

Html MetricTableHtml(const SiteData& site, const SequenceModel& sequence, const std::vector<MetricColumn>& columns,
                     std::vector<MetricCell> AlgorithmRow::*cells, std::string_view caption, std::string_view root) {
  Html header = Element("th", "", E("Algorithm")) + Element("th", "", E("Runs"));
  for (const MetricColumn& column : columns) header += ColumnHeader(column);
  Html rows;
  for (const AlgorithmRow& row : sequence.rows) {
    Html name = E(row.algorithm);
    if (row.median_run) name = Link(std::string(root) + site.layout->RunPage(*row.median_run), name);
    name = AlgorithmSwatch(site, row.name) + name;
    name += RowNotes(row);
    Html line = Element("th", "", name) + Element("td", row.counts.failed + row.counts.unfinished > 0 ? "failures" : "",
                                                  E(CountsText(row.counts)));
    for (const MetricCell& cell : row.*cells) line += Cell(cell);
    rows += Element("tr", RowClass(row), line) + T("\n");
  }
  Html notes;
  for (const MetricColumn& column : columns) {
    if (!column.best_withheld.empty()) notes += Element("li", "", E(column.best_withheld));
  }
  return T("<table>\n") + Element("caption", "", E(caption)) + T("\n<thead>") + Element("tr", "", header) +
         T("</thead>\n<tbody>\n") + rows + T("</tbody>\n</table>\n") +
         (notes.str().empty() ? Html() : Element("ul", "table-notes", notes) + T("\n"));
}

/// The mark of a table whose scans are too far apart for scan matching: its numbers judge the data as much as
/// the programs.
Html SparseDataMark(const SequenceModel& sequence) {
  if (!sequence.scan_spacing) return {};
  const std::string warning = evaluator::SparseScanWarning(*sequence.scan_spacing);
  if (warning.empty()) return {};
  return Element("p", "sparse-data", E("Sparse data: " + warning + "."));
}

Html SequenceTables(const SiteData& site, const SequenceModel& sequence, std::string_view root) {
  Html out = SparseDataMark(sequence);
  if (sequence.trajectory_columns.empty()) {
    out += Element("p", "note",
                   E("No trajectory metric for this sequence (no reference trajectory, or no run succeeded): "
                     "Table I is not available."));
  } else {
    out += MetricTableHtml(site, sequence, sequence.trajectory_columns, &AlgorithmRow::trajectory_cells,
                           "Table I: trajectory error over iterations, mean ± sample std (failed runs have no value "
                           "and are counted in Runs)",
                           root);
  }
  if (sequence.relations_inside_log && sequence.relations_outside_log > 0) {
    out += Element("p", "note",
                   E(fmt::format("Relations: the runs are scored on the {} relations with both stamps inside this "
                                 "log; {} more of the relations file lie outside the log (it holds part of the run, "
                                 "or is cut): they are not this sequence's to cover and never count as missed.",
                                 *sequence.relations_inside_log, sequence.relations_outside_log)));
  }
  if (sequence.map_columns.empty()) {
    out += Element("p", "note", E("No map metric for this sequence (no run produced a map)."));
  } else {
    out += MetricTableHtml(site, sequence, sequence.map_columns, &AlgorithmRow::map_cells,
                           "Map metrics without ground truth (paper profile), mean ± sample std", root);
  }
  return out;
}

Html Plots(const SiteData& site, const SequenceModel& sequence, std::string_view root) {
  const auto it = site.plots.find(sequence.key);
  if (it == site.plots.end() || it->second.empty()) return {};
  Html figures;
  for (const PlotArtifact& plot : it->second) {
    Html body = plot.made ? Image(std::string(root) + plot.path, plot.title, "plot")
                          : Element("p", "note", E("Plot not available: " + plot.note));
    figures += Element("figure", "plot", body + Element("figcaption", "", E(plot.title)));
  }
  return Element("div", "plots", figures);
}

Html Gallery(const SiteData& site, const SequenceModel& sequence, std::string_view root) {
  Html figures;
  for (const AlgorithmRow& row : sequence.rows) {
    if (row.kind == RowKind::kReferenceFloor || row.kind == RowKind::kPublished) continue;
    Html body;
    if (!row.median_run) {
      body = Element("p", "note", E("no successful run"));
    } else {
      const std::size_t run = *row.median_run;
      const std::string page = std::string(root) + site.layout->RunPage(run);
      if (site.runs[run].thumbnail) {
        body = Link(page, Image(std::string(root) + site.layout->RunDir(run) + "thumbnail.png",
                                "map of " + site.model->runs[run].run_id, "thumbnail"));
      } else {
        body = Link(page, E("map not available"));
      }
      const std::string why = row.median_by.empty() ? "the first successful run" : "median run by " + row.median_by;
      body += Element("p", "note", E(why + ", iteration " + std::to_string(site.model->runs[run].iteration)));
    }
    figures += Element("figure", "map", Element("figcaption", "", E(row.algorithm)) + body);
  }
  return Element("div", "gallery", figures);
}

Html RunList(const SiteData& site, const SequenceModel& sequence, std::string_view root) {
  Html rows;
  for (const AlgorithmRow& row : sequence.rows) {
    for (std::size_t run : row.runs) {
      const RunRecord& record = site.model->runs[run];
      const std::string status(RunStatusName(record.status));
      rows += Element("tr", "",
                      Element("td", "", Link(std::string(root) + site.layout->RunPage(run), E(record.run_id))) +
                          Element("td", "", E(row.algorithm)) + Element("td", "", E(std::to_string(record.iteration))) +
                          Element("td", "status-" + status, E(status)) + Element("td", "", E(record.reason))) +
              T("\n");
    }
  }
  Html header;
  for (const char* name : {"Run", "Algorithm", "Iteration", "Status", "Reason"}) header += Element("th", "", E(name));
  return T("<table>\n<thead>") + Element("tr", "", header) + T("</thead>\n<tbody>\n") + rows +
         T("</tbody>\n</table>\n");
}

/// Links to the table's segment-length and parameter pages, when it has them.
Html ViewLinks(const SiteData& site, const SequenceModel& sequence, std::string_view root) {
  const auto views = site.views.find(sequence.key);
  if (views == site.views.end()) return {};
  Html links;
  if (!views->second.segments_page.empty()) {
    links += Element("li", "",
                     Link(std::string(root) + views->second.segments_page,
                          E("Drift over segment lengths (segment RPE) on " + sequence.title)));
  }
  if (!views->second.parameters_page.empty()) {
    links += Element("li", "",
                     Link(std::string(root) + views->second.parameters_page,
                          E("Parameters: metrics against parameter values on " + sequence.title)));
  }
  return links.str().empty() ? Html() : Element("ul", "views", links);
}

Html KeyValueTable(const std::vector<std::pair<std::string, std::string>>& rows) {
  Html body;
  for (const auto& [key, value] : rows)
    body += Element("tr", "", Element("th", "", E(key)) + Element("td", "", E(value)));
  return T("<table class=\"facts\">\n") + body + T("</table>\n");
}

}  // namespace

std::string RenderIndexPage(const SiteData& site) {
  const SweepModel& model = *site.model;
  Html body = Element("p", model.counts.failed + model.counts.unfinished > 0 ? "summary failures" : "summary",
                      E(CountsText(model.counts) + " over " + std::to_string(model.sequences.size()) +
                        " sequences and " + std::to_string(model.algorithms.size()) + " algorithms."));
  // The first answer: which is better over every data set, before the downloads and the per-sequence rankings.
  body += AcrossDataSetsSection(site.across_data_sets);
  Html downloads;
  if (site.has_summary_csv) {
    downloads +=
        Element("li", "",
                Link("summary.csv", E("summary.csv")) + E(" (one line per sequence x algorithm x parameters x noise)"));
  }
  if (site.has_runs_csv) downloads += Element("li", "", Link("runs.csv", E("runs.csv")) + E(" (one line per run)"));
  if (site.has_summary_json) downloads += Element("li", "", Link("summary.json", E("summary.json")));
  downloads += Element("li", "", Link("metrics.html", E("Metric specification")) + E(" (every metric's definition)"));
  if (site.has_validity_page) {
    downloads += Element("li", "",
                         Link("validity.html", E("Which metrics can be trusted?")) +
                             E(" (each ground-truth-free metric against the real error)"));
  }
  body += Element("ul", "downloads", downloads);
  body += OverviewSection(site, site.significance);
  for (const SequenceModel& sequence : model.sequences) {
    Html section = Element("h2", "", Link(site.layout->SequencePage(sequence.key), E("Sequence " + sequence.title)));
    section += SequenceTables(site, sequence, "");
    section += Plots(site, sequence, "");
    section += Element(
        "p", "", Link(site.layout->SequencePage(sequence.key), E("Map gallery and every run of " + sequence.title)));
    section += ViewLinks(site, sequence, "");
    Html files;
    for (const AlgorithmRow& row : sequence.rows) {
      if (row.runs.empty()) continue;
      const std::string dir = site.layout->FilesDir(row.algorithm, sequence.key);
      Html links = Link(dir + "rmse.txt", E("RMSE")) + T(" · ") + Link(dir + "corners.txt", E("corners")) + T(" · ") +
                   Link(dir + "occupied_ratio.txt", E("occupied ratio"));
      if (site.pose_logs.count({row.algorithm, sequence.key}) > 0) {
        links += T(" · ") + Link(dir + "pose_log.tum", E("pose log"));
      }
      files += Element("li", "", E(row.algorithm + ": ") + links);
    }
    section += Element("details", "", Element("summary", "", E("Text files per algorithm")) + Element("ul", "", files));
    body += Element("section", "", section);
  }
  body += site.history_section;
  return Page(site.title, "", body);
}

/// The sequence page's "Data density": median and 95th percentile of the spacing of consecutive scans.
Html DensitySection(const SequenceModel& sequence) {
  Html out = Element("h2", "", E("Data density"));
  if (!sequence.scan_spacing) {
    return out +
           Element("p", "note", E("Not recorded: no run of this table has sequence.scan_spacing in its result.json."));
  }
  const evaluator::ScanSpacing& spacing = *sequence.scan_spacing;
  Html rows;
  const auto row = [&](const std::string& what, const evaluator::SpacingPercentiles& percentiles) {
    rows += Element("tr", "",
                    Element("th", "", E(what)) + Element("td", "num", E(FormatNumber(percentiles.median))) +
                        Element("td", "num", E(FormatNumber(percentiles.p95))));
  };
  row("Time gap (s)", spacing.gap_s);
  row("Travel (m)", spacing.travel_m);
  row("Rotation (rad)", spacing.rotation_rad);
  const Html header = Element("th", "", E("Between consecutive scans")) + Element("th", "", E("median")) +
                      Element("th", "", E("95th percentile"));
  out += T("<table class=\"facts\">\n<thead>") + Element("tr", "", header) + T("</thead>\n<tbody>\n") + rows +
         T("</tbody>\n</table>\n");
  std::string note = std::to_string(spacing.steps) +
                     " steps between the consecutive scans the programs were given; travel and rotation by the "
                     "odometry poses at the scans (what a SLAM program has, not the reference). ";
  const std::optional<bool> sparse = evaluator::TooSparseForScanMatching(spacing);
  const evaluator::SparseScanThreshold threshold = evaluator::SparseScanThresholdInUse();
  if (!sparse) {
    note += "The odometry never moves: travel and rotation say nothing of the scans' density.";
  } else if (*sparse) {
    note += "Too far apart for scan matching (see the mark above the tables).";
  } else {
    note += "Dense enough for scan matching: the median travel is within " + FormatNumber(threshold.median_travel_m) +
            " m, below the spacing at which Cartographer lost most of its accuracy on the intel run "
            "(docs/data-density.md).";
  }
  return out + Element("p", "note", E(note));
}

std::string RenderSequencePage(const SiteData& site, const SequenceModel& sequence) {
  const std::string root = "../";
  Html body = SequenceTables(site, sequence, root);
  body += DensitySection(sequence);
  body += ViewLinks(site, sequence, root);
  body += Element("h2", "", E("Metric plots"));
  body += Plots(site, sequence, root);
  body += TrajectoriesSection(site, sequence, root);
  body += MapsComparedSection(site, sequence, root);
  body += Element("h2", "", E("Map gallery"));
  if (!sequence.has_reference) {
    body += Element("p", "note", E("No reference trajectory: each map is the median run by corner count."));
  }
  body += Gallery(site, sequence, root);
  body += Element("h2", "", E("Runs"));
  body += RunList(site, sequence, root);
  return Page("Sequence " + sequence.title, root, body);
}

namespace {

// A run's flat metrics, one row per metric and a column per statistic (in the worker's order), so a page of
// a hundred statistics stays a short table. Every value is shown as it was before, with its unit.
Html MetricsTable(const RunRecord& record) {
  std::vector<std::string> metrics;
  std::vector<std::string> statistics;
  std::map<std::pair<std::string, std::string>, const FlatMetric*> values;
  std::map<std::string, std::string> units;
  for (const FlatMetric& metric : record.metrics) {
    if (!metric.value) continue;
    if (std::find(metrics.begin(), metrics.end(), metric.metric) == metrics.end()) metrics.push_back(metric.metric);
    if (std::find(statistics.begin(), statistics.end(), metric.statistic) == statistics.end()) {
      statistics.push_back(metric.statistic);
    }
    values[{metric.metric, metric.statistic}] = &metric;
    // A count's unit says nothing about the metric's.
    if (metric.statistic != "n" && units.count(metric.metric) == 0) units[metric.metric] = metric.unit;
  }
  Html header = Element("th", "", E("Metric")) + Element("th", "", E("Unit"));
  for (const std::string& statistic : statistics) header += Element("th", "", E(statistic));
  header += Element("th", "", E("Specification"));
  Html rows;
  for (const std::string& metric : metrics) {
    Html cells = Element("td", "", E(metric)) + Element("td", "", E(units[metric]));
    for (const std::string& statistic : statistics) {
      const auto found = values.find({metric, statistic});
      if (found == values.end()) {
        cells += Element("td", "", E(""));
        continue;
      }
      const FlatMetric& value = *found->second;
      const bool other_unit = value.unit != units[metric] && !(statistic == "n" && value.unit == "count");
      cells += Element("td", "", E(FormatNumber(*value.value) + (other_unit ? " " + value.unit : "")));
    }
    cells += Element("td", "spec", E(MetricSpecLabel(record, metric)));
    rows += Element("tr", "", cells);
  }
  return T("<table>\n<thead>") + Element("tr", "", header) + T("</thead>\n<tbody>\n") + rows +
         T("</tbody>\n</table>\n");
}

}  // namespace

std::string RenderRunPage(const SiteData& site, std::size_t run) {
  const RunRecord& record = site.model->runs[run];
  const RunArtifacts& artifacts = site.runs[run];
  const std::string root = "../";
  // The page is runs/<name>.html and its files are in runs/<name>/: link relative to the page.
  const std::string dir = site.layout->RunDir(run).substr(std::string_view("runs/").size());
  const std::string status(RunStatusName(record.status));
  Html body = Element("p", "status-" + status,
                      E("Status: " + status + (record.failure_kind.empty() ? "" : " (" + record.failure_kind + ")") +
                        (record.reason.empty() ? "" : ": " + record.reason)));
  for (const orchestrator::RunFlag flag : record.flags) {
    body += Element(
        "p", "warning",
        E(std::string(orchestrator::RunFlagLabel(flag)) + ": " + std::string(orchestrator::RunFlagMeaning(flag))));
  }
  body += KeyValueTable({
      {"Algorithm", record.algorithm},
      {"Sequence", record.sequence},
      {"Noise", record.noise},
      {"Parameters", record.parameters.empty() ? "-" : record.parameters},
      {"Iteration", std::to_string(record.iteration)},
      {"Exit code", record.exit_code ? std::to_string(*record.exit_code) : "n/a"},
      {"Signal", record.signal ? std::to_string(*record.signal) : "none"},
      {"Wall time", FormatOptional(record.wall_s, "s")},
      {"CPU time", FormatOptional(record.cpu_s, "s")},
      // No program ran for the odometry baseline: slamsweep's own memory would be a misleading number.
      {"Peak memory", record.peak_rss_kb ? FormatNumber(*record.peak_rss_kb / 1024.0) + " MiB" : "-"},
      {"Seeding", record.seeding.empty() ? "not recorded" : record.seeding},
      {"Started", record.started_at},
      {"Finished", record.finished_at},
  });
  Html images;
  if (!artifacts.animation.empty()) {
    Html caption = E("Map being built (stage maps)");
    if (artifacts.gif) caption += E("; as a GIF: ") + Link(dir + "stages.gif", E("stages.gif"));
    images += Element(
        "figure", "map",
        Image(dir + artifacts.animation, "the map being built", "animation") + Element("figcaption", "", caption));
  } else if (artifacts.gif) {
    images += Element("figure", "map",
                      Image(dir + "stages.gif", "the map being built", "animation") +
                          Element("figcaption", "", E("Map being built (stage maps)")));
  }
  if (artifacts.overlay) {
    images += Element("figure", "map",
                      Image(dir + "trajectory.png", "estimated trajectory over the map", "overlay") +
                          Element("figcaption", "",
                                  E("Estimated trajectory over the map, with the aligned reference "
                                    "when there is one")));
  } else if (artifacts.thumbnail) {
    images +=
        Element("figure", "map",
                Image(dir + "thumbnail.png", "final map", "thumbnail") + Element("figcaption", "", E("Final map")));
  }
  if (artifacts.path_error_made) {
    images += Element("figure", "figure-small",
                      Image(root + artifacts.path_error, "translation error along the path", "figure-small") +
                          Element("figcaption", "",
                                  E("Translation error along the path: the trajectory aligned onto "
                                    "the reference as its ATE was computed, coloured by the error "
                                    "at every associated pose")));
  }
  if (!images.str().empty()) body += Element("div", "gallery", images);
  for (const std::string& note : artifacts.notes) body += Element("p", "note", E(note));
  if (artifacts.figures_left_out > 0) {
    body += Element("p", "note",
                    E("This sweep has " + std::to_string(artifacts.figures_left_out) +
                      " runs: their own figures are drawn for each table row's median run and for failed runs. "
                      "`slamsweep report RESULT_DIR --run-figures all` draws this run's too."));
  }

  body += Element("h2", "", E("Metrics"));
  if (record.metrics.empty()) {
    body += Element("p", "note", E("No metric was computed for this run."));
  } else {
    body += MetricsTable(record);
  }
  if (!record.metric_details.empty()) {
    const bool linked =
        std::find(artifacts.downloads.begin(), artifacts.downloads.end(), "result.json") != artifacts.downloads.end();
    body += Element("p", "",
                    linked ? T("Full specification and statistics of every metric: ") +
                                 Link(dir + "result.json", E("result.json")) + T(" (metric_details).")
                           : E("Full specification and statistics of every metric: result.json "
                               "(metric_details) in the run folder."));
  }
  if (!record.warnings.empty()) {
    Html items;
    for (const std::string& warning : record.warnings) items += Element("li", "", E(warning));
    body += Element("h2", "", E("Warnings")) + Element("ul", "", items);
  }
  body += Element("h2", "", E("Command line"));
  std::string command;
  for (const std::string& arg : record.command) command += (command.empty() ? "" : "\n") + arg;
  body += Element("pre", "", E(command.empty() ? "(not recorded)" : command));
  body += Element("h2", "", E("Resolved configuration (run.json)"));
  body += Element("pre", "", E(record.run_spec.dump(2)));
  body += Element("h2", "", E("Log tail"));
  if (artifacts.log_truncated)
    body += Element("p", "note", E("Only the last lines are shown; the whole log is below."));
  body += Element("pre", "log", E(artifacts.log_tail.empty() ? "(empty or missing)" : artifacts.log_tail));
  body += Element("h2", "", E("Files"));
  Html files;
  for (const std::string& name : artifacts.downloads) files += Element("li", "", Link(dir + name, E(name)));
  body += files.str().empty() ? Element("p", "note", E("No file to download.")) : Element("ul", "downloads", files);
  const std::string table_key = record.sequence + "/" + record.noise;
  body += Element(
      "p", "",
      Link(root + site.layout->SequencePage(table_key), E("Sequence " + record.sequence + ", noise " + record.noise)));
  return Page("Run " + record.run_id, root, body);
}

std::string RenderPage(std::string_view title, std::string_view root, const Html& body) {
  return RenderTemplate(kPageTemplate, {{"title", E(title)}, {"root", E(root)}, {"body", body}}).str();
}

Html ImageElement(std::string_view src, std::string_view alt, std::string_view css_class) {
  return T("<img class=\"" + EscapeHtml(css_class) + "\" src=\"" + EscapeHtml(src) + "\" alt=\"" + EscapeHtml(alt) +
           "\">");
}

Html AlgorithmSwatch(const SiteData& site, std::string_view algorithm) {
  if (site.palette == nullptr) return {};
  const AlgorithmStyle style = site.palette->StyleOf(algorithm);
  return Element("span", "swatch " + style.CssClass(), E(style.glyph)) + T(" ");
}

std::string_view StyleSheet() {
  return R"(body { font-family: sans-serif; margin: 1em 2em; color: #111; background: #fff; }
header nav { font-size: 0.9em; }
h1 { font-size: 1.5em; word-break: break-all; }
h2 { font-size: 1.2em; margin-top: 1.5em; }
table { border-collapse: collapse; margin: 0.8em 0; }
caption { text-align: left; font-style: italic; padding: 0.2em 0; }
th, td { border: 1px solid #bbb; padding: 0.25em 0.6em; text-align: left; vertical-align: top; }
thead th { background: #eee; }
td.best { background: #d8f0d8; font-weight: bold; }
tr.baseline th, tr.baseline td, tr.reference-line th, tr.reference-line td { background: #f3f3f3; color: #444;
  font-style: italic; border-top: 2px dashed #888; border-bottom: 2px dashed #888; }
.baseline-note { color: #444; font-size: 0.85em; font-weight: normal; }
ul.table-notes { color: #8a4b00; font-size: 0.9em; margin-top: 0; }
.marker { color: #064; white-space: nowrap; }
.n, .spec { color: #555; font-size: 0.85em; font-weight: normal; }
.failures, .status-failed, .status-unreadable, .status-unfinished { color: #a00; }
.status-ok { color: #060; }
.note { color: #555; font-style: italic; }
.warning { color: #8a4b00; font-size: 0.85em; font-weight: normal; }
p.sparse-data { color: #8a4b00; font-weight: bold; border-left: 4px solid #8a4b00; padding-left: 0.5em; }
.plots, .gallery { display: flex; flex-wrap: wrap; gap: 1em; }
figure { margin: 0; border: 1px solid #ddd; padding: 0.5em; }
figcaption { font-size: 0.9em; margin: 0.3em 0; word-break: break-all; }
img.plot { max-width: 640px; }
img.overlay { max-width: 480px; }
img.thumbnail, img.animation { width: 400px; height: auto; image-rendering: pixelated; }
pre { background: #f6f6f6; padding: 0.5em; overflow-x: auto; max-height: 40em; white-space: pre-wrap;
      overflow-wrap: anywhere; }
footer { margin-top: 2em; font-size: 0.8em; color: #666; }
td.verdict-tracks { background: #d8f0d8; }
td.verdict-opposite { background: #f6d6d0; }
td.verdict-unclear { background: #f4f0dc; }
td.verdict-none { color: #555; }
table.definitions td:last-child { max-width: 60em; }
table.overview tr.best td { background: #d8f0d8; }
table.overview tr.beside td { color: #555; font-style: italic; }
td.num { text-align: right; white-space: nowrap; }
p.verdict { font-weight: bold; }
div.cd-diagram { overflow-x: auto; }
table.across td:nth-child(2) { font-weight: bold; }
ul.tests { font-size: 0.85em; color: #444; }
)";
}

}  // namespace slamsweep::report::inline html
