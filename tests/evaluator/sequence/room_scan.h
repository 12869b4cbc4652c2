#pragma once

#include "evaluator/core/laser_scan.h"
#include "evaluator/core/pose.h"

namespace slamsweep::evaluator::testing {

/// A 361-beam, 180 deg scan of a 6 m x 4 m room (walls x = -1 and 5, y = -2 and 2) with a square
/// pillar 0.4 m wide at (3, 1), taken by a robot at `robot` (the room's frame), ray-cast exactly.
LaserScan RoomScan(const Pose& robot);

}  // namespace slamsweep::evaluator::testing
