#include "evaluator/statistics/mann_whitney.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace slamsweep::evaluator::inline statistics {
namespace {

struct RankSums {
  double rank_sum_x = 0.0;
  /// Sum over groups of tied values of t^3 - t (the tie correction of the variance).
  double tie_term = 0.0;
};

// Mid-ranks of the pooled sample: tied values share the mean of the ranks they occupy.
RankSums RankSum(std::span<const double> x, std::span<const double> y) {
  struct Item {
    double value;
    bool from_x;
  };
  std::vector<Item> pooled;
  pooled.reserve(x.size() + y.size());
  for (const double v : x) pooled.push_back({v, true});
  for (const double v : y) pooled.push_back({v, false});
  std::sort(pooled.begin(), pooled.end(), [](const Item& a, const Item& b) { return a.value < b.value; });
  RankSums sums;
  std::size_t i = 0;
  while (i < pooled.size()) {
    std::size_t j = i;
    while (j < pooled.size() && pooled[j].value == pooled[i].value) ++j;
    const double count = static_cast<double>(j - i);
    // Ranks i+1 .. j (1-based); their mean.
    const double mid_rank = (static_cast<double>(i + 1) + static_cast<double>(j)) / 2.0;
    for (std::size_t k = i; k < j; ++k) {
      if (pooled[k].from_x) sums.rank_sum_x += mid_rank;
    }
    sums.tie_term += count * count * count - count;
    i = j;
  }
  return sums;
}

// counts[u] = number of arrangements of n_x x's and n_y y's whose U of x is u (all C(n_x + n_y, n_x) equally likely
// under the null). Recurrence on the largest pooled element: it is an x (adds n_y to U) or a y (adds nothing).
std::vector<double> ExactUCounts(std::size_t n_x, std::size_t n_y) {
  // table[m][u] for the current n (number of y's), built up from n = 0.
  const std::size_t max_u = n_x * n_y;
  std::vector<std::vector<double>> previous(n_x + 1);  // n - 1 y's
  for (std::size_t m = 0; m <= n_x; ++m) {             // n = 0: U is 0 whatever m is
    previous[m].assign(max_u + 1, 0.0);
    previous[m][0] = 1.0;
  }
  for (std::size_t n = 1; n <= n_y; ++n) {
    std::vector<std::vector<double>> current(n_x + 1, std::vector<double>(max_u + 1, 0.0));
    current[0][0] = 1.0;
    for (std::size_t m = 1; m <= n_x; ++m) {
      for (std::size_t u = 0; u <= max_u; ++u) {
        // Largest is a y: f(m, n-1, u). Largest is an x: it beats all n y's: f(m-1, n, u-n).
        double count = previous[m][u];
        if (u >= n) count += current[m - 1][u - n];
        current[m][u] = count;
      }
    }
    previous = std::move(current);
  }
  return previous[n_x];
}

}  // namespace

std::string_view MannWhitneyMethodName(MannWhitneyMethod method) {
  return method == MannWhitneyMethod::kExact ? "exact" : "normal";
}

MannWhitneyResult MannWhitneyU(std::span<const double> x, std::span<const double> y, Alternative alternative) {
  MannWhitneyResult result;
  if (x.empty() || y.empty()) return result;
  const double n_x = static_cast<double>(x.size());
  const double n_y = static_cast<double>(y.size());
  const RankSums sums = RankSum(x, y);
  result.u_x = sums.rank_sum_x - n_x * (n_x + 1.0) / 2.0;
  result.u_y = n_x * n_y - result.u_x;
  // The U whose upper tail is the evidence: x lower than y means a small u_x, so a large u_y.
  const double u_tail = alternative == Alternative::kTwoSided ? std::max(result.u_x, result.u_y)
                        : alternative == Alternative::kLess   ? result.u_y
                                                              : result.u_x;
  const double sides = alternative == Alternative::kTwoSided ? 2.0 : 1.0;

  const bool ties = sums.tie_term > 0.0;
  if (!ties && x.size() <= kMannWhitneyExactMaxSize && y.size() <= kMannWhitneyExactMaxSize) {
    result.method = MannWhitneyMethod::kExact;
    const std::vector<double> counts = ExactUCounts(x.size(), y.size());
    double total = 0.0;
    double upper_tail = 0.0;  // P(U >= u_tail)
    const auto u_high = static_cast<std::size_t>(std::llround(u_tail));
    for (std::size_t u = 0; u < counts.size(); ++u) {
      total += counts[u];
      if (u >= u_high) upper_tail += counts[u];
    }
    // The distribution is symmetric: the two-sided p-value doubles the upper tail of the larger U.
    result.p_value = std::min(1.0, sides * upper_tail / total);
    return result;
  }

  result.method = MannWhitneyMethod::kNormal;
  const double n = n_x + n_y;
  const double mean = n_x * n_y / 2.0;
  const double variance = n_x * n_y / 12.0 * ((n + 1.0) - sums.tie_term / (n * (n - 1.0)));
  if (variance <= 0.0) {
    // Every value equal: no evidence of any difference.
    result.p_value = 1.0;
    return result;
  }
  const double z = (u_tail - mean - 0.5) / std::sqrt(variance);
  result.z = alternative == Alternative::kTwoSided ? std::max(0.0, z) : z;
  result.p_value = std::min(1.0, sides * 0.5 * std::erfc(result.z / std::sqrt(2.0)));
  return result;
}

double MannWhitneyMinimumOneSidedP(std::size_t n_x, std::size_t n_y) {
  // 1 / C(n_x + n_y, n_x), built up as a product to stay finite.
  double p = 1.0;
  for (std::size_t i = 1; i <= n_x; ++i) p *= static_cast<double>(i) / static_cast<double>(n_y + i);
  return p;
}

double CliffsDelta(std::span<const double> x, std::span<const double> y) {
  if (x.empty() || y.empty()) return 0.0;
  double dominance = 0.0;
  for (const double a : x) {
    for (const double b : y) dominance += (a > b) - (a < b);
  }
  return dominance / (static_cast<double>(x.size()) * static_cast<double>(y.size()));
}

}  // namespace slamsweep::evaluator::inline statistics
