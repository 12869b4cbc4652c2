#include "evaluator/formats/trajectory/planarity.h"

#include <cmath>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {

void RequirePlanar(const Trajectory& trajectory, std::string_view what, double tolerance) {
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const Pose& pose = trajectory.poses()[i];
    if (std::abs(pose.position.z()) > tolerance || std::abs(pose.orientation.x()) > tolerance ||
        std::abs(pose.orientation.y()) > tolerance) {
      throw InputError("pose " + std::to_string(i) + " is not planar (z = " + std::to_string(pose.position.z()) +
                       " m or a rotation not about z); " + std::string(what) +
                       " holds planar poses only: write TUM, KITTI or CSV instead");
    }
  }
}

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
