#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "orchestrator/run/run_status.h"

namespace slamsweep::orchestrator::service {

/// A Prometheus histogram: cumulative bucket counts, sum and count.
class Histogram {
 public:
  explicit Histogram(std::vector<double> upper_bounds);
  void Observe(double value);
  /// The `_bucket{le=...}`, `_sum` and `_count` lines of metric `name`.
  std::string Render(const std::string& name) const;

 private:
  std::vector<double> upper_bounds_;
  std::vector<std::uint64_t> counts_;  // per bucket, not cumulative
  double sum_ = 0.0;
  std::uint64_t count_ = 0;
};

/// The queue as it stands, for gauges.
struct QueueGauges {
  std::size_t runs_queued = 0;
  std::size_t runs_running = 0;
  std::map<QueuedSweepState, std::size_t> sweeps_by_state;
  std::size_t slots = 0;
  bool draining = false;
};

/// What /metrics reports (Prometheus text exposition format 0.0.4). Thread-safe. There is no
/// Prometheus client library for C++ in Debian 12; the format is a few lines of text.
class ServiceMetrics {
 public:
  ServiceMetrics();
  /// A run recorded with `status` ok, failed or reused; its program's wall time when it ran.
  void RunFinished(QueuedRunState status, double wall_s, bool has_wall);
  /// Scheduler time spent on one run: from its slot freeing (or its sweep arriving) to its worker's
  /// start, plus recording its end (store row, queue row).
  void SchedulingOverhead(double seconds);
  void HttpRequest(int status, double seconds);

  std::string Render(const QueueGauges& gauges) const;

 private:
  mutable std::mutex mutex_;
  std::map<QueuedRunState, std::uint64_t> runs_finished_;
  std::map<int, std::uint64_t> http_requests_;
  Histogram run_seconds_;
  Histogram scheduling_seconds_;
  Histogram http_seconds_;
};

}  // namespace slamsweep::orchestrator::service
