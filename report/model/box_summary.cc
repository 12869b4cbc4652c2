#include "report/model/box_summary.h"

#include <algorithm>
#include <cmath>

namespace slamsweep::report::inline model {

double InterpolatedQuantile(const std::vector<double>& sorted, double p) {
  const double h = p * static_cast<double>(sorted.size() - 1);
  const std::size_t below = static_cast<std::size_t>(std::floor(h));
  if (below + 1 >= sorted.size()) return sorted.back();
  return sorted[below] + (h - static_cast<double>(below)) * (sorted[below + 1] - sorted[below]);
}

std::optional<BoxSummary> SummarizeBox(std::vector<double> values) {
  std::erase_if(values, [](double v) { return !std::isfinite(v); });
  if (values.empty()) return std::nullopt;
  std::sort(values.begin(), values.end());
  BoxSummary box;
  box.n = values.size();
  box.q1 = InterpolatedQuantile(values, 0.25);
  box.median = InterpolatedQuantile(values, 0.5);
  box.q3 = InterpolatedQuantile(values, 0.75);
  const double reach = 1.5 * (box.q3 - box.q1);
  box.whisker_low = box.q1;
  box.whisker_high = box.q3;
  double sum = 0.0;
  for (const double v : values) {
    sum += v;
    if (v < box.q1 - reach || v > box.q3 + reach) {
      ++box.outliers;
    } else {
      box.whisker_low = std::min(box.whisker_low, v);
      box.whisker_high = std::max(box.whisker_high, v);
    }
  }
  box.mean = sum / static_cast<double>(values.size());
  return box;
}

}  // namespace slamsweep::report::inline model
