#include "orchestrator/history/regression.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/history/series_odometry.h"
#include "orchestrator/store/junit_xml.h"
#include "orchestrator/store/metric_direction.h"

namespace slamsweep::orchestrator::inline history {
namespace {

using nlohmann::json;

double Median(std::vector<double> values) {
  if (values.empty()) return std::nan("");
  std::sort(values.begin(), values.end());
  const std::size_t half = values.size() / 2;
  return values.size() % 2 == 1 ? values[half] : (values[half - 1] + values[half]) / 2.0;
}

// NaN (an empty sample's median) is not JSON; null says "no value".
json NumberOrNull(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

std::string NotComparableReason(const Finding& f) {
  if (!IsComparableOdometryMode(f.odometry)) {
    return fmt::format(
        "odometry mode {}: the series' runs cannot say which odometry they got, or had both "
        "(recorded before the history kept the mode); not compared",
        f.odometry);
  }
  return fmt::format("no samples to compare (baseline n = {}, current n = {})", f.baseline_n, f.current_n);
}

std::string DescribeFinding(const Finding& f) {
  return fmt::format("median {:.6g} -> {:.6g} {} (n {} -> {}), p = {:.4g} ({}), Cliff's delta = {:+.3f}",
                     f.baseline_median, f.current_median, f.unit, f.baseline_n, f.current_n, f.test.p_value,
                     evaluator::MannWhitneyMethodName(f.test.method), f.cliffs_delta);
}

}  // namespace

void ValidateRegressionOptions(const RegressionOptions& options, std::string_view source) {
  if (!(options.alpha > 0.0 && options.alpha < 1.0)) {
    throw evaluator::InputError(
        fmt::format("{}alpha: expected a significance level in (0, 1), e.g. 0.05, got {}", source, options.alpha));
  }
  if (!(options.min_effect >= 0.0 && options.min_effect <= 1.0)) {
    throw evaluator::InputError(fmt::format(
        "{}min_effect: expected a Cliff's delta magnitude in [0, 1], e.g. 0.2, got {}", source, options.min_effect));
  }
}

std::string_view VerdictName(Verdict verdict) {
  switch (verdict) {
    case Verdict::kUnchanged:
      return "unchanged";
    case Verdict::kRegression:
      return "regression";
    case Verdict::kImprovement:
      return "improvement";
    case Verdict::kNotComparable:
      return "not_comparable";
  }
  return "unchanged";
}

std::size_t Comparison::Count(Verdict verdict) const {
  return static_cast<std::size_t>(
      std::count_if(findings.begin(), findings.end(), [verdict](const Finding& f) { return f.verdict == verdict; }));
}

std::string ComparedStatistic(const Night& night, const std::string& metric) {
  bool has_value = false;
  for (const SampleSeries& s : night.series) {
    if (s.metric != metric) continue;
    if (s.statistic == "rmse") return "rmse";
    has_value = has_value || s.statistic == "value";
  }
  return has_value ? "value" : "";
}

Comparison CompareNights(const Night& baseline, const Night& current, const RegressionOptions& options) {
  ValidateRegressionOptions(options, "regression.");
  Comparison comparison;
  comparison.baseline_label = baseline.label;
  comparison.current_label = current.label;
  comparison.options = options;

  using Key = std::tuple<std::string, std::string, std::string, std::string, std::string, std::string>;
  std::set<Key> keys;
  for (const Night* night : {&baseline, &current}) {
    for (const SampleSeries& s : night->series) {
      std::string statistic = ComparedStatistic(*night, s.metric);
      if (s.statistic == statistic) keys.insert({s.algorithm, s.sequence, s.noise, s.odometry, s.metric, statistic});
    }
  }
  for (const auto& [algorithm, sequence, noise, odometry, metric, statistic] : keys) {
    // The odometry mode is part of the key: a night on recorded odometry is never the baseline of one on the
    // reference, or the other way round.
    const SeriesKey key{algorithm, sequence, noise, odometry, metric, statistic, ""};
    const SampleSeries* before = FindSeries(baseline, key);
    const SampleSeries* after = FindSeries(current, key);
    Finding f{key, 0, 0, std::nan(""), std::nan(""), {}, 0.0, Verdict::kNotComparable};
    f.unit = after != nullptr ? after->unit : before->unit;
    if (before != nullptr) {
      f.baseline_n = before->values.size();
      f.baseline_median = Median(before->values);
    }
    if (after != nullptr) {
      f.current_n = after->values.size();
      f.current_median = Median(after->values);
    }
    if (f.baseline_n > 0 && f.current_n > 0 && IsComparableOdometryMode(f.odometry)) {
      f.test = evaluator::MannWhitneyU(after->values, before->values);
      f.cliffs_delta = evaluator::CliffsDelta(after->values, before->values);
      const bool significant = f.test.p_value < options.alpha && std::abs(f.cliffs_delta) >= options.min_effect;
      // Errors and defect counts get worse as they grow; the map-versus-reference scores get better.
      const bool grew = f.cliffs_delta > 0.0;
      if (!significant) {
        f.verdict = Verdict::kUnchanged;
      } else {
        f.verdict = grew != HigherIsBetter(f.metric) ? Verdict::kRegression : Verdict::kImprovement;
      }
    }
    comparison.findings.push_back(std::move(f));
  }
  return comparison;
}

json ComparisonToJson(const Comparison& comparison) {
  json findings = json::array();
  for (const Finding& f : comparison.findings) {
    findings.push_back({{"algorithm", f.algorithm},
                        {"sequence", f.sequence},
                        {"noise", f.noise},
                        {"odometry", f.odometry},
                        {"metric", f.metric},
                        {"statistic", f.statistic},
                        {"unit", f.unit},
                        {"verdict", VerdictName(f.verdict)},
                        {"baseline_n", f.baseline_n},
                        {"current_n", f.current_n},
                        {"baseline_median", NumberOrNull(f.baseline_median)},
                        {"current_median", NumberOrNull(f.current_median)},
                        {"u", f.test.u_x},
                        {"p_value", f.test.p_value},
                        {"method", evaluator::MannWhitneyMethodName(f.test.method)},
                        {"cliffs_delta", f.cliffs_delta}});
  }
  return {{"baseline", comparison.baseline_label},
          {"current", comparison.current_label},
          {"alpha", comparison.options.alpha},
          {"min_effect", comparison.options.min_effect},
          {"counts",
           {{"regression", comparison.Count(Verdict::kRegression)},
            {"improvement", comparison.Count(Verdict::kImprovement)},
            {"unchanged", comparison.Count(Verdict::kUnchanged)},
            {"not_comparable", comparison.Count(Verdict::kNotComparable)}}},
          {"findings", std::move(findings)}};
}

std::string RenderComparisonJUnit(const Comparison& comparison) {
  std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml += fmt::format("<testsuites name=\"slamsweep regressions\" tests=\"{}\" failures=\"{}\">\n",
                     comparison.findings.size(), comparison.Count(Verdict::kRegression));
  xml += fmt::format("  <testsuite name=\"regressions\" tests=\"{}\" failures=\"{}\" skipped=\"{}\">\n",
                     comparison.findings.size(), comparison.Count(Verdict::kRegression),
                     comparison.Count(Verdict::kNotComparable));
  xml += fmt::format(
      "    <properties><property name=\"baseline\" value=\"{}\"/><property name=\"current\" "
      "value=\"{}\"/></properties>\n",
      XmlEscape(comparison.baseline_label), XmlEscape(comparison.current_label));
  for (const Finding& f : comparison.findings) {
    xml += fmt::format("    <testcase classname=\"{}\" name=\"{}\"",
                       XmlEscape(fmt::format("{}.{}.{}.{}", f.algorithm, f.sequence, f.noise, f.odometry)),
                       XmlEscape(fmt::format("{}.{}", f.metric, f.statistic)));
    switch (f.verdict) {
      case Verdict::kRegression:
        xml += fmt::format(
            ">\n      <failure type=\"regression\" message=\"{}\"/>\n    </testcase>\n",
            XmlEscape(SeriesName(f) + " worse than " + comparison.baseline_label + ": " + DescribeFinding(f)));
        break;
      case Verdict::kNotComparable:
        xml += fmt::format(">\n      <skipped message=\"{}\"/>\n    </testcase>\n", XmlEscape(NotComparableReason(f)));
        break;
      default:
        xml += fmt::format(">\n      <system-out>{}</system-out>\n    </testcase>\n",
                           XmlEscape(std::string(VerdictName(f.verdict)) + ": " + DescribeFinding(f)));
    }
  }
  xml += "  </testsuite>\n</testsuites>\n";
  return xml;
}

}  // namespace slamsweep::orchestrator::inline history
