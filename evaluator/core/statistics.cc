#include "evaluator/core/statistics.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline core {

ErrorStatistics ComputeStatistics(std::span<const double> errors) {
  if (errors.empty()) throw InputError("no errors to summarise: the metric produced zero values");
  ErrorStatistics s;
  s.n = errors.size();
  const auto [min_it, max_it] = std::minmax_element(errors.begin(), errors.end());
  s.min = *min_it;
  s.max = *max_it;
  double sum = 0.0;
  for (double e : errors) {
    sum += e;
    s.sse += e * e;
  }
  const double count = static_cast<double>(s.n);
  s.mean = sum / count;
  s.rmse = std::sqrt(s.sse / count);
  // Two-pass variance: numerically safer than sse/n - mean^2 when errors are similar.
  double squared_deviation = 0.0;
  for (double e : errors) squared_deviation += (e - s.mean) * (e - s.mean);
  s.std = std::sqrt(squared_deviation / count);

  std::vector<double> sorted(errors.begin(), errors.end());
  const std::size_t mid = sorted.size() / 2;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(mid), sorted.end());
  s.median = sorted[mid];
  if (sorted.size() % 2 == 0) {
    const double lower = *std::max_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(mid));
    s.median = 0.5 * (s.median + lower);
  }
  return s;
}

void to_json(nlohmann::json& out, const ErrorStatistics& s) {
  out = nlohmann::json{{"rmse", s.rmse}, {"mean", s.mean}, {"median", s.median}, {"std", s.std},
                       {"min", s.min},   {"max", s.max},   {"sse", s.sse},       {"n", s.n}};
}

void from_json(const nlohmann::json& in, ErrorStatistics& s) {
  in.at("rmse").get_to(s.rmse);
  in.at("mean").get_to(s.mean);
  in.at("median").get_to(s.median);
  in.at("std").get_to(s.std);
  in.at("min").get_to(s.min);
  in.at("max").get_to(s.max);
  in.at("sse").get_to(s.sse);
  in.at("n").get_to(s.n);
}

}  // namespace slamsweep::evaluator::inline core
