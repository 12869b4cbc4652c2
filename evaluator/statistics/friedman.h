#pragma once

#include <cstddef>
#include <vector>

namespace slamsweep::evaluator::inline statistics {

/// Demšar's (2006) comparison of k contestants over N data sets: the Friedman test on the contestants' ranks
/// within each data set, the Iman-Davenport F that corrects its conservatism, and the mean ranks the
/// Nemenyi post-hoc test compares.
struct FriedmanResult {
  std::size_t data_sets = 0;    ///< N
  std::size_t contestants = 0;  ///< k
  /// Per contestant, its rank averaged over the data sets (1 = lowest value; tied values share the mean of
  /// the ranks they occupy).
  std::vector<double> mean_ranks;
  /// Friedman's chi-square, divided by the tie correction 1 - sum(t^3 - t) / (N k (k^2 - 1)) over the groups
  /// of t tied values (as scipy.stats.friedmanchisquare); k - 1 degrees of freedom.
  double chi_square = 0.0;
  double chi_square_p = 1.0;
  /// The tie correction's divisor (1 without ties).
  double tie_correction = 1.0;
  /// Iman and Davenport's F = (N - 1) chi2 / (N (k - 1) - chi2) with (k - 1, (k - 1)(N - 1)) degrees of freedom,
  /// and its p-value; infinite with p = 0 when every data set ranks the contestants alike.
  double iman_davenport_f = 0.0;
  double iman_davenport_p = 1.0;
  /// Every value of every data set equal: no statistic (p = 1).
  bool all_tied = false;
};

/// `values[d][c]` is contestant c's value on data set d, lower being better. Throws std::invalid_argument for
/// fewer than 2 data sets or 2 contestants, rows of unequal length, or a non-finite value.
FriedmanResult FriedmanTest(const std::vector<std::vector<double>>& values);

/// The studentized range distribution with infinite degrees of freedom (the range of k standard normal
/// draws): P(range <= q).
double StudentizedRangeCdf(double q, std::size_t k);

/// Its upper quantile: the q with P(range > q) = alpha.
double StudentizedRangeUpperQuantile(double alpha, std::size_t k);

/// Nemenyi's critical difference of mean ranks: q_alpha / sqrt(2) * sqrt(k (k + 1) / (6 N)). Two contestants
/// whose mean ranks differ by at least this much differ at level alpha (two-sided, all pairs at once).
double NemenyiCriticalDifference(std::size_t contestants, std::size_t data_sets, double alpha = 0.05);

/// The fewest data sets at which the critical difference is at most `rank_difference` (a difference of mean
/// ranks that large would then be significant); 0 when more than `max_data_sets` would be needed.
std::size_t DataSetsNeeded(std::size_t contestants, double rank_difference, double alpha = 0.05,
                           std::size_t max_data_sets = 10000);

}  // namespace slamsweep::evaluator::inline statistics
