#include "evaluator/sequence/flaser_fan.h"

#include <numbers>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline sequence {

BeamFan FlaserBeamFan(std::size_t beam_count) {
  if (beam_count < 2) {
    throw InputError("FLASER with " + std::to_string(beam_count) +
                     " readings: expected at least 2 (SICK layouts: 180, 181, 360 or 361) to infer the beam fan");
  }
  constexpr double kPi = std::numbers::pi;
  BeamFan fan;
  fan.angle_min_rad = -kPi / 2.0;
  switch (beam_count) {
    case 180:
    case 360:
      fan.angle_increment_rad = kPi / static_cast<double>(beam_count);
      break;
    case 181:
    case 361:
      fan.angle_increment_rad = kPi / static_cast<double>(beam_count - 1);
      break;
    default:
      fan.angle_increment_rad = kPi / static_cast<double>(beam_count - 1);
      fan.known_layout = false;
      break;
  }
  return fan;
}

}  // namespace slamsweep::evaluator::inline sequence
