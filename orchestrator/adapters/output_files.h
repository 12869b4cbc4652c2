#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "evaluator/core/laser_scan.h"
#include "evaluator/core/occupancy_grid.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/formats/map/map_options.h"
#include "evaluator/formats/trajectory/trajectory_file.h"
#include "orchestrator/adapters/run_paths.h"

namespace slamsweep::orchestrator::inline adapters {

/// `file` relative to the run folder when it lies inside it ("raw/map.yaml"), for reasons that
/// stay readable and do not depend on where the output directory is.
std::string RunRelative(const RunPaths& paths, const std::filesystem::path& file);

/// Throws RunFailure kMissingOutput "no <what>: <file> missing" unless `file` is a regular file.
void RequireOutputFile(const RunPaths& paths, const std::filesystem::path& file, std::string_view what);

/// ReadMap on a program output: missing -> kMissingOutput, unreadable (InputError) ->
/// kCorruptOutput "corrupt <what>: <reader's message>".
evaluator::OccupancyGrid ReadMapOutput(const RunPaths& paths, const std::filesystem::path& file, std::string_view what,
                                       const evaluator::MapReadOptions& options = {});

/// ReadTrajectoryFile on a program output, failures as ReadMapOutput. The notes of the reader
/// are appended to `warnings`.
evaluator::Trajectory ReadTrajectoryOutput(const RunPaths& paths, const std::filesystem::path& file,
                                           evaluator::TrajectoryFormat format,
                                           const evaluator::TrajectoryReadOptions& options,
                                           std::vector<std::string>& warnings);

/// Files under `dir` whose path relative to it matches the fnmatch(3) pattern `pattern`
/// ('*' does not cross '/'), in lexicographic order of that relative path.
std::vector<std::filesystem::path> GlobFiles(const std::filesystem::path& dir, const std::string& pattern);

/// `name` reduced to [A-Za-z0-9_.-] (others become '_', leading dots dropped; "sequence" when
/// nothing is left), so a sequence name can name the input file.
std::string SafeFileStem(std::string_view name);

/// The scan stamps: step k of an MRPT path is the k-th action/sensory-frame pair, i.e. scan k.
std::vector<double> ScanStamps(std::span<const evaluator::LaserScan> scans);

}  // namespace slamsweep::orchestrator::inline adapters
