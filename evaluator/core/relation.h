#pragma once

#include <vector>

#include "evaluator/core/pose.h"

namespace slamsweep::evaluator::inline core {

/// One Kuemmerle et al. (2009) relation: the pose at t2_s expressed in the frame of the
/// pose at t1_s, as measured on the reference (relations files: `t1 t2 x y z roll pitch yaw`).
struct Relation {
  double t1_s = 0.0;
  double t2_s = 0.0;
  Pose delta;
};

using Relations = std::vector<Relation>;

}  // namespace slamsweep::evaluator::inline core
