#pragma once

#include <cstddef>
#include <span>

#include "evaluator/statistics/mann_whitney.h"

namespace slamsweep::evaluator::inline statistics {

/// The outcome of a Wilcoxon signed-rank test of pairs (x[i], y[i]).
struct WilcoxonResult {
  /// Sum of the ranks of |x - y| over pairs where x > y (zero differences dropped, tied |d| mid-ranked).
  double w_plus = 0.0;
  /// Sum of the ranks over pairs where x < y.
  double w_minus = 0.0;
  /// Pairs with a non-zero difference: the test's n.
  std::size_t pairs_used = 0;
  /// Pairs whose difference is exactly 0: identical runs are ties, not evidence.
  std::size_t zero_pairs = 0;
  /// p-value of the requested alternative; 1 when no pair differs.
  double p_value = 1.0;
  MannWhitneyMethod method = MannWhitneyMethod::kExact;
};

/// Up to this many differing pairs without tied |differences| get the exact distribution of W+; beyond it or
/// with ties the normal approximation (tie-corrected variance, no continuity correction).
inline constexpr std::size_t kWilcoxonExactMaxPairs = 25;

/// Wilcoxon signed-rank test of paired samples (Wilcoxon's treatment of zeros: dropped). kLess asks whether x
/// tends to be lower than y. Throws std::invalid_argument when the spans differ in length.
WilcoxonResult WilcoxonSignedRank(std::span<const double> x, std::span<const double> y,
                                  Alternative alternative = Alternative::kTwoSided);

/// The smallest one-sided p-value n differing pairs can reach: 1 / 2^n (5 pairs: 1/32).
double WilcoxonMinimumOneSidedP(std::size_t pairs);

}  // namespace slamsweep::evaluator::inline statistics
