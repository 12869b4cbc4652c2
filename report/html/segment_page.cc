// sequences/<table>/segments.html: drift over segment lengths (report/html/view_pages.h).
#include "report/html/number_format.h"
#include "report/html/view_pages.h"

namespace slamsweep::report::inline html {
namespace {

using html_shorthand::E;
using html_shorthand::T;

constexpr std::string_view kSegmentPageRoot = "../../";

Html Figure(const TableViews& views, const std::string& id, std::string_view caption) {
  const auto found = views.figures.find(id);
  if (found == views.figures.end()) return {};
  const PlotArtifact& figure = found->second;
  Html body = figure.made ? ImageElement(std::string(kSegmentPageRoot) + figure.path, figure.title, "figure")
                          : Element("p", "note", E("Figure not available: " + figure.note));
  return Element("figure", "figure", body + Element("figcaption", "", E(caption)));
}

/// One table of the page: a row per table row, a column per length.
Html LengthTable(const SiteData& site, const SequenceModel& sequence, const SegmentTable& table,
                 MeanStd SegmentCell::*value, bool mark_best, std::string_view caption, std::string_view unit) {
  Html header = Element("th", "", E("Algorithm"));
  for (const double length : table.lengths_m) header += Element("th", "", E(LengthLabel(length)));
  Html rows;
  for (const SegmentRow& row : table.rows) {
    const AlgorithmRow& algorithm = sequence.rows[row.row];
    Html name = AlgorithmSwatch(site, algorithm.name) + E(algorithm.algorithm);
    for (const orchestrator::RunFlag flag : algorithm.flags) {
      name += T("<br>") + Element("span", "warning",
                                  E(std::string(orchestrator::RunFlagLabel(flag)) + ": " +
                                    std::string(orchestrator::RunFlagMeaning(flag))));
    }
    for (const std::string& note : row.notes) name += T("<br>") + Element("span", "warning", E(note));
    Html line = Element("th", "", name);
    for (const SegmentCell& cell : row.cells) {
      const MeanStd& summary = cell.*value;
      if (summary.n == 0) {
        line += Element("td", "missing", E("n/a"));
        continue;
      }
      Html content = E(FormatMeanStd(summary) + " " + std::string(unit));
      content += T(" ") + Element("span", "n", E("n=" + std::to_string(summary.n)));
      const bool best = mark_best && cell.best;
      if (best) content += T(" ") + Element("span", "marker", E("▼ best"));
      line += Element("td", best ? "best" : "", content);
    }
    rows += Element("tr", "", line) + T("\n");
  }
  return T("<table>\n") + Element("caption", "", E(caption)) + T("\n<thead>") + Element("tr", "", header) +
         T("</thead>\n<tbody>\n") + rows + T("</tbody>\n</table>\n");
}

}  // namespace

std::string RenderSegmentPage(const SiteData& site, const SequenceModel& sequence, const TableViews& views) {
  const SegmentTable& table = *views.segments;
  Html body = Element("p", "",
                      Link(std::string(kSegmentPageRoot) + site.layout->SequencePage(sequence.key),
                           E("Back to the tables of " + sequence.title)));
  body += Element(
      "p", "",
      E("How far each algorithm drifts over a stretch of path, by the length of the stretch (the relative pose error "
        "over segments, as the KITTI odometry benchmark and rpg_trajectory_evaluation report it). For each length L, "
        "every pose i of the reference is paired with the pose j whose path along the reference from i is nearest "
        "to L (within ±10 %): the segments are chosen on the reference, so every run of this sequence is scored on "
        "the same stretches whatever its own errors (evo_rpe --delta L --delta_unit m --all_pairs "
        "--pairs_from_reference). A segment's error is E = (Q_i⁻¹ Q_j)⁻¹ (P_i⁻¹ P_j) with Q the reference and P the "
        "estimate: its translation in metres and in % of L, and its rotation angle in degrees per metre of L. "
        "No alignment is needed: a rigid transform of the estimate does not change E."));
  body += Element("p", "", E("Segment lengths: " + table.lengths_from + "."));
  for (const std::string& note : table.notes) body += Element("p", "warning", E(note));

  body += Element("h2", "", E("Drift per segment length"));
  body += LengthTable(site, sequence, table, &SegmentCell::mean_drift_pct, true,
                      "Translation drift (% of segment length): each run's mean over its segments, then mean ± sample "
                      "std over the runs of the row (n runs); lowest mean marked per length",
                      "%");
  body += LengthTable(site, sequence, table, &SegmentCell::mean_rotation_deg_per_m, false,
                      "Rotation drift (deg per metre of segment): each run's mean, then mean ± sample std over runs",
                      "deg/m");

  body += Element("h2", "", E("Figures"));
  body +=
      Element("p", "legend-note",
              E("Colours and markers are the algorithms' throughout this report; the legends follow the table's row "
                "order. A second row of the same algorithm (other parameter values) is hatched or dashed. Boxes pool "
                "every segment of every successful run of a row: quartiles, median (black line), mean (the "
                "algorithm's marker), whiskers to the furthest segment within 1.5 interquartile ranges."));
  body += Element(
      "div", "plots",
      Figure(views, SegmentFigureId("translation"), "Translation error of every segment (m), per segment length") +
          Figure(views, SegmentFigureId("rotation"), "Rotation error of every segment (deg/m), per segment length") +
          Figure(views, SegmentFigureId("drift"),
                 "Translation drift (%) against segment length: mean ± std over runs of each run's mean drift"));
  return RenderPage("Drift over segment lengths: " + sequence.title, kSegmentPageRoot, body);
}

}  // namespace slamsweep::report::inline html
