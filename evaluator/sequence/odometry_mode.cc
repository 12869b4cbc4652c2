#include "evaluator/sequence/odometry_mode.h"

#include <fmt/format.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline sequence {

std::string_view OdometryModeName(OdometryMode mode) {
  return mode == OdometryMode::kRecorded ? "recorded" : "reference";
}

OdometryMode ParseOdometryMode(std::string_view text, std::string_view option) {
  for (OdometryMode mode : {OdometryMode::kRecorded, OdometryMode::kReference}) {
    if (text == OdometryModeName(mode)) return mode;
  }
  throw InputError(fmt::format("{}: expected recorded or reference, got '{}'", option, text));
}

}  // namespace slamsweep::evaluator::inline sequence
