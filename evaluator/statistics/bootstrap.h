#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "evaluator/statistics/rank_correlation.h"

namespace slamsweep::evaluator::inline statistics {

/// How a bootstrap interval is drawn. The seed is fixed so that a report is reproducible: the
/// same runs give the same interval on every machine (evaluator/noise/random.h draws the indices).
struct BootstrapOptions {
  std::size_t resamples = 2000;
  std::uint64_t seed = 20170517;
  double confidence = 0.95;
  /// The interval is undefined when fewer resamples than this share give a defined statistic:
  /// percentiles of the few non-degenerate resamples would describe another sample.
  double min_defined_fraction = 0.5;
};

/// A percentile bootstrap interval and how many resamples it rests on.
struct BootstrapInterval {
  double low = 0.0;
  double high = 0.0;
  std::size_t resamples = 0;
  /// Resamples whose statistic was defined (a resample can draw one value many times and so
  /// be constant); the interval is the percentiles of these.
  std::size_t defined = 0;
};

/// The percentile bootstrap interval of PooledRankCorrelation: each resample draws, within every
/// stratum separately, as many pairs as the stratum holds, uniformly with replacement (so no
/// resample mixes strata or changes their sizes), and computes the pooled rho. The bounds are the
/// (1 - confidence) / 2 and (1 + confidence) / 2 quantiles of the defined resamples, linearly
/// interpolated between order statistics (numpy's default quantile). Undefined when fewer than
/// min_defined_fraction of the resamples give a defined rho, or when options are invalid (no
/// resamples, confidence outside (0, 1)).
std::optional<BootstrapInterval> BootstrapPooledRankCorrelation(const std::vector<PairedStratum>& strata,
                                                                const BootstrapOptions& options = {});

/// The defined replicates of BootstrapPooledRankCorrelation's resamples, ascending, and how many resamples
/// were drawn: the percentile interval at any confidence follows from them without drawing again.
struct BootstrapReplicates {
  std::vector<double> sorted;
  std::size_t resamples = 0;
};

/// BootstrapPooledRankCorrelation's resamples (the same draws), kept; nullopt for invalid options.
std::optional<BootstrapReplicates> PooledRankCorrelationReplicates(const std::vector<PairedStratum>& strata,
                                                                   const BootstrapOptions& options = {});

/// The percentile interval of `replicates` at `confidence` (0 < confidence < 1), as
/// BootstrapPooledRankCorrelation gives it: undefined below min_defined_fraction of defined resamples.
std::optional<BootstrapInterval> PercentileInterval(const BootstrapReplicates& replicates, double confidence,
                                                    double min_defined_fraction);

/// The q-quantile (0 <= q <= 1) of `sorted` (ascending, not empty) by linear interpolation
/// between order statistics: position q (n - 1).
double InterpolatedQuantile(const std::vector<double>& sorted, double q);

}  // namespace slamsweep::evaluator::inline statistics
