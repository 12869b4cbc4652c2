#pragma once

#include <cstdint>

#include <filesystem>

namespace slamsweep::orchestrator::inline worker {

/// Exit codes of `slamsweep worker RUN_DIR` (orchestrator/DESIGN.md).
inline constexpr int kWorkerWroteResult = 0;
inline constexpr int kWorkerBadRunJson = 2;
inline constexpr int kWorkerInterrupted = 130;
/// The cap of a worker's own output, RUN_DIR/worker.log (head and tail kept, as for a program's log.txt).
inline constexpr std::uint64_t kWorkerLogCapBytes = 1 << 20;

/// One run, start to finish, inside `slamsweep worker RUN_DIR`: reads RUN_DIR/run.json, removes
/// what an earlier interrupted attempt left (everything but run.json), prepares the inputs, writes
/// command.txt, runs the program (own process group, timeout, memory limit, log.txt capped at
/// 8 MB), collects and converts its outputs, computes every metric the inputs allow and writes
/// result.json atomically. Every failure of the run is recorded in result.json (return 0).
/// Returns 2 with a message on stderr naming the file and field when run.json cannot be read, and
/// 130 after SIGINT/SIGTERM (the program's group is terminated, partial outputs are deleted and no
/// result.json is written). Sets PR_SET_PDEATHSIG(SIGTERM): a worker whose supervisor died stops.
int RunWorker(const std::filesystem::path& run_dir);

}  // namespace slamsweep::orchestrator::inline worker
