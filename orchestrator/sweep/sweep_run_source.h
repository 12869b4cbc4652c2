#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>

#include "orchestrator/run/run_spec.h"
#include "orchestrator/store/results_store.h"
#include "orchestrator/supervisor/run_source.h"
#include "orchestrator/sweep/shared_run_files.h"
#include "orchestrator/sweep/status.h"
#include "orchestrator/sweep/sweep_runner.h"

namespace slamsweep::orchestrator::inline sweep {

/// One sweep's runs for the Supervisor (`slamsweep run`): a queue started in the order added while
/// the failure budget allows, each ending recorded in the output directory and the store the moment
/// it arrives, counted into `outcome` and shown on `status`.
class SweepRunSource final : public RunSource {
 public:
  SweepRunSource(const SweepSettings& settings, Status& status, ResultsStore& store, std::int64_t sweep_id,
                 SweepOutcome& outcome);

  /// Queues `run` (it must outlive the source).
  void Add(const RunSpec* run);
  /// After the supervisor returned: counts the runs never started and says why when the failure
  /// budget stopped them.
  void CountNotStarted();

  std::optional<RunStart> Next() override;
  void Started(const RunStart& start) override;
  void Ended(const WorkerEnding& ending) override;
  void Draining() override;

 private:
  bool BudgetExhausted() const { return settings_.failure_budget > 0 && failures_ >= settings_.failure_budget; }

  const SweepSettings& settings_;
  Status& status_;
  ResultsStore& store_;
  std::int64_t sweep_id_;
  SweepOutcome& outcome_;
  std::deque<const RunSpec*> queue_;
  std::map<std::string, const RunSpec*> by_id_;
  std::size_t failures_ = 0;
  SharedRunFiles shared_files_;
};

}  // namespace slamsweep::orchestrator::inline sweep
