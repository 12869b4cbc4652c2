#include "evaluator/borders/polygon_simplify.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline borders {
namespace {

double SquaredDistance(const PlanarPoint& a, const PlanarPoint& b) {
  const double dx = a.x - b.x;
  const double dy = a.y - b.y;
  return dx * dx + dy * dy;
}

std::size_t Farthest(std::span<const PlanarPoint> ring, const PlanarPoint& from) {
  std::size_t best = 0;
  double best_distance2 = -1.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const double distance2 = SquaredDistance(ring[i], from);
    if (distance2 > best_distance2) {
      best_distance2 = distance2;
      best = i;
    }
  }
  return best;
}

// The point of points[first + 1 .. last - 1] farthest from the segment points[first] -
// points[last] (the first one on ties), and whether it lies more than `tolerance2`^(1/2) away.
// Distances are compared multiplied by the squared segment length, which is the same for the
// whole chain, so the loop needs no division (the divide dominated the run time).
struct Farthest2 {
  std::size_t index;
  bool beyond_tolerance;
};
Farthest2 FarthestFromSegment(const std::vector<PlanarPoint>& points, std::size_t first, std::size_t last,
                              double tolerance2) {
  const PlanarPoint a = points[first];
  const PlanarPoint b = points[last];
  const double abx = b.x - a.x;
  const double aby = b.y - a.y;
  const double length2 = abx * abx + aby * aby;
  std::size_t worst = first + 1;
  double worst_scaled = -1.0;
  if (length2 == 0.0) {  // the chain returns to its start: distance to that point
    for (std::size_t i = first + 1; i < last; ++i) {
      const double scaled = SquaredDistance(points[i], a);
      if (scaled > worst_scaled) {
        worst_scaled = scaled;
        worst = i;
      }
    }
    return {worst, worst_scaled > tolerance2};
  }
  for (std::size_t i = first + 1; i < last; ++i) {
    const double apx = points[i].x - a.x;
    const double apy = points[i].y - a.y;
    const double along = apx * abx + apy * aby;
    double scaled;  // squared distance to the segment times length2
    if (along <= 0.0) {
      scaled = (apx * apx + apy * apy) * length2;
    } else if (along >= length2) {
      scaled = SquaredDistance(points[i], b) * length2;
    } else {
      const double cross = apx * aby - apy * abx;
      scaled = cross * cross;
    }
    if (scaled > worst_scaled) {
      worst_scaled = scaled;
      worst = i;
    }
  }
  return {worst, worst_scaled > tolerance2 * length2};
}

}  // namespace

std::span<const std::size_t> RingSimplifier::Simplify(std::span<const PlanarPoint> ring, double tolerance) {
  if (!std::isfinite(tolerance) || tolerance < 0.0) {
    throw InputError(fmt::format("simplification tolerance: expected a finite number >= 0, got {}", tolerance));
  }
  const std::size_t n = ring.size();
  kept_.clear();
  if (n <= 2) {
    for (std::size_t i = 0; i < n; ++i) kept_.push_back(i);
    return kept_;
  }
  const std::size_t anchor_a = Farthest(ring, ring[0]);
  if (SquaredDistance(ring[anchor_a], ring[0]) == 0.0) {
    kept_.push_back(0);
    return kept_;
  }
  const std::size_t anchor_b = Farthest(ring, ring[anchor_a]);

  // Rotate the ring so that it starts at the lower anchor and repeat that point at the end:
  // the two chains between the anchors are then plain index ranges [0, mid] and [mid, n], and
  // the inner loop needs no modulo.
  const std::size_t low = std::min(anchor_a, anchor_b);
  const std::size_t mid = std::max(anchor_a, anchor_b) - low;
  points_.clear();
  points_.insert(points_.end(), ring.begin() + static_cast<std::ptrdiff_t>(low), ring.end());
  points_.insert(points_.end(), ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(low) + 1);

  keep_.assign(n + 1, 0);
  keep_[0] = 1;
  keep_[mid] = 1;
  const double tolerance2 = tolerance * tolerance;
  stack_.clear();
  stack_.push_back({0, mid});
  stack_.push_back({mid, n});
  while (!stack_.empty()) {
    const Chain chain = stack_.back();
    stack_.pop_back();
    if (chain.last - chain.first < 2) continue;
    const Farthest2 worst = FarthestFromSegment(points_, chain.first, chain.last, tolerance2);
    if (!worst.beyond_tolerance) continue;
    keep_[worst.index] = 1;
    stack_.push_back({chain.first, worst.index});
    stack_.push_back({worst.index, chain.last});
  }
  // Back to the caller's numbering, ascending: rotated index k is original index low + k (mod n).
  for (std::size_t k = n - low; k < n; ++k) {
    if (keep_[k] != 0) kept_.push_back(k - (n - low));
  }
  for (std::size_t k = 0; k < n - low; ++k) {
    if (keep_[k] != 0) kept_.push_back(low + k);
  }
  return kept_;
}

std::vector<std::size_t> SimplifyClosedRing(std::span<const PlanarPoint> ring, double tolerance) {
  RingSimplifier simplifier;
  const std::span<const std::size_t> kept = simplifier.Simplify(ring, tolerance);
  return {kept.begin(), kept.end()};
}

}  // namespace slamsweep::evaluator::inline borders
