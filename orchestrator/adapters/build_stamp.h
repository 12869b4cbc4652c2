#pragma once

#include <vector>

#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline adapters {

/// Fills every run's `build` (SlamsweepRevision() and the SHA-256 of each of its
/// ProgramFilesOf) and `seeding` (SeedingOf; program_identity.h). Each file is read once however many runs
/// share it. Throws InputError naming the algorithm when a program file is missing or unreadable:
/// a sweep whose program cannot run stops before any run starts.
void StampBuildIdentity(std::vector<RunSpec>& runs);

}  // namespace slamsweep::orchestrator::inline adapters
