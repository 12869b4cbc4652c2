#pragma once

#include <chrono>
#include <string_view>

namespace slamsweep::orchestrator::inline phase_times {

/// True when $SLAMSWEEP_PHASE_TIMES names a file: timers then add up, otherwise they cost a branch.
bool PhaseTimesEnabled();

/// Adds wall and CPU seconds (the whole process's CPU clock) to this process's totals for `phase` (thread-safe).
void AddPhaseTime(std::string_view phase, double wall_s, double cpu_s);

/// Appends {"process": kind, "phases": {phase: wall seconds, ...}, "cpu": {phase: CPU seconds, ...}} as one
/// line to $SLAMSWEEP_PHASE_TIMES and clears the totals; nothing when disabled or nothing was timed. Errors
/// are ignored: timing never fails a run. CPU time tells a phase's cost apart from other load on the machine.
void FlushPhaseTimes(std::string_view process_kind);

/// Times its own lifetime as `phase` (a string literal).
class PhaseTimer {
 public:
  explicit PhaseTimer(std::string_view phase);
  ~PhaseTimer();
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  std::string_view phase_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
  double start_cpu_s_ = 0.0;
};

}  // namespace slamsweep::orchestrator::inline phase_times
