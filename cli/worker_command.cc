// `slamsweep worker RUN_DIR`: the hidden subcommand the orchestrator starts for every run.
#include <memory>
#include <string>

#include "cli/command.h"
#include "cli/program.h"
#include "orchestrator/worker/worker.h"
#include "orchestrator/worker/worker_service.h"

namespace slamsweep::cli {

void RegisterWorkerCommand(CLI::App& app, const Streams& /*streams*/, int& exit_code) {
  auto run_dir = std::make_shared<std::string>();
  auto serve = std::make_shared<bool>(false);
  CLI::App* command = app.add_subcommand("worker", "run one prepared run folder (started by `slamsweep run`)");
  // Hidden: users start sweeps; workers are started by the orchestrator (and Slurm array tasks).
  command->group("");
  command->add_option("RUN_DIR", *run_dir, "run folder holding run.json");
  command->add_flag("--serve", *serve,
                    "take run folders one after another from descriptor 3 (a socket), answering each there "
                    "(the worker pool of `slamsweep run`)");
  // The worker's exit code is its whole interface to the supervisor (0 result written, 2 bad
  // run.json, 130 interrupted); RunWorker prints its own message on stderr.
  command->callback([run_dir, serve, &exit_code] {
    ReuseFreedMemory();  // one run at a time: its peak memory is the next one's
    if (*serve) {
      exit_code = orchestrator::ServeWorkerRuns(orchestrator::kWorkerPoolChannelFd);
    } else if (run_dir->empty()) {
      throw CLI::RequiredError("RUN_DIR");
    } else {
      exit_code = orchestrator::RunWorker(*run_dir);
    }
  });
}

}  // namespace slamsweep::cli
