#include "report/html/validity_page.h"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <map>
#include <set>
#include <system_error>

#include <fmt/format.h>

#include "report/html/number_format.h"
#include "report/html/safe_name.h"
#include "orchestrator/store/validity_table.h"

namespace slamsweep::report::inline html {
namespace {

namespace fs = std::filesystem;
namespace ev = slamsweep::evaluator;

using html_shorthand::E;
using html_shorthand::T;

/// "n2" before "n10": digit runs compare as numbers, so graded noise names keep their order.
bool NaturalLess(const std::string& a, const std::string& b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (std::isdigit(static_cast<unsigned char>(a[i])) && std::isdigit(static_cast<unsigned char>(b[j]))) {
      std::size_t i_end = i, j_end = j;
      while (i_end < a.size() && std::isdigit(static_cast<unsigned char>(a[i_end]))) ++i_end;
      while (j_end < b.size() && std::isdigit(static_cast<unsigned char>(b[j_end]))) ++j_end;
      std::string_view da(a.data() + i, i_end - i), db(b.data() + j, j_end - j);
      while (da.size() > 1 && da.front() == '0') da.remove_prefix(1);
      while (db.size() > 1 && db.front() == '0') db.remove_prefix(1);
      if (da.size() != db.size()) return da.size() < db.size();
      if (da != db) return da < db;
      i = i_end, j = j_end;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i, ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

std::string QuantityTitle(std::string_view key) {
  const ev::ValidityQuantity* quantity = ev::FindValidityQuantity(key);
  return quantity ? std::string(quantity->title) : std::string(key);
}

std::string AxisLabel(std::string_view key) {
  const ev::ValidityQuantity* quantity = ev::FindValidityQuantity(key);
  if (quantity == nullptr) return std::string(key);
  return quantity->unit.empty() ? std::string(quantity->title)
                                : fmt::format("{} ({})", quantity->title, quantity->unit);
}

std::vector<std::string_view> TargetsPresent(const ev::ValidityStudy& study) {
  std::vector<std::string_view> targets;
  for (const ev::ValidityQuantity& target : ev::ValidityTargets()) {
    for (const ev::ValidityCorrelation& c : study.correlations) {
      if (c.target == target.key) {
        targets.push_back(target.key);
        break;
      }
    }
  }
  return targets;
}

std::string ScopeTitle(const std::string& sequence, ev::ValidityPooling pooling) {
  return fmt::format("{}: {}", sequence.empty() ? "all sequences" : sequence,
                     pooling == ev::ValidityPooling::kAcrossNoise ? "all noise levels" : "within each noise level");
}

std::string VerdictClass(ev::ValidityVerdict verdict) {
  switch (verdict) {
    case ev::ValidityVerdict::kTracksError:
      return "verdict-tracks";
    case ev::ValidityVerdict::kOpposite:
      return "verdict-opposite";
    case ev::ValidityVerdict::kUnclear:
      return "verdict-unclear";
    case ev::ValidityVerdict::kTooFewRuns:
    case ev::ValidityVerdict::kNoVariation:
      break;
  }
  return "verdict-none";
}

std::string Rho(double value) { return fmt::format("{:+.2f}", value); }

Html CorrelationCell(const ev::ValidityCorrelation* c) {
  if (c == nullptr) return Element("td", "verdict-none", E("-"));
  Html content;
  if (c->verdict == ev::ValidityVerdict::kTooFewRuns) {
    content = E("too few runs") + T("<br>") + Element("span", "n", E(fmt::format("n={}", c->runs)));
  } else {
    std::string number = c->rho ? "ρ = " + Rho(*c->rho) : "ρ undefined";
    if (c->interval) number += fmt::format(" [{}, {}]", Rho(c->interval->low), Rho(c->interval->high));
    content = E(number) + T("<br>") +
              Element("span", "n", E(fmt::format("n={}, {}", c->runs, ev::ValidityVerdictName(c->verdict))));
    if (c->family_interval) {
      content += T("<br>") + Element("span", "n",
                                     E(fmt::format("Bonferroni [{}, {}]: {}", Rho(c->family_interval->low),
                                                   Rho(c->family_interval->high),
                                                   c->survives_family ? "survives" : "does not survive")));
    }
  }
  return Element("td", VerdictClass(c->verdict), content);
}

/// More than one algorithm among the points: the key then names both the noise setting and the algorithm.
bool SeveralAlgorithms(const std::vector<ev::ValidityPoint>& points) {
  return std::any_of(points.begin(), points.end(),
                     [&](const ev::ValidityPoint& p) { return p.algorithm != points.front().algorithm; });
}

/// The points' noise settings in the natural order of their names.
std::set<std::string, decltype(&NaturalLess)> NoiseSettings(const std::vector<ev::ValidityPoint>& points) {
  std::set<std::string, decltype(&NaturalLess)> noises(&NaturalLess);
  for (const ev::ValidityPoint& point : points) noises.insert(point.noise);
  return noises;
}

/// One series per noise setting and algorithm. With several noise settings the colour grades them in the
/// natural order of their names (light first, dark last: what "all noise levels" ranks across) and the
/// marker is the algorithm's; with one, colour and marker are the algorithm's, as in every other plot of
/// the report.
std::vector<ScatterSeries> ScatterSeriesOf(const std::vector<ev::ValidityPoint>& points,
                                           const AlgorithmPalette& palette) {
  const auto noises = NoiseSettings(points);
  const bool several_algorithms = SeveralAlgorithms(points);
  std::map<std::pair<std::size_t, std::string>, ScatterSeries> by_noise_and_algorithm;
  for (const ev::ValidityPoint& point : points) {
    const auto noise = static_cast<std::size_t>(std::distance(noises.begin(), noises.find(point.noise)));
    ScatterSeries& series = by_noise_and_algorithm[{noise, point.algorithm}];
    if (series.x.empty()) {
      const AlgorithmStyle style = palette.StyleOf(point.algorithm);
      if (noises.size() > 1) {
        series.label = several_algorithms ? point.noise + " · " + point.algorithm : point.noise;
        series.style.rgb = GradedColour(noise, noises.size());
      } else {
        series.label = point.algorithm;
        series.style.rgb = style.rgb;
      }
      series.style.point_type = style.point_type;
    }
    series.x.push_back(point.x);
    series.y.push_back(point.y);
  }
  std::vector<ScatterSeries> series;
  for (auto& [key, values] : by_noise_and_algorithm) series.push_back(std::move(values));
  return series;
}

/// What the key's colours and markers stand for.
std::string KeyTitle(const std::vector<ev::ValidityPoint>& points) {
  const auto noises = NoiseSettings(points);
  if (noises.size() == 1) return "algorithm (noise setting " + *noises.begin() + ")";
  return SeveralAlgorithms(points) ? "colour: noise setting, marker: algorithm" : "colour: noise setting";
}

}  // namespace

ValiditySite PlanValidity(const SweepModel& model, const AlgorithmPalette& palette, const fs::path& out_dir,
                          std::vector<ScatterPlotJob>& jobs) {
  ValiditySite site;
  const std::vector<ev::ValidityRun> runs = orchestrator::ToValidityRuns(model.runs);
  site.study = model.validity;  // computed once, with the model whose best marks rest on it
  if (site.study.empty()) return site;
  std::error_code error;
  fs::create_directories(out_dir / "plots" / "validity", error);
  for (const std::string_view target : TargetsPresent(site.study)) {
    for (const ev::ValidityQuantity& candidate : ev::ValidityCandidates()) {
      for (std::size_t s = 0; s < site.study.sequences.size(); ++s) {
        const std::string& sequence = site.study.sequences[s];
        const std::vector<ev::ValidityPoint> points = ev::ValidityPoints(runs, candidate.key, target, sequence);
        if (points.size() < 2) continue;
        ScatterPlotJob job;
        // The picture's own title stays short (the axes say what is plotted); the caption has it all.
        job.plot.title = sequence;
        job.plot.x_label = AxisLabel(candidate.key);
        job.plot.y_label = AxisLabel(target);
        job.plot.series = ScatterSeriesOf(points, palette);
        job.plot.key_title = KeyTitle(points);
        ValidityPlot plot;
        plot.candidate = candidate.key;
        plot.target = target;
        plot.sequence = sequence;
        plot.title = fmt::format("{}: {} vs {}", sequence, candidate.title, QuantityTitle(target));
        // Sequence names are untrusted: its index keeps two names that sanitise alike apart.
        plot.path = fmt::format("plots/validity/{}-{}-{}-vs-{}.png", s, SafeFileName(sequence), candidate.key, target);
        plot.note = "no image maker configured";
        job.png = out_dir / plot.path;
        site.plots.push_back(std::move(plot));
        jobs.push_back(std::move(job));
      }
    }
  }
  return site;
}

void CountValidityPlots(const fs::path& out_dir, bool drawing, ValiditySite& validity, ReportSummary& summary) {
  for (ValidityPlot& plot : validity.plots) {
    std::error_code error;
    plot.made = fs::is_regular_file(out_dir / plot.path, error);
    if (plot.made) {
      plot.note.clear();
      ++summary.images;
    } else if (drawing) {
      ++summary.images_missing;
    }
  }
}

std::string RenderValidityPage(const SiteData& /*site*/, const ValiditySite& validity) {
  const ev::ValidityStudy& study = validity.study;
  const ev::ValidityOptions& options = study.options;
  Html body = Element(
      "p", "",
      E("The map metrics of the paper need no ground truth. On this sweep there is ground truth, so we can measure "
        "whether each of them ranks runs the way their real error does. For every ground-truth-free metric and run "
        "resource, the table gives Spearman's rank correlation ρ with each real error, its 95 % bootstrap interval, "
        "the number of runs n and a verdict. Every metric reads \"higher is worse\": one that can be trusted has ρ "
        "near +1 with its whole interval above 0 (\"tracks error\")."));
  Html method;
  method += Element(
      "li", "",
      E("Runs: the successful runs whose odometry was not the reference (" + std::to_string(study.runs_used) + " used" +
        (study.runs_odometry_is_reference > 0 ? ", " + std::to_string(study.runs_odometry_is_reference) +
                                                    " left out because their odometry was the reference"
                                              : std::string()) +
        ")."));
  if (study.family_size > 0) {
    std::size_t decided = 0, survive = 0;
    for (const ev::ValidityCorrelation& c : study.correlations) {
      decided += c.family_interval ? 1 : 0;
      survive += c.survives_family ? 1 : 0;
    }
    method += Element("li", "",
                      E(fmt::format("Multiple comparisons: this page reports {} intervals, and some 95 % intervals "
                                    "exclude 0 by chance alone. Each decided verdict's interval is redrawn at the "
                                    "Bonferroni level {:.4g} (1 - 0.05 / {}, the same resamples); {} of {} decided "
                                    "verdicts survive it.",
                                    study.family_size, study.family_confidence, study.family_size, survive, decided)));
  }
  method += Element("li", "",
                    E("\"All noise levels\": the sequence's runs ranked together, every noise setting "
                      "mixed: does the metric follow the error as the conditions get worse? \"Within each "
                      "noise level\": runs ranked only against runs of the same sequence and noise setting "
                      "(those a table of this report compares), the ranks then pooled."));
  method += Element("li", "",
                    E("\"All sequences\": runs are never ranked against runs of another sequence; each "
                      "rank is centred on its sequence's (or sequence and noise setting's) mean rank and "
                      "divided by its size, and these pooled ranks are correlated."));
  method += Element("li", "",
                    E(fmt::format("Interval: percentile bootstrap, {} resamples drawn within each stratum, "
                                  "seed {}; fewer than {} runs give \"too few runs\" instead of a number.",
                                  options.bootstrap.resamples, options.bootstrap.seed, options.min_runs)));
  Html links = Link("metrics.html", E("metric specification"));
  if (validity.has_csv) links += T(" · ") + Link("validity.csv", E("validity.csv"));
  links += T(" · ") + Link("summary.json", E("summary.json (\"validity\")"));
  method += Element("li", "", E("Definitions, and the same table for other tools: ") + links);
  body += Element("h2", "", E("Method")) + Element("ul", "", method);

  for (const std::string_view target : TargetsPresent(study)) {
    // The target's scopes in the study's order: its sequences, then all of them together.
    std::vector<std::pair<std::string, ev::ValidityPooling>> scopes;
    for (const ev::ValidityCorrelation& c : study.correlations) {
      if (c.target == target && c.candidate == ev::ValidityCandidates().front().key)
        scopes.emplace_back(c.sequence, c.pooling);
    }
    body += Element("h2", "", E("Against " + QuantityTitle(target)));
    Html header = Element("th", "", E("Metric"));
    for (const auto& [sequence, pooling] : scopes) header += Element("th", "", E(ScopeTitle(sequence, pooling)));
    Html rows;
    for (const ev::ValidityQuantity& candidate : ev::ValidityCandidates()) {
      // A quantity no run has (no peak memory without a program, say) gets no row.
      bool any_run = false;
      for (const auto& [sequence, pooling] : scopes) {
        const ev::ValidityCorrelation* c = study.Find(candidate.key, target, sequence, pooling);
        any_run = any_run || (c != nullptr && c->runs > 0);
      }
      if (!any_run) continue;
      Html line = Element(
          "th", "",
          E(std::string(candidate.title)) + T("<br>") + Element("span", "spec", E(std::string(candidate.kind))));
      for (const auto& [sequence, pooling] : scopes) {
        line += CorrelationCell(study.Find(candidate.key, target, sequence, pooling));
      }
      rows += Element("tr", "", line) + T("\n");
    }
    body += T("<table class=\"validity\">\n") +
            Element("caption", "",
                    E("Spearman's ρ with " + QuantityTitle(target) + " [95 % bootstrap interval], runs and verdict")) +
            T("\n<thead>") + Element("tr", "", header) + T("</thead>\n<tbody>\n") + rows + T("</tbody>\n</table>\n");
    Html figures;
    for (const ValidityPlot& plot : validity.plots) {
      if (plot.target != target) continue;
      Html content =
          plot.made
              ? T("<img class=\"plot\" src=\"" + EscapeHtml(plot.path) + "\" alt=\"" + EscapeHtml(plot.title) + "\">")
              : Element("p", "note", E("Plot not available: " + plot.note));
      figures += Element("figure", "plot", content + Element("figcaption", "", E(plot.title)));
    }
    if (!figures.str().empty()) {
      body += Element("p", "note",
                      E("Each point is one run. With several noise settings, colour: its noise setting, light to dark "
                        "in the order of the settings' names (the key lists them), and marker: its algorithm's; with "
                        "one, colour and marker are its algorithm's, as in every plot of this report."));
      body += Element("div", "plots", figures);
    }
  }
  return RenderPage("Which metrics can be trusted?", "", body);
}

}  // namespace slamsweep::report::inline html
