#include "evaluator/statistics/friedman.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "evaluator/statistics/rank_correlation.h"

namespace slamsweep::evaluator::inline statistics {

FriedmanResult FriedmanTest(const std::vector<std::vector<double>>& values) {
  if (values.size() < 2) throw std::invalid_argument("Friedman test: needs at least 2 data sets");
  const std::size_t k = values.front().size();
  if (k < 2) throw std::invalid_argument("Friedman test: needs at least 2 contestants");
  FriedmanResult result;
  result.data_sets = values.size();
  result.contestants = k;
  result.mean_ranks.assign(k, 0.0);
  double tied_cubes = 0.0;  // sum over groups of tied values of t^3 - t
  for (std::size_t d = 0; d < values.size(); ++d) {
    const std::vector<double>& row = values[d];
    if (row.size() != k) {
      throw std::invalid_argument("Friedman test: data set " + std::to_string(d) + " has " +
                                  std::to_string(row.size()) + " values, expected " + std::to_string(k));
    }
    for (const double v : row) {
      if (!std::isfinite(v))
        throw std::invalid_argument("Friedman test: a non-finite value in data set " + std::to_string(d));
    }
    const std::vector<double> ranks = AverageRanks(row);
    for (std::size_t c = 0; c < k; ++c) result.mean_ranks[c] += ranks[c];
    std::map<double, std::size_t> counts;
    for (const double v : row) ++counts[v];
    for (const auto& [value, t] : counts) {
      const double tt = static_cast<double>(t);
      tied_cubes += tt * tt * tt - tt;
    }
  }
  const double n = static_cast<double>(values.size());
  const double kk = static_cast<double>(k);
  double rank_sum_squares = 0.0;
  for (double& r : result.mean_ranks) {
    rank_sum_squares += r * r;
    r /= n;
  }
  result.tie_correction = 1.0 - tied_cubes / (n * kk * (kk * kk - 1.0));
  if (result.tie_correction <= 0.0) {
    result.all_tied = true;
    return result;
  }
  const double chi2 = (12.0 / (n * kk * (kk + 1.0)) * rank_sum_squares - 3.0 * n * (kk + 1.0)) / result.tie_correction;
  result.chi_square = std::max(0.0, chi2);
  result.chi_square_p =
      boost::math::cdf(boost::math::complement(boost::math::chi_squared(kk - 1.0), result.chi_square));
  const double denominator = n * (kk - 1.0) - result.chi_square;
  if (denominator <= 0.0) {
    result.iman_davenport_f = std::numeric_limits<double>::infinity();
    result.iman_davenport_p = 0.0;
  } else {
    result.iman_davenport_f = (n - 1.0) * result.chi_square / denominator;
    const boost::math::fisher_f f(kk - 1.0, (kk - 1.0) * (n - 1.0));
    result.iman_davenport_p = boost::math::cdf(boost::math::complement(f, result.iman_davenport_f));
  }
  return result;
}

double StudentizedRangeCdf(double q, std::size_t k) {
  if (k < 2) throw std::invalid_argument("studentized range: needs k >= 2");
  if (q <= 0.0) return 0.0;
  const boost::math::normal normal;
  // P(range <= q) = k * integral of phi(z) (Phi(z) - Phi(z - q))^(k - 1) dz: the lowest draw at z, the others
  // within [z, z + q] (by symmetry, within [z - q, z] of the highest).
  const auto integrand = [&](double z) {
    const double inside = boost::math::cdf(normal, z) - boost::math::cdf(normal, z - q);
    return boost::math::pdf(normal, z) * std::pow(inside, static_cast<double>(k - 1));
  };
  const double integral =
      boost::math::quadrature::gauss_kronrod<double, 61>::integrate(integrand, -12.0, 12.0 + q, 15, 1e-14);
  return std::clamp(static_cast<double>(k) * integral, 0.0, 1.0);
}

double StudentizedRangeUpperQuantile(double alpha, std::size_t k) {
  if (!(alpha > 0.0 && alpha < 1.0)) throw std::invalid_argument("studentized range: alpha must lie in (0, 1)");
  double low = 0.0;
  double high = 40.0;
  for (int i = 0; i < 200 && high - low > 1e-13; ++i) {
    const double mid = 0.5 * (low + high);
    (StudentizedRangeCdf(mid, k) < 1.0 - alpha ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

double NemenyiCriticalDifference(std::size_t contestants, std::size_t data_sets, double alpha) {
  if (contestants < 2 || data_sets < 1) throw std::invalid_argument("Nemenyi: needs 2 contestants and a data set");
  const double k = static_cast<double>(contestants);
  return StudentizedRangeUpperQuantile(alpha, contestants) / std::sqrt(2.0) *
         std::sqrt(k * (k + 1.0) / (6.0 * static_cast<double>(data_sets)));
}

std::size_t DataSetsNeeded(std::size_t contestants, double rank_difference, double alpha, std::size_t max_data_sets) {
  if (!(rank_difference > 0.0)) return 0;
  // CD(N) = CD(1) / sqrt(N): the first N with CD(N) <= difference, from the closed form, checked around it.
  const double cd_one = NemenyiCriticalDifference(contestants, 1, alpha);
  const double estimate = std::ceil(cd_one * cd_one / (rank_difference * rank_difference));
  if (estimate > static_cast<double>(max_data_sets)) return 0;
  std::size_t n = std::max<std::size_t>(1, static_cast<std::size_t>(estimate));
  while (n > 1 && cd_one / std::sqrt(static_cast<double>(n - 1)) <= rank_difference) --n;
  while (cd_one / std::sqrt(static_cast<double>(n)) > rank_difference) ++n;
  return n <= max_data_sets ? n : 0;
}

}  // namespace slamsweep::evaluator::inline statistics
