#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "orchestrator/supervisor/executor.h"
#include "orchestrator/run/run_folder.h"

namespace slamsweep::orchestrator::fakes {

/// An executor without processes: each started run ends at the next Wait with the result that
/// `outcome` decides, written to its folder as a worker would. Lets the sweep loop be tested for
/// skipping, budgets and interruption without SLAM programs.
class FakeExecutor final : public Executor {
 public:
  /// Return "ok", "failed", "no-result" (the worker died without one) or "interrupt" (an
  /// interruption arrives while this run is running).
  using Outcome = std::function<std::string(const RunSpec&)>;
  explicit FakeExecutor(Outcome outcome) : outcome_(std::move(outcome)) {}

  void Start(const RunSpec& run, const std::filesystem::path& run_dir) override {
    started.push_back(run.run_id);
    running_.push_back({run, run_dir});
    max_running = std::max(max_running, running_.size());
  }
  std::vector<WorkerEnding> Wait() override {
    std::vector<WorkerEnding> ended = std::move(stopped_endings_);
    stopped_endings_.clear();
    std::vector<Pending> still;
    for (Pending& pending : running_) {
      const std::string what = outcome_(pending.run);
      if (what == "interrupt") {
        interrupted_ = true;
        still.push_back(pending);
        continue;
      }
      if (what == "ok" || what == "failed") {
        nlohmann::json result = {
            {"run_id", pending.run.run_id},
            {"status", what},
            {"wall_s", 1.5},
            {"metrics", nlohmann::json::array(
                            {{{"metric", "corners"}, {"statistic", "value"}, {"value", 12.0}, {"unit", "count"}}})}};
        if (what == "failed") {
          result["failure_kind"] = "exit_code";
          result["reason"] = "exit code 3";
        }
        WriteJsonAtomically(pending.run_dir / "result.json", result);
      }
      ended.push_back({pending.run.run_id, false, "worker: killed by SIGKILL (signal 9)"});
    }
    running_ = still;
    return ended;
  }
  std::vector<WorkerEnding> TerminateAll() override {
    std::vector<WorkerEnding> ended = std::move(stopped_endings_);
    stopped_endings_.clear();
    for (const Pending& pending : running_) ended.push_back({pending.run.run_id, true, "worker: interrupted"});
    running_.clear();
    return ended;
  }
  void Stop(const std::string& run_id) override {
    for (auto it = running_.begin(); it != running_.end(); ++it) {
      if (it->run.run_id != run_id) continue;
      stopped.push_back(run_id);
      running_.erase(it);
      stopped_endings_.push_back({run_id, true, "worker: stopped by the supervisor"});
      return;
    }
  }
  std::size_t Running() const override { return running_.size() + stopped_endings_.size(); }
  bool Interrupted() const override { return interrupted_; }

  std::vector<std::string> started;
  std::vector<std::string> stopped;
  std::size_t max_running = 0;

 private:
  struct Pending {
    RunSpec run;
    std::filesystem::path run_dir;
  };
  Outcome outcome_;
  std::vector<Pending> running_;
  std::vector<WorkerEnding> stopped_endings_;
  bool interrupted_ = false;
};

}  // namespace slamsweep::orchestrator::fakes
