#include "orchestrator/service/fair_share.h"

#include <algorithm>
#include <tuple>

namespace slamsweep::orchestrator::service {
namespace {

bool WaitsForTwin(const SweepEntry& entry, std::size_t index, const RunningRuns& running) {
  return running.count(entry.runs[index].view.run_id) > 0;
}

}  // namespace

bool WantsASlot(const SweepEntry& entry) {
  return entry.active && !entry.sweep.cancel_requested && !entry.pending.empty();
}

SweepEntry* NextSweep(const std::vector<SweepEntry*>& candidates, const RunningRuns& running) {
  SweepEntry* best = nullptr;
  for (SweepEntry* entry : candidates) {
    const bool startable = std::any_of(entry->pending.begin(), entry->pending.end(),
                                       [&](std::size_t index) { return !WaitsForTwin(*entry, index, running); });
    if (!startable) continue;
    if (best == nullptr) {
      best = entry;
      continue;
    }
    const auto key = [](const SweepEntry* e) {
      return std::make_tuple(-e->sweep.priority, e->running, e->last_start_tick, e->sweep.id);
    };
    if (key(entry) < key(best)) best = entry;
  }
  return best;
}

std::size_t TakeStartableRun(SweepEntry& entry, const RunningRuns& running) {
  const auto position = std::find_if(entry.pending.begin(), entry.pending.end(),
                                     [&](std::size_t index) { return !WaitsForTwin(entry, index, running); });
  const std::size_t index = *position;
  entry.pending.erase(position);
  return index;
}

}  // namespace slamsweep::orchestrator::service
