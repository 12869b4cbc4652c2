#include "orchestrator/service/service_metrics.h"

#include <algorithm>
#include <limits>

#include <fmt/format.h>

namespace slamsweep::orchestrator::service {
namespace {

/// Shortest text that reads back to the same double; Prometheus' spellings for infinities.
std::string Number(double value) {
  if (value == std::numeric_limits<double>::infinity()) return "+Inf";
  return fmt::format("{}", value);
}

void Header(std::string& out, const std::string& name, const std::string& type, const std::string& help) {
  out += fmt::format("# HELP {} {}\n# TYPE {} {}\n", name, help, name, type);
}

}  // namespace

Histogram::Histogram(std::vector<double> upper_bounds)
    : upper_bounds_(std::move(upper_bounds)), counts_(upper_bounds_.size() + 1, 0) {}

void Histogram::Observe(double value) {
  const auto bucket = std::lower_bound(upper_bounds_.begin(), upper_bounds_.end(), value) - upper_bounds_.begin();
  ++counts_[static_cast<std::size_t>(bucket)];
  sum_ += value;
  ++count_;
}

std::string Histogram::Render(const std::string& name) const {
  std::string out;
  std::uint64_t cumulative = 0;
  for (std::size_t i = 0; i < upper_bounds_.size(); ++i) {
    cumulative += counts_[i];
    out += fmt::format("{}_bucket{{le=\"{}\"}} {}\n", name, Number(upper_bounds_[i]), cumulative);
  }
  out += fmt::format("{}_bucket{{le=\"+Inf\"}} {}\n{}_sum {}\n{}_count {}\n", name, count_, name, Number(sum_), name,
                     count_);
  return out;
}

ServiceMetrics::ServiceMetrics()
    : run_seconds_({1, 5, 15, 60, 300, 900, 3600, 14400}),
      scheduling_seconds_({0.001, 0.002, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 1}),
      http_seconds_({0.0005, 0.001, 0.0025, 0.005, 0.01, 0.025, 0.05, 0.1, 0.5, 1}) {}

void ServiceMetrics::RunFinished(QueuedRunState status, double wall_s, bool has_wall) {
  const std::lock_guard lock(mutex_);
  ++runs_finished_[status];
  if (has_wall) run_seconds_.Observe(wall_s);
}

void ServiceMetrics::SchedulingOverhead(double seconds) {
  const std::lock_guard lock(mutex_);
  scheduling_seconds_.Observe(seconds);
}

void ServiceMetrics::HttpRequest(int status, double seconds) {
  const std::lock_guard lock(mutex_);
  ++http_requests_[status];
  http_seconds_.Observe(seconds);
}

std::string ServiceMetrics::Render(const QueueGauges& gauges) const {
  const std::lock_guard lock(mutex_);
  std::string out;
  Header(out, "slamsweep_queue_depth", "gauge", "Runs queued and not started yet, over all sweeps.");
  out += fmt::format("slamsweep_queue_depth {}\n", gauges.runs_queued);
  Header(out, "slamsweep_runs_running", "gauge", "Runs whose worker is running.");
  out += fmt::format("slamsweep_runs_running {}\n", gauges.runs_running);
  Header(out, "slamsweep_worker_slots", "gauge", "Runs the pool starts at once.");
  out += fmt::format("slamsweep_worker_slots {}\n", gauges.slots);
  Header(out, "slamsweep_draining", "gauge", "1 while the server drains after SIGTERM: no new runs start.");
  out += fmt::format("slamsweep_draining {}\n", gauges.draining ? 1 : 0);
  Header(out, "slamsweep_sweeps", "gauge", "Sweeps known to the server, by state.");
  for (const QueuedSweepState state : kSweepStates) {
    const auto found = gauges.sweeps_by_state.find(state);
    out += fmt::format("slamsweep_sweeps{{state=\"{}\"}} {}\n", ToString(state),
                       found == gauges.sweeps_by_state.end() ? 0 : found->second);
  }
  Header(out, "slamsweep_runs_finished_total", "counter",
         "Runs finished since the server started, by status (reused: linked from an identical ok run).");
  for (const QueuedRunState status : {QueuedRunState::kOk, QueuedRunState::kFailed, QueuedRunState::kReused}) {
    const auto found = runs_finished_.find(status);
    out += fmt::format("slamsweep_runs_finished_total{{status=\"{}\"}} {}\n", ToString(status),
                       found == runs_finished_.end() ? 0 : found->second);
  }
  Header(out, "slamsweep_run_duration_seconds", "histogram", "Wall time of the SLAM program of each run that ran.");
  out += run_seconds_.Render("slamsweep_run_duration_seconds");
  Header(out, "slamsweep_scheduling_seconds", "histogram",
         "Scheduler time per run: choosing it, preparing its folder and starting its worker, then recording its end.");
  out += scheduling_seconds_.Render("slamsweep_scheduling_seconds");
  Header(out, "slamsweep_http_requests_total", "counter", "HTTP requests answered, by status code.");
  for (const auto& [status, count] : http_requests_) {
    out += fmt::format("slamsweep_http_requests_total{{code=\"{}\"}} {}\n", status, count);
  }
  Header(out, "slamsweep_http_request_seconds", "histogram", "Time to answer an HTTP request.");
  out += http_seconds_.Render("slamsweep_http_request_seconds");
  return out;
}

}  // namespace slamsweep::orchestrator::service
