#include "report/html/across_data_sets_section.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "report/html/number_format.h"

namespace slamsweep::report::inline html {
namespace {

using html_shorthand::E;
using html_shorthand::T;

std::string SettingTitle(const DataSetVerdict& v) {
  return "noise " + v.noise + ", " + (v.odometry.empty() ? std::string("unrecorded") : v.odometry) + " odometry";
}

// Runs of contestants (sorted by mean rank) with no pair found different: maximal [first, last] with last > first.
std::vector<std::pair<std::size_t, std::size_t>> Cliques(const DataSetVerdict& v) {
  const std::size_t k = v.contestants.size();
  const auto different = [&](std::size_t a, std::size_t b) {
    return std::find(v.different.begin(), v.different.end(), std::make_pair(a, b)) != v.different.end();
  };
  std::vector<std::pair<std::size_t, std::size_t>> cliques;
  for (std::size_t first = 0; first < k; ++first) {
    std::size_t last = first;
    while (last + 1 < k && !different(first, last + 1)) ++last;
    if (last > first && (cliques.empty() || last > cliques.back().second)) cliques.emplace_back(first, last);
  }
  return cliques;
}

Html VerdictBlock(const DataSetVerdict& v) {
  Html block = Element("h3", "", E("Across data sets: " + SettingTitle(v)));
  const bool shown_difference = v.tested && !v.different.empty();
  block += Element("p", shown_difference ? "verdict" : "note", E(v.verdict));
  if (v.tested) block += Element("div", "cd-diagram", CriticalDifferenceDiagram(v));
  if (v.contestants.size() >= 2 && v.used.size() >= 2) {
    Html header = Element("th", "", E("Mean rank")) + Element("th", "", E("Contestant"));
    for (std::size_t d = 0; d < v.used.size(); ++d) {
      header += Element("th", "", E(v.used[d] + (v.used_metrics[d].empty() ? "" : ": " + v.used_metrics[d])));
    }
    Html rows = Element("tr", "", header);
    for (const DataSetContestant& c : v.contestants) {
      Html cells = Element("td", "num", E(fmt::format("{:.2f}", c.mean_rank))) + Element("td", "", E(c.label));
      for (std::size_t d = 0; d < c.values.size(); ++d) {
        const std::string rank = d < c.ranks.size() ? fmt::format(" (rank {:g})", c.ranks[d]) : "";
        cells += Element("td", "num", E(FormatNumber(c.values[d]) + rank));
      }
      rows += Element("tr", "", cells);
    }
    block += Element("table", "across", rows);
  }
  Html choices;
  for (const DataSetChoice& choice : v.data_sets) {
    choices += Element("li", choice.used ? "" : "note",
                       E((choice.used ? "counted: " : "left out: ") + choice.table_title + " — " + choice.why));
  }
  block += Element("p", "", E("Data sets:")) + Element("ul", "datasets", choices);
  if (!v.left_out.empty()) {
    Html rows;
    for (const std::string& line : v.left_out) rows += Element("li", "", E(line));
    block += Element("p", "", E("Rows not ranked on every data set, left out of the comparison:")) +
             Element("ul", "datasets", rows);
  }
  if (v.tested) {
    const evaluator::FriedmanResult& f = v.friedman;
    block += Element(
        "p", "note",
        E(fmt::format("{} contestants over {} data sets. Friedman chi-square = {:.3g} ({} df, p = {:.3g}){}; "
                      "Iman-Davenport F = {:.3g} ({} and {} df, p = {:.3g}); Nemenyi's critical difference at {:g} "
                      "= {:.2f} ranks (no tie correction).",
                      f.contestants, f.data_sets, f.chi_square, f.contestants - 1, f.chi_square_p,
                      f.tie_correction < 1.0
                          ? fmt::format(", tie-corrected (divided by {:.4f}: tied values share their mean rank)",
                                        f.tie_correction)
                          : ", no ties to correct for",
                      f.iman_davenport_f, f.contestants - 1, (f.contestants - 1) * (f.data_sets - 1),
                      f.iman_davenport_p, v.alpha, v.critical_difference)));
  }
  return Element("div", "across", block);
}

}  // namespace

Html CriticalDifferenceDiagram(const DataSetVerdict& v) {
  const std::size_t k = v.contestants.size();
  if (k < 2) return {};
  std::size_t longest = 0;
  for (const DataSetContestant& c : v.contestants) longest = std::max(longest, c.label.size() + 7);
  const double label_width = std::min(280.0, 6.6 * static_cast<double>(longest)) + 16.0;
  const double axis_width = std::max(300.0, 60.0 * static_cast<double>(k - 1));
  const double left = label_width + 10.0;
  const double right_end = left + axis_width;
  const double width = right_end + label_width + 10.0;
  const double step = axis_width / static_cast<double>(k - 1);
  const auto x = [&](double rank) { return left + (rank - 1.0) * step; };
  const std::vector<std::pair<std::size_t, std::size_t>> cliques = Cliques(v);
  const std::size_t half = (k + 1) / 2;
  const double axis_y = 56.0;
  const double first_label_y = axis_y + 16.0 + 7.0 * static_cast<double>(cliques.size()) + 12.0;
  const double height = first_label_y + 20.0 * static_cast<double>(half) + 6.0;

  std::string svg = fmt::format(
      R"(<svg class="cd" width="{0:.0f}" height="{1:.0f}" viewBox="0 0 {0:.0f} {1:.0f}" role="img" font-family="sans-serif" font-size="12">)",
      width, height);
  svg +=
      "<title>" +
      EscapeHtml(fmt::format("Critical-difference diagram: mean ranks of {} contestants over {} data sets, Nemenyi's "
                             "critical difference {:.2f}",
                             k, v.used.size(), v.critical_difference)) +
      "</title>";
  // The critical difference as a bar from rank 1, cut at the axis' end when it is longer.
  const double cd_end = std::min(x(1.0 + v.critical_difference), right_end);
  svg +=
      fmt::format(R"(<line x1="{:.1f}" y1="22" x2="{:.1f}" y2="22" stroke="#a00" stroke-width="2"/>)", x(1.0), cd_end);
  svg += fmt::format(R"(<line x1="{0:.1f}" y1="17" x2="{0:.1f}" y2="27" stroke="#a00"/>)", x(1.0));
  svg += fmt::format(R"(<line x1="{0:.1f}" y1="17" x2="{0:.1f}" y2="27" stroke="#a00"/>)", cd_end);
  const bool cut = x(1.0 + v.critical_difference) > right_end;
  svg += fmt::format(R"(<text x="{:.1f}" y="13" fill="#a00">{}</text>)", x(1.0),
                     EscapeHtml(fmt::format("CD = {:.2f}{}", v.critical_difference,
                                            cut ? " ranks: longer than the axis, no pair can differ" : " ranks")));
  // The axis, 1 (best) at the left.
  svg += fmt::format(R"(<line x1="{:.1f}" y1="{:.0f}" x2="{:.1f}" y2="{:.0f}" stroke="#222"/>)", left, axis_y,
                     right_end, axis_y);
  for (std::size_t r = 1; r <= k; ++r) {
    svg += fmt::format(R"(<line x1="{0:.1f}" y1="{1:.0f}" x2="{0:.1f}" y2="{2:.0f}" stroke="#222"/>)",
                       x(static_cast<double>(r)), axis_y - 5.0, axis_y);
    svg += fmt::format(R"(<text x="{:.1f}" y="{:.0f}" text-anchor="middle">{}</text>)", x(static_cast<double>(r)),
                       axis_y - 9.0, r);
  }
  // Runs of contestants no test tells apart, as thick lines under the axis.
  for (std::size_t c = 0; c < cliques.size(); ++c) {
    const double y = axis_y + 10.0 + 7.0 * static_cast<double>(c);
    svg += fmt::format(R"(<line x1="{:.1f}" y1="{:.0f}" x2="{:.1f}" y2="{:.0f}" stroke="#222" stroke-width="4"/>)",
                       x(v.contestants[cliques[c].first].mean_rank) - 4.0, y,
                       x(v.contestants[cliques[c].second].mean_rank) + 4.0, y);
  }
  // Each contestant: a line from its mean rank down to its label, the better half at the left.
  for (std::size_t i = 0; i < k; ++i) {
    const DataSetContestant& c = v.contestants[i];
    const bool at_left = i < half;
    const double y = first_label_y + 20.0 * static_cast<double>(at_left ? i : k - 1 - i);
    const double xr = x(c.mean_rank);
    const double end = at_left ? left - 8.0 : right_end + 8.0;
    svg +=
        fmt::format(R"(<polyline points="{0:.1f},{1:.0f} {0:.1f},{2:.0f} {3:.1f},{2:.0f}" fill="none" stroke="#555"/>)",
                    xr, axis_y, y, end);
    svg += fmt::format(R"(<circle cx="{:.1f}" cy="{:.0f}" r="3" fill="#222"/>)", xr, axis_y);
    svg +=
        fmt::format(R"(<text x="{:.1f}" y="{:.0f}" text-anchor="{}">{}</text>)", at_left ? end - 4.0 : end + 4.0,
                    y + 4.0, at_left ? "end" : "start", EscapeHtml(fmt::format("{} ({:.2f})", c.label, c.mean_rank)));
  }
  svg += "</svg>";
  return T(svg);
}

Html AcrossDataSetsSection(const std::vector<DataSetVerdict>& verdicts) {
  Html blocks;
  for (const DataSetVerdict& v : verdicts) {
    if (v.data_sets.size() >= 2) blocks += VerdictBlock(v);
  }
  if (blocks.str().empty()) return {};
  Html section = Element("h2", "", E("Which is better overall?"));
  section += Element(
      "p", "note",
      E("Demšar's comparison over data sets: within each data set the contestants are ranked by their mean of the "
        "headline metric over iterations (1 = lowest error; tied values share the mean of their ranks), and the "
        "ranks are averaged. The Friedman test (with Iman and Davenport's F) asks whether the contestants differ at "
        "all; Nemenyi's critical difference at 0.05 says which pairs do. A data set counts when its error is measured "
        "against an independent reference (Kuemmerle's relations, or exact ground truth): ATE against a corrected "
        "log is agreement with GMapping, whose output it is. Several logs of one physical run count once, by the "
        "densest. Contestants are the rows ranked on every data set; the odometry baseline, reference and published "
        "rows and rows with failed or marked runs are never contestants. One verdict per noise setting and odometry "
        "mode."));
  section += blocks;
  return Element("section", "across", section);
}

}  // namespace slamsweep::report::inline html
