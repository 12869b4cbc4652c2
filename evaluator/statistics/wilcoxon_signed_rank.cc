#include "evaluator/statistics/wilcoxon_signed_rank.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace slamsweep::evaluator::inline statistics {
namespace {

// counts[w] = number of the 2^n sign assignments of ranks 1..n whose positive ranks sum to w.
std::vector<double> ExactWCounts(std::size_t n) {
  const std::size_t max_w = n * (n + 1) / 2;
  std::vector<double> counts(max_w + 1, 0.0);
  counts[0] = 1.0;
  for (std::size_t rank = 1; rank <= n; ++rank) {
    for (std::size_t w = max_w; w >= rank; --w) counts[w] += counts[w - rank];
  }
  return counts;
}

}  // namespace

WilcoxonResult WilcoxonSignedRank(std::span<const double> x, std::span<const double> y, Alternative alternative) {
  if (x.size() != y.size()) throw std::invalid_argument("Wilcoxon signed-rank test: samples differ in length");
  WilcoxonResult result;
  std::vector<double> differences;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double d = x[i] - y[i];
    if (d == 0.0) {
      ++result.zero_pairs;
    } else {
      differences.push_back(d);
    }
  }
  result.pairs_used = differences.size();
  if (differences.empty()) return result;
  std::sort(differences.begin(), differences.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
  double tie_term = 0.0;  // sum of t^3 - t over groups of tied |d|
  for (std::size_t i = 0; i < differences.size();) {
    std::size_t j = i;
    while (j < differences.size() && std::abs(differences[j]) == std::abs(differences[i])) ++j;
    const double mid_rank = (static_cast<double>(i + 1) + static_cast<double>(j)) / 2.0;
    const double count = static_cast<double>(j - i);
    tie_term += count * count * count - count;
    for (std::size_t k = i; k < j; ++k) (differences[k] > 0.0 ? result.w_plus : result.w_minus) += mid_rank;
    i = j;
  }
  const double n = static_cast<double>(differences.size());
  // x lower than y shows as a large W-: the upper tail of W- is the evidence for kLess.
  const double w_tail = alternative == Alternative::kTwoSided ? std::max(result.w_plus, result.w_minus)
                        : alternative == Alternative::kLess   ? result.w_minus
                                                              : result.w_plus;
  const double sides = alternative == Alternative::kTwoSided ? 2.0 : 1.0;

  if (tie_term == 0.0 && differences.size() <= kWilcoxonExactMaxPairs) {
    result.method = MannWhitneyMethod::kExact;
    const std::vector<double> counts = ExactWCounts(differences.size());
    const auto w_high = static_cast<std::size_t>(std::llround(w_tail));
    double upper_tail = 0.0;
    for (std::size_t w = w_high; w < counts.size(); ++w) upper_tail += counts[w];
    result.p_value = std::min(1.0, sides * upper_tail / std::pow(2.0, n));
    return result;
  }
  result.method = MannWhitneyMethod::kNormal;
  const double mean = n * (n + 1.0) / 4.0;
  const double variance = n * (n + 1.0) * (2.0 * n + 1.0) / 24.0 - tie_term / 48.0;
  if (variance <= 0.0) return result;
  const double z = (w_tail - mean) / std::sqrt(variance);
  result.p_value = std::min(1.0, sides * 0.5 * std::erfc(z / std::sqrt(2.0)));
  return result;
}

double WilcoxonMinimumOneSidedP(std::size_t pairs) { return std::pow(0.5, static_cast<double>(pairs)); }

}  // namespace slamsweep::evaluator::inline statistics
