#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace slamsweep::evaluator::inline statistics {

/// The 1-based ranks of `values` in ascending order; tied values share the mean of the ranks they
/// occupy ("average" or mid-ranks, as scipy.stats.rankdata's default). Values must be finite.
std::vector<double> AverageRanks(std::span<const double> values);

/// Spearman's rank correlation: the Pearson correlation of the average ranks of x and y (so ties
/// are handled exactly, as scipy.stats.spearmanr does). Undefined (nullopt) when the spans differ
/// in length, hold fewer than 2 pairs, or either variable is constant.
std::optional<double> SpearmanRho(std::span<const double> x, std::span<const double> y);

/// Spearman's rho pooled over strata, for samples whose raw values must not be ranked together
/// (different sequences, different noise settings). Within each stratum (samples with the same
/// `strata` id) x and y are ranked separately, each rank is centred on the stratum's mean rank
/// and divided by the stratum's size; the result is the Pearson correlation of these pooled
/// within-stratum ranks (about the size-weighted mean of the strata's own rhos). With one stratum
/// it equals SpearmanRho. A stratum of one sample carries no order and adds nothing. Undefined
/// when no stratum has two samples or either variable is constant within every stratum.
std::optional<double> StratifiedSpearmanRho(std::span<const double> x, std::span<const double> y,
                                            std::span<const std::size_t> strata);

/// The paired samples of one stratum.
struct PairedStratum {
  std::vector<double> x;
  std::vector<double> y;
};

/// StratifiedSpearmanRho of samples already grouped by stratum (the bootstrap's inner loop).
std::optional<double> PooledRankCorrelation(const std::vector<PairedStratum>& strata);

/// The pooled correlation of within-stratum ranks already computed (AverageRanks of each stratum's x and y):
/// PooledRankCorrelation's arithmetic, in its order, so both give the same double. Strata whose x and y ranks
/// differ in length make it undefined.
std::optional<double> PooledCorrelationOfRanks(const std::vector<std::vector<double>>& x_ranks,
                                               const std::vector<std::vector<double>>& y_ranks);

/// The samples grouped by stratum id, strata in ascending id order, samples in input order.
std::vector<PairedStratum> GroupIntoStrata(std::span<const double> x, std::span<const double> y,
                                           std::span<const std::size_t> strata);

}  // namespace slamsweep::evaluator::inline statistics
