#include "evaluator/map_metrics/otsu.h"

#include <algorithm>
#include <cfloat>

namespace slamsweep::evaluator::inline map_metrics {

int OtsuThreshold(const Histogram256& histogram) {
  std::int64_t total = 0;
  for (const std::int64_t count : histogram) total += count;
  if (total == 0) return 0;

  // Probabilities are count * (1 / total), as OpenCV scales them; dividing instead would
  // round differently and could pick another value when two variances nearly tie.
  const double inverse_total = 1.0 / static_cast<double>(total);
  double image_mean = 0.0;
  for (int value = 0; value < 256; ++value) image_mean += value * static_cast<double>(histogram[value]);
  image_mean *= inverse_total;

  double low_weight = 0.0;  // probability of {v <= value}
  double low_mean = 0.0;    // mean of {v <= value}
  double best_variance = 0.0;
  int best_value = 0;
  for (int value = 0; value < 256; ++value) {
    const double p = static_cast<double>(histogram[value]) * inverse_total;
    const double low_sum = low_mean * low_weight;  // un-normalise before adding the new value
    low_weight += p;
    const double high_weight = 1.0 - low_weight;
    low_mean = low_sum;
    // A split with (almost) all mass on one side is no split at all. Such a value leaves
    // low_mean un-normalised and does not add its own mass to it; OpenCV's loop behaves the
    // same way, and matching it matters more here than the (negligible) mass it drops.
    if (std::min(low_weight, high_weight) < FLT_EPSILON || std::max(low_weight, high_weight) > 1.0 - FLT_EPSILON) {
      continue;
    }
    low_mean = (low_sum + value * p) / low_weight;
    const double high_mean = (image_mean - low_weight * low_mean) / high_weight;
    const double variance = low_weight * high_weight * (low_mean - high_mean) * (low_mean - high_mean);
    if (variance > best_variance) {
      best_variance = variance;
      best_value = value;
    }
  }
  return best_value;
}

}  // namespace slamsweep::evaluator::inline map_metrics
