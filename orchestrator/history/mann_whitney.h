#pragma once

#include <cstddef>
#include <span>
#include <string_view>

namespace slamsweep::orchestrator {

/// How the p-value of a Mann-Whitney U test was obtained.
enum class MannWhitneyMethod {
  /// The exact null distribution of U (small samples without ties).
  kExact,
  /// Normal approximation with tie and continuity corrections.
  kNormal,
};

/// "exact" or "normal".
std::string_view MannWhitneyMethodName(MannWhitneyMethod method);

/// The outcome of a two-sided Mann-Whitney U test of samples x and y.
struct MannWhitneyResult {
  /// U of x: the number of pairs (x_i, y_j) with x_i > y_j, ties counting one half.
  double u_x = 0.0;
  /// U of y = n_x * n_y - u_x.
  double u_y = 0.0;
  /// Two-sided p-value in [0, 1]; 1 when either sample is empty.
  double p_value = 1.0;
  /// The normal approximation's z (continuity-corrected, >= 0); 0 for the exact method.
  double z = 0.0;
  MannWhitneyMethod method = MannWhitneyMethod::kExact;
};

/// Samples up to this size (both) without ties get the exact distribution; larger or tied ones the normal
/// approximation, whose error is small from there on and whose cost does not grow with the sample.
inline constexpr std::size_t kMannWhitneyExactMaxSize = 10;

/// Two-sided Mann-Whitney U test (Wilcoxon rank-sum) of x against y. Non-finite values must be removed by
/// the caller (they have no rank); an empty sample gives p = 1 (nothing can be concluded).
MannWhitneyResult MannWhitneyU(std::span<const double> x, std::span<const double> y);

/// Cliff's delta of x against y: (#{x_i > y_j} - #{x_i < y_j}) / (n_x n_y), in [-1, 1]; positive when x tends
/// to be larger. 0 when either sample is empty.
double CliffsDelta(std::span<const double> x, std::span<const double> y);

}  // namespace slamsweep::orchestrator
