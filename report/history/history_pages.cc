#include "report/history/history_pages.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "orchestrator/history/series_odometry.h"
#include "report/html/number_format.h"
#include "report/html/safe_name.h"
#include "report/plots/algorithm_palette.h"
#include "report/plots/gnuplot_string.h"

namespace slamsweep::report::inline history {
namespace {

using orchestrator::Finding;
using orchestrator::Verdict;

constexpr std::string_view kPageTemplate = R"(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>{{title}}</title>
<link rel="stylesheet" href="../style.css">
</head>
<body>
<header><nav><a href="../index.html">Sweep overview</a></nav><h1>{{title}}</h1></header>
<main>
{{body}}
</main>
<footer>Made by slamsweep report from the nightly history database. Lower is better for every metric. Metric definitions: <a href="../metrics.html">metric specification</a>.</footer>
</body>
</html>
)";

Html T(std::string_view markup) { return Html::Trusted(markup); }
Html E(std::string_view text) { return Html::Escape(text); }

std::string Num(double value) { return fmt::format("{:.4g}", value); }

// The odometry mode is in every title: the series of one cell on recorded and on reference odometry are two pages.
std::string SeriesTitle(const orchestrator::SeriesKey& key) {
  return fmt::format("{} on {} ({}, {} odometry): {} {}", key.algorithm, key.sequence, key.noise, key.odometry,
                     key.metric, key.statistic);
}

Html NightName(const std::string& label, const std::string& href, bool current) {
  Html name = href.empty() ? E(label) : Link(href, E(label));
  if (current) name += T(" ") + Element("span", "marker", E("this sweep"));
  return name;
}

Html Row(std::initializer_list<Html> cells, std::string_view css_class = "") {
  Html row;
  for (const Html& cell : cells) row += Element("td", "", cell);
  return Element("tr", css_class, row);
}

Html Header(std::initializer_list<std::string_view> names) {
  Html row;
  for (const std::string_view name : names) row += Element("th", "", E(name));
  return Element("thead", "", Element("tr", "", row));
}

Html FindingsTable(const std::vector<const Finding*>& findings, const std::string& unit_note) {
  Html rows;
  for (const Finding* f : findings) {
    rows += Row({E(f->algorithm), E(f->sequence), E(f->noise), E(f->odometry), E(f->metric + "." + f->statistic),
                 E(Num(f->baseline_median) + " → " + Num(f->current_median) + (f->unit.empty() ? "" : " " + f->unit)),
                 E(fmt::format("{} / {}", f->baseline_n, f->current_n)), E(fmt::format("{:.3g}", f->test.p_value)),
                 E(fmt::format("{:+.2f}", f->cliffs_delta))});
  }
  return T("<table>\n") + Element("caption", "", E(unit_note)) +
         Header({"algorithm", "sequence", "noise", "odometry", "metric", "median before → now", "n", "p",
                 "Cliff's delta"}) +
         Element("tbody", "", rows) + T("</table>\n");
}

}  // namespace

std::string HistoryPageStem(const orchestrator::SeriesKey& key) {
  return "history/" +
         SafeFileName(key.algorithm + "-" + key.sequence + "-" + key.noise + "-" + key.odometry + "-" + key.metric);
}

NightPoint SummarizeNight(const std::vector<double>& values) {
  NightPoint point;
  point.n = values.size();
  if (values.empty()) return point;
  double sum = 0.0;
  point.min = std::numeric_limits<double>::infinity();
  point.max = -std::numeric_limits<double>::infinity();
  for (const double v : values) {
    sum += v;
    point.min = std::min(point.min, v);
    point.max = std::max(point.max, v);
  }
  point.mean = sum / static_cast<double>(values.size());
  if (values.size() >= 2) {
    double squares = 0.0;
    for (const double v : values) squares += (v - point.mean) * (v - point.mean);
    point.std = std::sqrt(squares / static_cast<double>(values.size() - 1));
  }
  return point;
}

std::string RenderHistoryPage(const HistorySeriesPage& page) {
  const std::string title = SeriesTitle(page.key);
  Html body;
  // The page is history/<stem>.html and its plot history/<stem>.png: the src is relative to the page.
  const std::string plot_src = std::filesystem::path(page.plot).filename().string();
  if (page.plot_made) {
    body += T("<figure>") +
            T("<img class=\"plot\" src=\"" + EscapeHtml(plot_src) + "\" alt=\"" +
              EscapeHtml("history plot of " + title) + "\">") +
            Element("figcaption", "", E("Mean per night with the min–max band of the iterations.")) + T("</figure>\n");
  } else {
    body += Element("p", "note", E("No plot: " + (page.plot_note.empty() ? "not drawn" : page.plot_note)));
  }
  if (!orchestrator::IsComparableOdometryMode(page.key.odometry)) {
    body += Element("p", "note",
                    E("Odometry mode " + page.key.odometry +
                      ": these nights were recorded before the history kept the odometry mode and their result "
                      "directories cannot say it (or their runs had both modes), so their points may mix runs on "
                      "the recorded odometry with runs handed the reference. They are shown, never compared."));
  }
  const std::string unit = page.key.unit.empty() ? "" : " (" + page.key.unit + ")";
  Html rows;
  for (const NightPoint& night : page.nights) {
    rows += Row({NightName(night.label, night.report_href, night.current), E(night.started_at),
                 E(std::to_string(night.n)), E(night.n > 0 ? Num(night.mean) : "–"),
                 E(night.std ? Num(*night.std) : "–"), E(night.n > 0 ? Num(night.min) : "–"),
                 E(night.n > 0 ? Num(night.max) : "–"), E(std::to_string(night.failed_runs))},
                night.failed_runs > 0 ? "failures" : "");
  }
  body += Element("h2", "", E("Nights"));
  body += T("<table>\n") + Header({"night", "started", "ok runs", "mean" + unit, "std", "min", "max", "failed runs"}) +
          Element("tbody", "", rows) + T("</table>\n");
  body += Element("p", "note",
                  E("A night links to its own report when that report can be reached from here; otherwise it is "
                    "named only."));
  return RenderTemplate(kPageTemplate, {{"title", E("History: " + title)}, {"body", body}}).str();
}

Html RenderHistorySection(const HistorySection& section) {
  Html body = Element("h2", "", E("Nightly history"));
  Html nights;
  for (const NightLink& night : section.nights) {
    nights += Element("li", "",
                      NightName(night.label, night.report_href, night.current) +
                          E(night.started_at.empty() ? "" : " (started " + night.started_at + ")"));
  }
  body += Element("p", "", E(fmt::format("{} nights in {}.", section.nights.size(), section.history_file.string())));
  if (!section.nights.empty()) body += Element("ul", "nights", nights);

  if (section.comparison) {
    const orchestrator::Comparison& c = *section.comparison;
    std::vector<const Finding*> regressions;
    std::vector<const Finding*> improvements;
    for (const Finding& f : c.findings) {
      if (f.verdict == Verdict::kRegression) regressions.push_back(&f);
      if (f.verdict == Verdict::kImprovement) improvements.push_back(&f);
    }
    const std::string test =
        fmt::format("two-sided Mann-Whitney U, p < {}, |Cliff's delta| ≥ {}", c.options.alpha, c.options.min_effect);
    body += Element("h3", "", E("Compared with night " + c.baseline_label));
    body += Element(
        "p", regressions.empty() ? "summary" : "summary failures",
        E(fmt::format("{} regressions, {} improvements, {} unchanged, {} not comparable ({}).", regressions.size(),
                      improvements.size(), c.Count(Verdict::kUnchanged), c.Count(Verdict::kNotComparable), test)));
    if (!regressions.empty()) body += Element("div", "failures", FindingsTable(regressions, "Regressions"));
    if (!improvements.empty()) body += Element("div", "status-ok", FindingsTable(improvements, "Improvements"));
  } else if (!section.comparison_note.empty()) {
    body += Element("p", "note", E(section.comparison_note));
  }

  Html links;
  for (const HistorySeriesPage& page : section.pages) {
    links += Element("li", "",
                     Link(page.page, E(SeriesTitle(page.key))) + E(fmt::format(" ({} nights)", page.nights.size())));
  }
  if (!section.pages.empty()) {
    body += Element("details", "", Element("summary", "", E("History of every series")) + Element("ul", "", links));
  }
  return Element("section", "history", body);
}

std::string HistoryPlotScript(const HistorySeriesPage& page, const std::filesystem::path& png) {
  bool positive = true;
  std::string rows;
  std::string xtics;
  std::size_t x = 0;
  for (const NightPoint& night : page.nights) {
    ++x;
    if (!xtics.empty()) xtics += ", ";
    xtics += fmt::format("{} {}", GnuplotQuoted(night.label), x);
    if (night.n == 0) continue;
    positive = positive && night.min > 0.0;
    rows += fmt::format("{} {} {} {}\n", x, night.mean, night.min, night.max);
  }
  std::string title = SeriesTitle(page.key);
  if (!positive) title += " (values <= 0: linear axis)";
  std::string script = "reset\n";
  script += "set terminal pngcairo noenhanced size 800,420 font 'Sans,10'\n";
  script += fmt::format("set output {}\n", GnuplotQuoted(png.string()));
  script += fmt::format("set title {} noenhanced\n", GnuplotQuoted(title));
  script += fmt::format("set ylabel {} noenhanced\n",
                        GnuplotQuoted(page.key.metric + (page.key.unit.empty() ? "" : " (" + page.key.unit + ")")));
  // Room on the right and below for the last rotated night label.
  script += "set key top left\nset grid ytics\nset border 3\nset ytics nomirror\nset rmargin 10\nset bmargin 7\n";
  script += fmt::format("set xrange [0.5:{}]\n", static_cast<double>(page.nights.size()) + 0.5);
  if (!xtics.empty()) script += fmt::format("set xtics ({}) nomirror rotate by -30 left\n", xtics);
  if (positive) script += "set logscale y\n";
  if (rows.empty()) {
    // gnuplot refuses an empty plot: one point outside the x range.
    script += "$d << EOD\n-10 1 1 1\nEOD\nplot $d using 1:2 with points notitle\n";
  } else {
    script += "$d << EOD\n" + rows + "EOD\n";
    // The algorithm's colour and marker, as in the report's other plots (its preferred palette slot).
    const AlgorithmStyle style = StyleOfSlot(PreferredSlot(page.key.algorithm));
    script += fmt::format(
        "plot $d using 1:3:4 with filledcurves fillcolor rgb '#E3E3E3' title 'min-max', "
        "$d using 1:2 with linespoints pointtype {} linecolor rgb '{}' linewidth 2 title 'mean'\n",
        style.point_type, style.Hex());
  }
  script += "unset output\n";
  return script;
}

}  // namespace slamsweep::report::inline history
