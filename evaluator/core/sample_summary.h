#pragma once

#include <cstddef>
#include <optional>
#include <span>

namespace slamsweep::evaluator::inline core {

/// Mean and sample standard deviation of one metric over the iterations of one comparison group
/// (the paper's "mean +- std"), as the report and summary.json/csv compute it. std uses n - 1 and
/// is absent for n < 2 (undefined, shown as "n/a"), never 0, so one iteration does not pass for a
/// perfectly repeatable one.
struct MeanStd {
  std::size_t n = 0;
  double mean = 0.0;
  std::optional<double> std;
  double min = 0.0;
  double max = 0.0;
};

/// Mean, sample std (n - 1), min and max of `values`; n = 0 gives {n = 0}.
MeanStd ComputeMeanStd(std::span<const double> values);

}  // namespace slamsweep::evaluator::inline core
