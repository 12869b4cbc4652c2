#include "evaluator/statistics/bootstrap.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "evaluator/noise/random.h"

namespace slamsweep::evaluator::inline statistics {

double InterpolatedQuantile(const std::vector<double>& sorted, double q) {
  const double position = std::clamp(q, 0.0, 1.0) * static_cast<double>(sorted.size() - 1);
  const std::size_t below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  const double fraction = position - static_cast<double>(below);
  return sorted[below] + fraction * (sorted[above] - sorted[below]);
}

namespace {

// A stratum's values sorted once, so that the average ranks of any resample of it follow from how often each
// distinct value was drawn (a counting pass instead of a sort per resample). The ranks are the same doubles
// AverageRanks gives: one value's positions i..j-1 in the resample's ascending order rank (i + 1 + j) / 2.
class DistinctValues {
 public:
  explicit DistinctValues(const std::vector<double>& values) : group_(values.size()) {
    std::vector<std::size_t> order(values.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
    for (std::size_t i = 0; i < order.size(); ++i) {
      if (i > 0 && !(values[order[i]] == values[order[i - 1]])) ++groups_;
      group_[order[i]] = static_cast<std::uint32_t>(groups_);
    }
    if (!order.empty()) ++groups_;
    counts_.resize(groups_);
    rank_of_group_.resize(groups_);
  }

  /// The distinct value of values[index], counted as drawn once more.
  std::uint32_t Draw(std::size_t index) {
    const std::uint32_t group = group_[index];
    ++counts_[group];
    return group;
  }
  /// After a resample's draws: each drawn group's average rank; the counts start again from zero.
  void RankDrawn() {
    std::size_t start = 0;
    for (std::size_t g = 0; g < groups_; ++g) {
      const std::size_t count = counts_[g];
      if (count == 0) continue;
      rank_of_group_[g] = (static_cast<double>(start + 1) + static_cast<double>(start + count)) / 2.0;
      start += count;
      counts_[g] = 0;
    }
  }
  double Rank(std::uint32_t group) const { return rank_of_group_[group]; }

 private:
  std::vector<std::uint32_t> group_;  ///< per value, the index of its distinct value in ascending order
  std::size_t groups_ = 0;
  std::vector<std::uint32_t> counts_;
  std::vector<double> rank_of_group_;
};

// One stratum's part of every resample: its index sampler, its distinct x and y values, and the groups drawn.
struct StratumResampler {
  explicit StratumResampler(const PairedStratum& stratum)
      : sampler(stratum.x.size()), x(stratum.x), y(stratum.y), x_drawn(stratum.x.size()), y_drawn(stratum.x.size()) {}
  UniformIndexSampler sampler;
  DistinctValues x;
  DistinctValues y;
  std::vector<std::uint32_t> x_drawn;
  std::vector<std::uint32_t> y_drawn;
};

// The rho of one resample: draws every stratum's pairs (the same draws, in the same order, as copying the
// pairs), ranks them by counting and sums exactly as PooledCorrelationOfRanks does (strata in order, pairs
// in draw order), so the value is the same double.
std::optional<double> ResampledRho(RandomEngine& engine, std::vector<StratumResampler>& strata) {
  for (StratumResampler& stratum : strata) {
    const std::size_t n = stratum.x_drawn.size();
    for (std::size_t k = 0; k < n; ++k) {
      const auto drawn = static_cast<std::size_t>(stratum.sampler(engine));
      stratum.x_drawn[k] = stratum.x.Draw(drawn);
      stratum.y_drawn[k] = stratum.y.Draw(drawn);
    }
  }
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  std::size_t used = 0;
  for (StratumResampler& stratum : strata) {
    stratum.x.RankDrawn();
    stratum.y.RankDrawn();
    const std::size_t size = stratum.x_drawn.size();
    if (size < 2) continue;
    const double n = static_cast<double>(size);
    const double mean_rank = (n + 1.0) / 2.0;
    for (std::size_t k = 0; k < size; ++k) {
      const double cx = (stratum.x.Rank(stratum.x_drawn[k]) - mean_rank) / n;
      const double cy = (stratum.y.Rank(stratum.y_drawn[k]) - mean_rank) / n;
      sxy += cx * cy;
      sxx += cx * cx;
      syy += cy * cy;
    }
    used += size;
  }
  if (used < 2 || !(sxx > 0.0) || !(syy > 0.0)) return std::nullopt;
  return std::clamp(sxy / std::sqrt(sxx * syy), -1.0, 1.0);
}

bool AllComparable(const std::vector<PairedStratum>& strata) {
  for (const PairedStratum& stratum : strata) {
    if (stratum.x.size() != stratum.y.size()) return false;
    for (const std::vector<double>* values : {&stratum.x, &stratum.y}) {
      for (const double value : *values) {
        if (std::isnan(value)) return false;
      }
    }
  }
  return true;
}

}  // namespace

std::optional<BootstrapReplicates> PooledRankCorrelationReplicates(const std::vector<PairedStratum>& strata,
                                                                   const BootstrapOptions& options) {
  if (options.resamples == 0 || !(options.confidence > 0.0 && options.confidence < 1.0)) return std::nullopt;
  RandomEngine engine(options.seed);
  BootstrapReplicates out;
  out.resamples = options.resamples;
  std::vector<double>& replicates = out.sorted;
  replicates.reserve(options.resamples);
  if (AllComparable(strata)) {
    // The same draws as the copying path below, ranked by counting.
    std::vector<StratumResampler> resamplers;
    resamplers.reserve(strata.size());
    for (const PairedStratum& stratum : strata) resamplers.emplace_back(stratum);
    for (std::size_t r = 0; r < options.resamples; ++r) {
      if (const std::optional<double> rho = ResampledRho(engine, resamplers)) replicates.push_back(*rho);
    }
  } else {
    std::vector<PairedStratum> resample(strata.size());
    for (std::size_t s = 0; s < strata.size(); ++s) {
      resample[s].x.resize(strata[s].x.size());
      resample[s].y.resize(strata[s].y.size());
    }
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
  }
  std::sort(replicates.begin(), replicates.end());
  return out;
}

std::optional<BootstrapInterval> PercentileInterval(const BootstrapReplicates& replicates, double confidence,
                                                    double min_defined_fraction) {
  if (replicates.resamples == 0 || !(confidence > 0.0 && confidence < 1.0)) return std::nullopt;
  const std::vector<double>& sorted = replicates.sorted;
  if (sorted.empty() ||
      static_cast<double>(sorted.size()) < min_defined_fraction * static_cast<double>(replicates.resamples)) {
    return std::nullopt;
  }
  BootstrapInterval interval;
  interval.low = InterpolatedQuantile(sorted, (1.0 - confidence) / 2.0);
  interval.high = InterpolatedQuantile(sorted, (1.0 + confidence) / 2.0);
  interval.resamples = replicates.resamples;
  interval.defined = sorted.size();
  return interval;
}

std::optional<BootstrapInterval> BootstrapPooledRankCorrelation(const std::vector<PairedStratum>& strata,
                                                                const BootstrapOptions& options) {
  const std::optional<BootstrapReplicates> replicates = PooledRankCorrelationReplicates(strata, options);
  if (!replicates) return std::nullopt;
  return PercentileInterval(*replicates, options.confidence, options.min_defined_fraction);
}

}  // namespace slamsweep::evaluator::inline statistics
