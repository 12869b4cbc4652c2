#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace slamsweep::report::inline model {

/// The five numbers a boxplot draws, plus the mean and the count: Tukey's box. Quartiles are
/// interpolated linearly between order statistics (numpy's default, R's type 7); the whiskers end
/// at the most extreme values within 1.5 interquartile ranges of the box, and values beyond them are
/// counted as outliers (the figures leave them out and say how many).
struct BoxSummary {
  std::size_t n = 0;
  double whisker_low = 0.0;
  double q1 = 0.0;
  double median = 0.0;
  double q3 = 0.0;
  double whisker_high = 0.0;
  double mean = 0.0;
  std::size_t outliers = 0;
};

/// The quantile `p` in [0, 1] of ascending `sorted` values (non-empty), by linear interpolation.
double InterpolatedQuantile(const std::vector<double>& sorted, double p);

/// nullopt for no finite value; non-finite values are left out.
std::optional<BoxSummary> SummarizeBox(std::vector<double> values);

}  // namespace slamsweep::report::inline model
