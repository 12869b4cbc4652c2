#include "evaluator/statistics/bootstrap.h"

#include <algorithm>
#include <cmath>

#include "evaluator/noise/random.h"

namespace slamsweep::evaluator {

double InterpolatedQuantile(const std::vector<double>& sorted, double q) {
  const double position = std::clamp(q, 0.0, 1.0) * static_cast<double>(sorted.size() - 1);
  const std::size_t below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  const double fraction = position - static_cast<double>(below);
  return sorted[below] + fraction * (sorted[above] - sorted[below]);
}

std::optional<BootstrapInterval> BootstrapPooledRankCorrelation(const std::vector<PairedStratum>& strata,
                                                                const BootstrapOptions& options) {
  if (options.resamples == 0 || !(options.confidence > 0.0 && options.confidence < 1.0)) return std::nullopt;
  RandomEngine engine(options.seed);
  std::vector<PairedStratum> resample(strata.size());
  for (std::size_t s = 0; s < strata.size(); ++s) {
    resample[s].x.resize(strata[s].x.size());
    resample[s].y.resize(strata[s].y.size());
  }
  std::vector<double> replicates;
  replicates.reserve(options.resamples);
  for (std::size_t r = 0; r < options.resamples; ++r) {
    for (std::size_t s = 0; s < strata.size(); ++s) {
      const std::size_t n = std::min(strata[s].x.size(), strata[s].y.size());
      for (std::size_t k = 0; k < n; ++k) {
        const std::size_t drawn = static_cast<std::size_t>(UniformIndex(engine, n));
        resample[s].x[k] = strata[s].x[drawn];
        resample[s].y[k] = strata[s].y[drawn];
      }
    }
    if (const std::optional<double> rho = PooledRankCorrelation(resample)) replicates.push_back(*rho);
  }
  if (replicates.empty() ||
      static_cast<double>(replicates.size()) < options.min_defined_fraction * static_cast<double>(options.resamples)) {
    return std::nullopt;
  }
  std::sort(replicates.begin(), replicates.end());
  BootstrapInterval interval;
  interval.low = InterpolatedQuantile(replicates, (1.0 - options.confidence) / 2.0);
  interval.high = InterpolatedQuantile(replicates, (1.0 + options.confidence) / 2.0);
  interval.resamples = options.resamples;
  interval.defined = replicates.size();
  return interval;
}

}  // namespace slamsweep::evaluator
