#include "evaluator/statistics/mean_interval.h"

#include <cmath>

#include <boost/math/distributions/students_t.hpp>

namespace slamsweep::evaluator::inline statistics {

std::optional<MeanInterval> StudentTInterval(std::span<const double> values, double confidence) {
  if (values.size() < 2) return std::nullopt;
  const double n = static_cast<double>(values.size());
  double sum = 0.0;
  for (const double v : values) sum += v;
  const double mean = sum / n;
  double squares = 0.0;
  for (const double v : values) squares += (v - mean) * (v - mean);
  const double standard_error = std::sqrt(squares / (n - 1.0)) / std::sqrt(n);
  const boost::math::students_t distribution(n - 1.0);
  const double t = boost::math::quantile(distribution, 0.5 + confidence / 2.0);
  return MeanInterval{mean, mean - t * standard_error, mean + t * standard_error};
}

}  // namespace slamsweep::evaluator::inline statistics
