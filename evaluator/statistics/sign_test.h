#pragma once

#include <cstddef>
#include <span>

namespace slamsweep::evaluator::inline statistics {

/// The one-sided sign test of paired samples: does `candidate` come out lower (better) than
/// `baseline` more often than chance would have it? Pairs are (candidate[i], baseline[i]); a tie
/// carries no sign and is dropped, as the test defines it.
struct SignTestResult {
  std::size_t wins = 0;    ///< candidate[i] < baseline[i]
  std::size_t losses = 0;  ///< candidate[i] > baseline[i]
  std::size_t ties = 0;
  /// P(at least `wins` of wins + losses fair coin flips come up heads): 1 with no untied pair.
  double p_value = 1.0;
};

/// Throws std::invalid_argument when the spans differ in length.
SignTestResult OneSidedSignTest(std::span<const double> candidate, std::span<const double> baseline);

/// P(X >= k) for X ~ Binomial(n, 1/2): the sign test's one-sided p-value of k wins in n untied pairs.
double SignTestPValue(std::size_t wins, std::size_t pairs);

/// The fewest wins out of `pairs` untied pairs whose one-sided p-value is at most alpha; pairs + 1
/// when no count is enough (too few pairs for that level). 10 pairs at 0.05 need 9 wins.
std::size_t SignTestWinsNeeded(std::size_t pairs, double alpha);

}  // namespace slamsweep::evaluator::inline statistics
