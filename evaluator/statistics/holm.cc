#include "evaluator/statistics/holm.h"

#include <algorithm>
#include <numeric>

namespace slamsweep::evaluator::inline statistics {

std::vector<double> HolmAdjusted(std::span<const double> p_values) {
  const std::size_t m = p_values.size();
  std::vector<std::size_t> order(m);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p_values[a] < p_values[b]; });
  std::vector<double> adjusted(m, 1.0);
  double running = 0.0;
  for (std::size_t i = 0; i < m; ++i) {
    running = std::max(running, std::min(1.0, static_cast<double>(m - i) * p_values[order[i]]));
    adjusted[order[i]] = running;
  }
  return adjusted;
}

std::vector<double> BonferroniAdjusted(std::span<const double> p_values) {
  std::vector<double> adjusted;
  adjusted.reserve(p_values.size());
  for (const double p : p_values) adjusted.push_back(std::min(1.0, static_cast<double>(p_values.size()) * p));
  return adjusted;
}

}  // namespace slamsweep::evaluator::inline statistics
