#pragma once

#include "orchestrator/service/queue_store.h"

namespace slamsweep::orchestrator::service {

/// Sweep "s" (s.yaml, submitted by "me"), ready for QueueStore::AddSweep.
inline QueuedSweep SweepNamedS() {
  QueuedSweep sweep;
  sweep.name = "s";
  sweep.config_name = "s.yaml";
  sweep.config_text = "name: s";
  sweep.submitter = "me";
  return sweep;
}

}  // namespace slamsweep::orchestrator::service
