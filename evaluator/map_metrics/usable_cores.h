#pragma once

#include <sched.h>

#include <thread>

namespace slamsweep::evaluator::inline map_metrics {

/// The cores this process may run on: its CPU affinity (taskset, a cgroup's cpuset), else the
/// machine's count. A second thread only pays where this is 2 or more.
inline int UsableCores() {
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (sched_getaffinity(0, sizeof allowed, &allowed) == 0) return CPU_COUNT(&allowed);
  return static_cast<int>(std::thread::hardware_concurrency());
}

}  // namespace slamsweep::evaluator::inline map_metrics
