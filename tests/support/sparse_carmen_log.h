#pragma once

// A five-scan CARMEN log whose scans are metres apart, with its spacing worked out by hand: the fixture of
// the scan-spacing checks of `data info`, the worker's result.json and `run`'s warning.

#include <string>

namespace slamsweep::testing {

/// FLASER records at 10, 11, 13, 13.5 and 15.5 s, each pose equal to its odometry: (0, 0, 0), (5, 0, 0),
/// (5, 12, 0.3), (5, 12, 0.3), (8, 16, -0.2). Sorted steps and percentiles (rank (n - 1) * p, interpolated):
/// gaps 0.5 1 2 2 s: median 1.5, p95 2; travel 0 5 5 12 m: median 5, p95 5 + 0.85 * 7 = 10.95;
/// rotation 0 0 0.3 0.5 rad: median 0.15, p95 0.3 + 0.85 * 0.2 = 0.47.
inline std::string SparseCarmenLog() {
  std::string text;
  const char* poses[] = {"0 0 0", "5 0 0", "5 12 0.3", "5 12 0.3", "8 16 -0.2"};
  const char* stamps[] = {"10", "11", "13", "13.5", "15.5"};
  for (int i = 0; i < 5; ++i) {
    text += std::string("FLASER 3 1.5 2.5 3.5 ") + poses[i] + " " + poses[i] + " " + stamps[i] + " host " + stamps[i] +
            "\n";
  }
  return text;
}

inline constexpr double kSparseLogMedianGapS = 1.5;
inline constexpr double kSparseLogP95GapS = 2.0;
inline constexpr double kSparseLogMedianTravelM = 5.0;
inline constexpr double kSparseLogP95TravelM = 10.95;
inline constexpr double kSparseLogMedianRotationRad = 0.15;
inline constexpr double kSparseLogP95RotationRad = 0.47;

}  // namespace slamsweep::testing
