// sequences/<table>/parameters.html: metrics against parameter values (report/html/view_pages.h).
#include "report/html/number_format.h"
#include "report/html/view_pages.h"

namespace slamsweep::report::inline html {
namespace {

using html_shorthand::E;
using html_shorthand::T;

constexpr std::string_view kParametersPageRoot = "../../";

/// The drawn parameters' values of a row of the slice: "0.5" for one parameter (its name heads the
/// column), "a=1, b=fast" for two.
std::string Coordinates(const ParameterSweep& sweep, const ParameterSlice& slice, std::size_t row) {
  for (std::size_t y = 0; y < slice.cells.size(); ++y) {
    for (std::size_t x = 0; x < slice.cells[y].size(); ++x) {
      if (slice.cells[y][x] != row) continue;
      if (sweep.axes.size() == 1) return ParameterValueText(sweep.axes[0].values[x]);
      return sweep.axes[0].name + "=" + ParameterValueText(sweep.axes[0].values[x]) + ", " + sweep.axes[1].name + "=" +
             ParameterValueText(sweep.axes[1].values[y]);
    }
  }
  return "?";
}

std::string ValueText(const SequenceModel& sequence, std::size_t row, const ColumnRef& column) {
  const MeanStd& summary = CellOf(sequence.rows[row], column).summary;
  const std::string& unit = ColumnOf(sequence, column).unit;
  return FormatMeanStd(summary) + (unit.empty() ? "" : " " + unit) + " (n=" + std::to_string(summary.n) + ")";
}

/// The best value of every metric among the rows of one slice: all other parameters are fixed there.
Html BestTable(const SequenceModel& sequence, const ParameterSweep& sweep, const ParameterSlice& slice) {
  const std::string values = sweep.axes.size() == 1 ? sweep.axes[0].name : "values";
  Html header;
  for (const std::string& name : {std::string("Metric"), "Best " + values, std::string("Its mean ± std"),
                                  "Next best " + values, std::string("Note")}) {
    header += Element("th", "", E(name));
  }
  Html rows;
  const std::vector<std::size_t> slice_rows = slice.Rows();
  for (const ColumnRef& column : TableColumns(sequence)) {
    const MetricColumn& metric = ColumnOf(sequence, column);
    const BestValue best = FindBest(sequence, slice_rows, column);
    Html line = Element("th", "", E(metric.title + (metric.spec.empty() ? "" : ", " + metric.spec)));
    if (!best.row) {
      line += Element("td", "missing", E("no value")) + Element("td", "", E("")) + Element("td", "", E("")) +
              Element("td", "", E(metric.best_withheld.empty() ? "" : metric.best_withheld));
      rows += Element("tr", "", line) + T("\n");
      continue;
    }
    line += Element("td", best.tie ? "" : "best", E(Coordinates(sweep, slice, *best.row)));
    line += Element("td", "", E(ValueText(sequence, *best.row, column)));
    line += Element("td", "",
                    best.runner_up ? E(Coordinates(sweep, slice, *best.runner_up) + ": " +
                                       ValueText(sequence, *best.runner_up, column))
                                   : E("-"));
    std::string note;
    if (!best.runner_up) {
      note = "the only value with a result";
    } else if (best.tie) {
      note = "tie: no value is best";
    } else if (!best.clear) {
      note = "within noise";
    }
    line += Element("td", "", E(note));
    rows += Element("tr", "", line) + T("\n");
  }
  return T("<table>\n") +
         Element("caption", "",
                 E("Best value per metric: the lowest mean (every metric here is lower is better) among these rows "
                   "only; rows with a run mark (odometry = reference, stale, unisolated) or a failed run are never "
                   "best, nor "
                   "are ground-truth-free metrics the validity study does not support. \"within noise\": the next best "
                   "mean is "
                   "within one standard deviation of it, or a value has a single run; \"tie\": equal means.")) +
         T("\n<thead>") + Element("tr", "", header) + T("</thead>\n<tbody>\n") + rows + T("</tbody>\n</table>\n");
}

Html Figures(const TableViews& views, const SequenceModel& sequence, std::size_t sweep, std::size_t slice) {
  Html figures;
  const std::vector<ColumnRef> columns = TableColumns(sequence);
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const auto found = views.figures.find(ParameterFigureId(sweep, slice, c));
    if (found == views.figures.end()) continue;
    const PlotArtifact& figure = found->second;
    Html body = figure.made ? ImageElement(std::string(kParametersPageRoot) + figure.path, figure.title, "figure-small")
                            : Element("p", "note", E("Figure not available: " + figure.note));
    figures += Element("figure", "figure-small", body + Element("figcaption", "", E(figure.title)));
  }
  return Element("div", "plots", figures);
}

}  // namespace

std::string RenderParametersPage(const SiteData& site, const SequenceModel& sequence, const TableViews& views) {
  const ParameterTable& table = *views.parameters;
  Html body = Element("p", "",
                      Link(std::string(kParametersPageRoot) + site.layout->SequencePage(sequence.key),
                           E("Back to the tables of " + sequence.title)));
  body +=
      Element("p", "",
              E("Which parameter value to ship: each metric of the tables against the values of the parameters an "
                "algorithm was swept over, on this sequence and noise setting. Every point or cell is one row of the "
                "tables (mean ± sample std over its runs). Rows are compared only with rows of the same algorithm "
                "whose other parameters are the same. One varying parameter gives a curve per metric, two give a "
                "heatmap (light = lower = better); with three or more, the two with the most values are drawn and "
                "there is one heatmap per combination of the others."));
  for (std::size_t s = 0; s < table.sweeps.size(); ++s) {
    const ParameterSweep& sweep = table.sweeps[s];
    std::string drawn = sweep.axes[0].name + (sweep.axes.size() > 1 ? " × " + sweep.axes[1].name : "");
    body += Element("h2", "", AlgorithmSwatch(site, sweep.algorithm) + E(sweep.algorithm + ": " + drawn));
    if (!sweep.constant.empty()) body += Element("p", "", E("The same in every row: " + sweep.constant + "."));
    if (!sweep.sliced.empty()) {
      std::string others;
      for (const ParameterAxis& axis : sweep.sliced) others += (others.empty() ? "" : ", ") + axis.name;
      body += Element("p", "warning",
                      E(std::to_string(sweep.axes.size() + sweep.sliced.size()) + " parameters vary: heatmaps show " +
                        drawn + ", one set per combination of " + others + " (" + std::to_string(sweep.slices.size()) +
                        " combinations run); a best value is named within each combination only."));
    }
    for (std::size_t slice = 0; slice < sweep.slices.size(); ++slice) {
      if (!sweep.sliced.empty()) body += Element("h3", "", E("With " + SliceText(sweep, sweep.slices[slice])));
      body += BestTable(sequence, sweep, sweep.slices[slice]);
      body += Figures(views, sequence, s, slice);
    }
  }
  return RenderPage("Parameters: " + sequence.title, kParametersPageRoot, body);
}

}  // namespace slamsweep::report::inline html
