#pragma once

#include <array>
#include <cstdint>

namespace slamsweep::evaluator::inline map_metrics {

/// Counts of an 8-bit image's values.
using Histogram256 = std::array<std::int64_t, 256>;

/// Otsu's threshold of an 8-bit image given by its histogram: the value t maximising the
/// between-class variance of {v <= t} and {v > t}. It reproduces the value OpenCV's
/// threshold(..., THRESH_OTSU) returns for the same image (same recurrence in double
/// precision, first maximum wins, classes holding almost no mass skipped), so that a
/// threshold can be found for many variants of one image from histograms alone.
/// Returns 0 for an empty or single-valued histogram, as OpenCV does.
int OtsuThreshold(const Histogram256& histogram);

}  // namespace slamsweep::evaluator::inline map_metrics
