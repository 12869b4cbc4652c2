#pragma once

#include <cstddef>

namespace slamsweep::evaluator::inline sequence {

/// Beam directions of a scan in the sensor frame: beam i at angle_min_rad + i * angle_increment_rad.
struct BeamFan {
  double angle_min_rad = 0.0;
  double angle_increment_rad = 0.0;
  /// False when the beam count is none of the SICK layouts CARMEN knows, and the fan is a guess.
  bool known_layout = true;
};

/// The fan of an old-style CARMEN FLASER record, which states only its beam count. As CARMEN's own
/// log reader: the fan starts at -90 deg and turns counter-clockwise; 181 and 361 beams cover
/// -90..+90 deg inclusive (1 and 0.5 deg steps, 180 / (n - 1)); 180 and 360 beams are the same
/// scanner with its last beam dropped (1 and 0.5 deg steps, 180 / n, ending at +89 and +89.5 deg).
/// Any other count n >= 2 is spread over 180 deg in n - 1 steps, CARMEN's fallback, with
/// known_layout = false. Throws InputError for n < 2 (no fan can be inferred).
BeamFan FlaserBeamFan(std::size_t beam_count);

}  // namespace slamsweep::evaluator::inline sequence
