#pragma once

#include <cstddef>
#include <span>
#include <string_view>

namespace slamsweep::evaluator::inline statistics {

/// How the p-value of a Mann-Whitney U test was obtained.
enum class MannWhitneyMethod {
  /// The exact null distribution of U (small samples without ties).
  kExact,
  /// Normal approximation with tie and continuity corrections.
  kNormal,
};

/// "exact" or "normal".
std::string_view MannWhitneyMethodName(MannWhitneyMethod method);

/// Which difference a rank test looks for: any (two-sided), or x tending to be lower (less) or higher (greater)
/// than y. A "best" row is claimed lower than its runner-up, so the report's tests are one-sided (kLess).
enum class Alternative { kTwoSided, kLess, kGreater };

/// The outcome of a Mann-Whitney U test of samples x and y.
struct MannWhitneyResult {
  /// U of x: the number of pairs (x_i, y_j) with x_i > y_j, ties counting one half.
  double u_x = 0.0;
  /// U of y = n_x * n_y - u_x.
  double u_y = 0.0;
  /// p-value of the requested alternative in [0, 1]; 1 when either sample is empty.
  double p_value = 1.0;
  /// The normal approximation's z (continuity-corrected; two-sided: >= 0); 0 for the exact method.
  double z = 0.0;
  MannWhitneyMethod method = MannWhitneyMethod::kExact;
};

/// Samples up to this size (both) without ties get the exact distribution; larger or tied ones the normal
/// approximation, whose error is small from there on and whose cost does not grow with the sample.
inline constexpr std::size_t kMannWhitneyExactMaxSize = 10;

/// Mann-Whitney U test (Wilcoxon rank-sum) of x against y, two-sided unless told. Non-finite values must be
/// removed by the caller (they have no rank); an empty sample gives p = 1 (nothing can be concluded).
MannWhitneyResult MannWhitneyU(std::span<const double> x, std::span<const double> y,
                               Alternative alternative = Alternative::kTwoSided);

/// The smallest one-sided p-value samples of these sizes can reach (complete separation, no ties):
/// 1 / C(n_x + n_y, n_x). 5 runs against 5 reach 1/252.
double MannWhitneyMinimumOneSidedP(std::size_t n_x, std::size_t n_y);

/// Cliff's delta of x against y: (#{x_i > y_j} - #{x_i < y_j}) / (n_x n_y), in [-1, 1]; positive when x tends
/// to be larger. 0 when either sample is empty.
double CliffsDelta(std::span<const double> x, std::span<const double> y);

}  // namespace slamsweep::evaluator::inline statistics
