#include "evaluator/statistics/sign_test.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace slamsweep::evaluator::inline statistics {

double SignTestPValue(std::size_t wins, std::size_t pairs) {
  if (wins == 0) return 1.0;
  if (wins > pairs) return 0.0;
  if (pairs <= 52) {
    // Exact: the sum of C(n, k) for k >= wins is an integer below 2^52, and dividing by 2^n is exact.
    std::uint64_t binomial = 1, sum = 0;  // C(n, k), walking k from n down
    for (std::size_t k = pairs;; --k) {
      if (k >= wins) sum += binomial;
      if (k == wins) break;
      binomial = binomial * k / (pairs - k + 1);
    }
    return std::ldexp(static_cast<double>(sum), -static_cast<int>(pairs));
  }
  // Sum of C(n, k) / 2^n for k = wins..n, each term from lgamma so large n neither overflows nor underflows.
  double p = 0.0;
  const double n = static_cast<double>(pairs);
  for (std::size_t k = wins; k <= pairs; ++k) {
    const double kk = static_cast<double>(k);
    p += std::exp(std::lgamma(n + 1.0) - std::lgamma(kk + 1.0) - std::lgamma(n - kk + 1.0) - n * std::log(2.0));
  }
  return std::min(1.0, p);
}

std::size_t SignTestWinsNeeded(std::size_t pairs, double alpha) {
  for (std::size_t wins = 0; wins <= pairs; ++wins) {
    if (SignTestPValue(wins, pairs) <= alpha) return wins;
  }
  return pairs + 1;
}

SignTestResult OneSidedSignTest(std::span<const double> candidate, std::span<const double> baseline) {
  if (candidate.size() != baseline.size()) throw std::invalid_argument("sign test: the samples are not paired");
  SignTestResult result;
  for (std::size_t i = 0; i < candidate.size(); ++i) {
    if (candidate[i] < baseline[i]) {
      ++result.wins;
    } else if (candidate[i] > baseline[i]) {
      ++result.losses;
    } else {
      ++result.ties;
    }
  }
  result.p_value = SignTestPValue(result.wins, result.wins + result.losses);
  return result;
}

}  // namespace slamsweep::evaluator::inline statistics
