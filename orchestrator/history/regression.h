#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/statistics/mann_whitney.h"
#include "orchestrator/history/night.h"

namespace slamsweep::orchestrator::inline history {

/// When a difference between two nights counts (the sweep config's `regression:` block, or CLI options).
struct RegressionOptions {
  /// Significance level of the two-sided Mann-Whitney U test, in (0, 1).
  double alpha = 0.05;
  /// Minimum |Cliff's delta|, in [0, 1]: a significant but tiny shift is not reported.
  double min_effect = 0.2;
};

/// Throws InputError naming `source` (an option or config field prefix) when a value is out of range.
void ValidateRegressionOptions(const RegressionOptions& options, std::string_view source);

enum class Verdict {
  kUnchanged,
  kRegression,
  kImprovement,
  /// One of the nights has no sample of this series (every run failed, or the cell is new or gone), or the
  /// series' odometry mode is unknown (recorded before the history kept it).
  kNotComparable,
};

/// "unchanged", "regression", "improvement", "not_comparable".
std::string_view VerdictName(Verdict verdict);

/// The comparison of one algorithm x sequence x noise x odometry mode x metric between a baseline night and the
/// current one.
/// Its statistic is "rmse" for trajectory metrics, "value" for map metrics.
struct Finding : SeriesKey {
  std::size_t baseline_n = 0;
  std::size_t current_n = 0;
  double baseline_median = 0.0;
  double current_median = 0.0;
  /// U of the current samples against the baseline's.
  evaluator::MannWhitneyResult test;
  /// Cliff's delta of current against baseline: positive = current larger = worse (every metric: lower is better).
  double cliffs_delta = 0.0;
  Verdict verdict = Verdict::kUnchanged;
};

/// Everything `slamsweep history compare` reports.
struct Comparison {
  std::string baseline_label;
  std::string current_label;
  RegressionOptions options;
  /// Ordered by algorithm, sequence, noise, odometry, metric.
  std::vector<Finding> findings;

  std::size_t Count(Verdict verdict) const;
  bool HasRegression() const { return Count(Verdict::kRegression) > 0; }
};

/// The exit code of `slamsweep history compare` when at least one regression was found (distinct from
/// 1 failed runs, 2 usage, 130 interrupted), so the nightly job can map it to UNSTABLE.
inline constexpr int kRegressionExitCode = 3;

/// The statistic compared for `metric` ("rmse" for trajectory metrics, "value" for map metrics), chosen from
/// the statistics `night` has; empty when the night has neither.
std::string ComparedStatistic(const Night& night, const std::string& metric);

/// Compares every algorithm x sequence x noise x odometry mode x metric present in either night (statistic per
/// ComparedStatistic), only with the other night's series of the same mode: a regression when p < alpha,
/// |delta| >= min_effect and the current samples are larger; an improvement when smaller. A series whose mode is
/// unknown or mixed (IsComparableOdometryMode) is not comparable. Throws InputError naming the field when
/// `options` are out of range.
Comparison CompareNights(const Night& baseline, const Night& current, const RegressionOptions& options);

/// {"baseline", "current", "alpha", "min_effect", "counts": {...}, "findings": [...]}.
nlohmann::json ComparisonToJson(const Comparison& comparison);

/// JUnit XML: one testsuite "regressions", one testcase per finding (classname
/// "<algorithm>.<sequence>.<noise>.<odometry>",
/// name "<metric>.<statistic>"); a regression is a <failure type="regression">, a finding that could not be
/// compared is <skipped>.
std::string RenderComparisonJUnit(const Comparison& comparison);

}  // namespace slamsweep::orchestrator::inline history
