#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace slamsweep::evaluator::inline borders {

/// A point in the plane; the unit is the caller's (cells for traced borders).
struct PlanarPoint {
  double x = 0.0;
  double y = 0.0;
};

/// Douglas-Peucker simplification of a closed ring (the last point joins the first; the
/// closing point is not repeated). Returns the indices of the kept points in ascending order,
/// so the ring's orientation is kept. A point is kept when it lies more than `tolerance` from
/// the segment between the kept points around it; with tolerance 0 exactly collinear points
/// are dropped. Distances are to the segment, not its line, so a ring that doubles back on
/// itself (a one-cell-wide wall walked there and back) keeps its far end.
/// A ring has no natural first point, so the two anchors that are never dropped are chosen
/// from its shape, not its numbering: the point farthest from point 0, then the point
/// farthest from that one -- both are extreme points, which any simplification keeps.
/// Iterative (an explicit stack), so a border of millions of points cannot overflow the call
/// stack. Rings of at most 2 points are returned whole; a ring whose points all coincide
/// gives {0}. Throws InputError when `tolerance` is negative or not finite.
std::vector<std::size_t> SimplifyClosedRing(std::span<const PlanarPoint> ring, double tolerance);

/// SimplifyClosedRing with buffers kept between calls, for simplifying many rings (every
/// border of a map) without allocating for each. Not thread-safe: one per thread.
class RingSimplifier {
 public:
  /// Same contract as SimplifyClosedRing; the result is valid until the next call.
  std::span<const std::size_t> Simplify(std::span<const PlanarPoint> ring, double tolerance);

 private:
  struct Chain {
    std::size_t first;
    std::size_t last;
  };
  std::vector<PlanarPoint> points_;
  std::vector<std::uint8_t> keep_;
  std::vector<Chain> stack_;
  std::vector<std::size_t> kept_;
};

}  // namespace slamsweep::evaluator::inline borders
