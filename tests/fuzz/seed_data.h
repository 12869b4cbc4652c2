#pragma once

// Inputs the fuzz targets start from, made by slamsweep's own writers from simulated data, and the checks
// the sequence and trajectory targets share.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/sequence/robot_log.h"
#include "evaluator/sequence/sequence.h"

namespace slamsweep::fuzz {

/// The first `scans` scans of a small simulated run (one room each side of a corridor), `beams` beams over
/// `fov_rad` (181 over pi is a CARMEN FLASER fan), with their odometry.
evaluator::RobotLog SeedLog(std::size_t scans, int beams, double fov_rad);

/// The ground truth of that run at the same scans.
evaluator::Trajectory SeedGroundTruth(std::size_t scans);

/// A small occupancy grid (40 x 30 cells: walls, free space, an unknown border and grey cells).
evaluator::OccupancyGrid SeedGrid();

/// The bytes of a file (one that a writer just wrote).
std::string FileBytes(const std::filesystem::path& path);

/// The checks of a sequence reader: `read` returns or throws InputError naming `file`, and a sequence read
/// without error is valid (ValidateSequence); anything else is a finding.
void CheckSequenceRead(const std::filesystem::path& file, const std::function<evaluator::Sequence()>& read);

}  // namespace slamsweep::fuzz
