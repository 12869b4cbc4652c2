#pragma once

#include "orchestrator/process/process_outcome.h"
#include "orchestrator/process/running_child.h"

namespace slamsweep::orchestrator::inline process {

/// Collects a child that has ended: SIGKILLs its group (so no grandchild outlives it or holds its
/// pipe), drains its output into the log, waits for it with wait4() (rusage) and closes its
/// descriptors. The outcome follows the child's stop cause; with none it is the exit status, for a
/// sandboxed child the one slamsweep-sandbox-init reported. Call only once the child has ended.
ProcessOutcome ReapChild(RunningChild& child);

}  // namespace slamsweep::orchestrator::inline process
