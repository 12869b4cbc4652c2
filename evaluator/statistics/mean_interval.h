#pragma once

#include <optional>
#include <span>

namespace slamsweep::evaluator::inline statistics {

/// A confidence interval of a mean.
struct MeanInterval {
  double mean = 0.0;
  double low = 0.0;
  double high = 0.0;
};

/// Student's t interval of the mean of `values` at `confidence` (0.95: mean +- t_{0.975, n-1} s / sqrt(n)).
/// None with fewer than two values (no spread to estimate); a zero-width interval when every value is equal.
std::optional<MeanInterval> StudentTInterval(std::span<const double> values, double confidence = 0.95);

}  // namespace slamsweep::evaluator::inline statistics
