#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "orchestrator/service/sweep_entry.h"

namespace slamsweep::orchestrator::service {

/// Run ids whose worker is running, each with its sweep's id.
using RunningRuns = std::map<std::string, std::int64_t>;

/// Whether `entry` competes for the pool's next slot: active, not being cancelled, with runs to start.
bool WantsASlot(const SweepEntry& entry);

/// The sweep whose run takes the next free slot. Among `candidates` (WantsASlot) with a run that
/// can start now (a run whose identical twin is running elsewhere waits for it), the highest priority
/// first; between equal priorities the sweep with the fewest runs running, then the one that waited
/// longest since it last started a run, then the oldest: fair shares of the pool. nullptr when no
/// candidate can start a run now.
SweepEntry* NextSweep(const std::vector<SweepEntry*>& candidates, const RunningRuns& running);

/// Takes `entry`'s first pending run that does not wait for a running twin off its pending list and
/// returns its index; `entry` must be one NextSweep chose.
std::size_t TakeStartableRun(SweepEntry& entry, const RunningRuns& running);

}  // namespace slamsweep::orchestrator::service
