#include "evaluator/core/sample_summary.h"

#include <algorithm>
#include <cmath>

namespace slamsweep::evaluator::inline core {

MeanStd ComputeMeanStd(std::span<const double> values) {
  MeanStd out;
  out.n = values.size();
  if (values.empty()) return out;
  double sum = 0.0;
  for (double v : values) sum += v;
  out.mean = sum / static_cast<double>(values.size());
  out.min = *std::min_element(values.begin(), values.end());
  out.max = *std::max_element(values.begin(), values.end());
  if (values.size() >= 2) {
    // Two-pass: the squared deviations from the mean, which stays exact for values far from 0.
    double squares = 0.0;
    for (double v : values) squares += (v - out.mean) * (v - out.mean);
    out.std = std::sqrt(squares / static_cast<double>(values.size() - 1));
  }
  return out;
}

}  // namespace slamsweep::evaluator::inline core
