#include "cli/scan_spacing_output.h"

#include <fmt/format.h>

namespace slamsweep::cli {

void PrintScanSpacing(const std::optional<evaluator::ScanSpacing>& spacing, std::ostream& out) {
  if (!spacing) {
    out << "scan_spacing: none (fewer than two scans)\n";
    return;
  }
  out << fmt::format(
      "scan_spacing: between consecutive scans ({} steps), median / 95th percentile; travel and rotation from the "
      "odometry poses at the scans (what a SLAM program has)\n"
      "  time gap: {:.3f} s / {:.3f} s\n"
      "  travel:   {:.3f} m / {:.3f} m\n"
      "  rotation: {:.3f} rad / {:.3f} rad\n",
      spacing->steps, spacing->gap_s.median, spacing->gap_s.p95, spacing->travel_m.median, spacing->travel_m.p95,
      spacing->rotation_rad.median, spacing->rotation_rad.p95);
  const std::optional<bool> sparse = evaluator::TooSparseForScanMatching(*spacing);
  if (!sparse) {
    out << "  the odometry never moves: travel and rotation say nothing about the scans' density\n";
  } else if (*sparse) {
    out << "warning: " << evaluator::SparseScanWarning(*spacing) << "\n";
  } else {
    out << fmt::format("  dense enough for scan matching (median travel within {:.2f} m, docs/data-density.md)\n",
                       evaluator::SparseScanThresholdInUse().median_travel_m);
  }
}

}  // namespace slamsweep::cli
