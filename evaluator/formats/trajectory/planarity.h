#pragma once

#include <string_view>

#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {

/// Planar formats (x y theta) cannot hold height or tilt; writing them silently would lose it.
/// Throws an InputError naming the first pose with |z|, |qx| or |qy| above `tolerance` and `what`
/// needs planar poses.
void RequirePlanar(const Trajectory& trajectory, std::string_view what, double tolerance = 1e-9);

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
