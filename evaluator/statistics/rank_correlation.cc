#include "evaluator/statistics/rank_correlation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace slamsweep::evaluator::inline statistics {

std::vector<double> AverageRanks(std::span<const double> values) {
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  std::vector<double> ranks(values.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j < order.size() && values[order[j]] == values[order[i]]) ++j;
    // Positions i..j-1 hold one value: ranks i+1 .. j, whose mean is (i + 1 + j) / 2.
    const double mid_rank = (static_cast<double>(i + 1) + static_cast<double>(j)) / 2.0;
    for (std::size_t k = i; k < j; ++k) ranks[order[k]] = mid_rank;
    i = j;
  }
  return ranks;
}

std::optional<double> PooledRankCorrelation(const std::vector<PairedStratum>& strata) {
  std::vector<std::vector<double>> x_ranks, y_ranks;
  x_ranks.reserve(strata.size());
  y_ranks.reserve(strata.size());
  for (const PairedStratum& stratum : strata) {
    if (stratum.x.size() != stratum.y.size()) return std::nullopt;
    x_ranks.push_back(stratum.x.size() < 2 ? std::vector<double>() : AverageRanks(stratum.x));
    y_ranks.push_back(stratum.y.size() < 2 ? std::vector<double>() : AverageRanks(stratum.y));
  }
  return PooledCorrelationOfRanks(x_ranks, y_ranks);
}

std::optional<double> PooledCorrelationOfRanks(const std::vector<std::vector<double>>& x_ranks,
                                               const std::vector<std::vector<double>>& y_ranks) {
  if (x_ranks.size() != y_ranks.size()) return std::nullopt;
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  std::size_t used = 0;
  for (std::size_t s = 0; s < x_ranks.size(); ++s) {
    const std::vector<double>& rx = x_ranks[s];
    const std::vector<double>& ry = y_ranks[s];
    if (rx.size() != ry.size()) return std::nullopt;
    if (rx.size() < 2) continue;
    const double n = static_cast<double>(rx.size());
    const double mean_rank = (n + 1.0) / 2.0;
    for (std::size_t k = 0; k < rx.size(); ++k) {
      const double cx = (rx[k] - mean_rank) / n, cy = (ry[k] - mean_rank) / n;
      sxy += cx * cy;
      sxx += cx * cx;
      syy += cy * cy;
    }
    used += rx.size();
  }
  if (used < 2 || !(sxx > 0.0) || !(syy > 0.0)) return std::nullopt;
  // Rounding can push a perfect correlation a hair past 1.
  return std::clamp(sxy / std::sqrt(sxx * syy), -1.0, 1.0);
}

std::vector<PairedStratum> GroupIntoStrata(std::span<const double> x, std::span<const double> y,
                                           std::span<const std::size_t> strata) {
  std::map<std::size_t, PairedStratum> by_id;
  const std::size_t n = std::min({x.size(), y.size(), strata.size()});
  for (std::size_t i = 0; i < n; ++i) {
    PairedStratum& stratum = by_id[strata[i]];
    stratum.x.push_back(x[i]);
    stratum.y.push_back(y[i]);
  }
  std::vector<PairedStratum> grouped;
  for (auto& [id, stratum] : by_id) grouped.push_back(std::move(stratum));
  return grouped;
}

std::optional<double> SpearmanRho(std::span<const double> x, std::span<const double> y) {
  if (x.size() != y.size() || x.size() < 2) return std::nullopt;
  return PooledRankCorrelation({PairedStratum{{x.begin(), x.end()}, {y.begin(), y.end()}}});
}

std::optional<double> StratifiedSpearmanRho(std::span<const double> x, std::span<const double> y,
                                            std::span<const std::size_t> strata) {
  if (x.size() != y.size() || x.size() != strata.size()) return std::nullopt;
  return PooledRankCorrelation(GroupIntoStrata(x, y, strata));
}

}  // namespace slamsweep::evaluator::inline statistics
