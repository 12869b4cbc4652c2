#include "report/html/overview_section.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "report/html/number_format.h"

namespace slamsweep::report::inline html {
namespace {

using html_shorthand::E;
using html_shorthand::T;

struct Scale {
  double low = 0.0;
  double high = 1.0;
  double X(double value) const { return 4.0 + 152.0 * (value - low) / (high - low); }
};

Scale ScaleOf(const std::vector<RankedEntry>& entries) {
  Scale scale{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (const RankedEntry& entry : entries) {
    if (entry.summary.n == 0) continue;
    scale.low = std::min(scale.low, entry.interval ? entry.interval->low : entry.summary.mean);
    scale.high = std::max(scale.high, entry.interval ? entry.interval->high : entry.summary.mean);
  }
  if (!std::isfinite(scale.low)) return Scale{};
  if (scale.high <= scale.low) scale.high = scale.low + 1.0;
  return scale;
}

// A 160 x 14 figure: the interval as a line, the mean as a dot (hollow for rows beside the ranking).
Html DotPlot(const RankedEntry& entry, const Scale& scale) {
  if (entry.summary.n == 0) return E("");
  std::string svg = R"(<svg class="dot" width="160" height="14" viewBox="0 0 160 14" role="img">)";
  if (entry.interval) {
    svg += fmt::format(R"(<line x1="{:.1f}" y1="7" x2="{:.1f}" y2="7" stroke="#555" stroke-width="1.5"/>)",
                       scale.X(entry.interval->low), scale.X(entry.interval->high));
  }
  svg += fmt::format(R"(<circle cx="{:.1f}" cy="7" r="3.5" fill="{}" stroke="#222"/>)", scale.X(entry.summary.mean),
                     entry.rank ? "#222" : "#fff");
  svg += "</svg>";
  return T(svg);
}

std::string IntervalText(const RankedEntry& entry, const AlgorithmRow& row) {
  if (entry.summary.n == 0) return "n/a";
  // A published figure's spread is over the log's relations, not over runs.
  if (row.kind == RowKind::kPublished && entry.summary.std) {
    return FormatNumber(entry.summary.mean) + " ± " + FormatNumber(*entry.summary.std) + " (over relations)";
  }
  if (!entry.interval) return FormatNumber(entry.summary.mean) + " (one value)";
  return FormatNumber(entry.summary.mean) + " [" + FormatNumber(entry.interval->low) + ", " +
         FormatNumber(entry.interval->high) + "]";
}

Html TestLine(const char* against, const RowTest& test) {
  if (test.identical) return Element("li", "", E(std::string(against) + " " + test.other + ": identical runs, a tie"));
  return Element("li", "",
                 E(fmt::format("{} {}: {} ({}{}), one-sided p = {:.3g}, Holm-adjusted {:.3g}, Cliff's delta {:.2f}; "
                               "smallest p these runs can reach {:.3g}",
                               against, test.other, test.test, test.paired ? "paired by iteration seed, " : "",
                               test.paired ? fmt::format("{} pairs", test.n)
                                           : fmt::format("{} against {} runs", test.n, test.n_other),
                               test.p_value, test.p_holm, test.cliffs_delta, test.min_p)));
}

}  // namespace

Html OverviewSection(const SiteData& site, const std::vector<TableSignificance>& significance) {
  const SweepModel& model = *site.model;
  Html section = Element("h2", "", E("Which is better, and is the difference real?"));
  section += Element("p", "note",
                     E("Per sequence and noise setting: contestants ranked by the headline metric (the relations "
                       "error where relations exist, else ATE), mean with its 95 % t interval over iterations. The "
                       "odometry baseline, reference and published rows and rows with failed or marked runs are "
                       "shown below the ranking, never ranked. The best row is tested one-sided against the runner-"
                       "up and the baseline (Wilcoxon signed-rank where runs pair by iteration seed, else Mann-"
                       "Whitney U), Holm-corrected over every test of this report at 0.05."));
  for (std::size_t s = 0; s < significance.size() && s < model.sequences.size(); ++s) {
    const TableSignificance& t = significance[s];
    const SequenceModel& table = model.sequences[s];
    Html block = Element("h3", "", Link(site.layout->SequencePage(table.key), E(table.title)));
    if (!t.column) {
      block += Element("p", "note", E(t.verdict));
      section += Element("div", "overview", block);
      continue;
    }
    const MetricColumn& column = table.trajectory_columns[*t.column];
    const std::string unit = column.unit.empty() ? "" : " (" + column.unit + ")";
    Html rows = Element("tr", "",
                        Element("th", "", E("Rank")) + Element("th", "", E("Row")) +
                            Element("th", "", E(column.title + unit + ", mean [95 % interval]")) +
                            Element("th", "", E("ok / runs")) + Element("th", "", E("")) +
                            Element("th", "", E("Not ranked because")));
    const Scale scale = ScaleOf(t.entries);
    for (const RankedEntry& entry : t.entries) {
      const AlgorithmRow& row = table.rows[entry.row];
      rows += Element(
          "tr", entry.rank ? (*entry.rank == 1 ? "best" : "") : "beside",
          Element("td", "", E(entry.rank ? std::to_string(*entry.rank) : "–")) + Element("td", "", E(row.algorithm)) +
              Element("td", "num", E(IntervalText(entry, row))) +
              Element("td", "num",
                      E(entry.n_runs == 0 ? std::string("–") : fmt::format("{} / {}", entry.n_ok, entry.n_runs))) +
              Element("td", "", DotPlot(entry, scale)) + Element("td", "", E(entry.unranked_because)));
    }
    block += Element("table", "overview", rows);
    block += Element("p", t.vs_runner_up && t.vs_runner_up->p_holm <= 0.05 ? "verdict" : "note", E(t.verdict));
    Html tests;
    if (t.vs_runner_up) tests += TestLine("against the runner-up", *t.vs_runner_up);
    if (t.vs_baseline) tests += TestLine("against the odometry baseline", *t.vs_baseline);
    if (!tests.str().empty()) block += Element("ul", "tests", tests);
    section += Element("div", "overview", block);
  }
  return Element("section", "overview", section);
}

}  // namespace slamsweep::report::inline html
