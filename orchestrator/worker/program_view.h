#pragma once

#include <string>
#include <vector>

#include "orchestrator/adapters/run_paths.h"
#include "orchestrator/matrix/run_spec.h"
#include "orchestrator/process/file_system_view.h"

namespace slamsweep::orchestrator {

/// Set by `slamsweep serve` for its workers: more folders (':'-separated) a program must not see,
/// such as the service's data folder with every other sweep's results.
inline constexpr const char* kPrivateDirsVariable = "SLAMSWEEP_PRIVATE_DIRS";

/// What a SLAM program may see: its input and output folders (input/, raw/) and the rest of the
/// system, but not the sweep's output folder (run.json, command.txt and every other run's
/// reference.tum and result.json, results.sqlite, the reference-map cache), nor the folders of the
/// catalog files holding its sequence's reference (the log with corrected poses, the relations, a
/// reference map), nor those in SLAMSWEEP_PRIVATE_DIRS. A folder that holds the program itself stays
/// visible (it could not start otherwise), with a warning naming it.
FileSystemView ProgramFileSystemView(const RunSpec& spec, const RunPaths& paths, const std::string& program,
                                     std::vector<std::string>& warnings);

}  // namespace slamsweep::orchestrator
