#pragma once

#include <ostream>
#include <set>
#include <string>

namespace slamsweep::cli {

/// The roster algorithms among `adapters` whose upstream or driver is not installed, built now: before any
/// worker starts (`plan` and `run` call it; workers, Slurm tasks and `serve` never do). Under an exclusive
/// lock on the roster prefix (another slamsweep installing waits, then finds it installed), for each
/// missing upstream scripts/install-slam.sh UPSTREAM (seconds when ~/.cache/slamsweep holds its build),
/// then the build tree reconfigured and the drivers built, with a progress line and an estimate on
/// `progress`. Only a program run from its build tree builds (not an installation, nor with
/// $SLAMSWEEP_SLAM_PREFIX or $SLAMSWEEP_SLAM_DRIVER_DIR set, nor with $SLAMSWEEP_NO_ROSTER_BUILD=1): otherwise
/// nothing is done and loading the sweep names the install command. Throws InputError when a step fails.
void InstallMissingRoster(const std::set<std::string>& adapters, std::ostream& progress);

}  // namespace slamsweep::cli
