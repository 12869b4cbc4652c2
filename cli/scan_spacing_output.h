#pragma once

#include <optional>
#include <ostream>

#include "evaluator/sequence/scan_spacing.h"

namespace slamsweep::cli {

/// `slamsweep data info`'s lines on how far apart consecutive scans are (median and 95th percentile of
/// the time gap, travel and rotation), and a "warning:" line when they are too far apart for scan matching.
void PrintScanSpacing(const std::optional<evaluator::ScanSpacing>& spacing, std::ostream& out);

}  // namespace slamsweep::cli
