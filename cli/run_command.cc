// `slamsweep run CONFIG`: expand the sweep, run it with worker processes, record, report.
#include <unistd.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli/command.h"
#include "cli/data_sources.h"
#include "cli/sweep_loading.h"
#include "orchestrator/adapters/sparse_sequences.h"
#include "orchestrator/input_cache/prepared_sequence_cache.h"
#include "orchestrator/matrix/plan_listing.h"
#include "orchestrator/matrix/shard.h"
#include "orchestrator/phase_times/phase_times.h"
#include "orchestrator/process/interruption.h"
#include "orchestrator/slurm/slurm_executor.h"
#include "orchestrator/sweep/local_executor.h"
#include "orchestrator/sweep/sweep_runner.h"
#include "orchestrator/sweep/worker_pool.h"
#include "orchestrator/worker/program_sandbox.h"
#include "orchestrator/run/run_status.h"

namespace slamsweep::cli {
namespace {

struct RunOptions {
  std::string config;
  std::size_t jobs = 0;
  MatrixSelection selection;
  std::string rerun;
  std::string output;
  bool keep_going = false;
  bool reuse_stale = false;
  bool allow_unisolated = false;
  std::string executor = "local";
  std::string slurm_partition;
  bool no_report = false;
};

/// The invocation as recorded with the sweep, to reproduce it.
std::string ReproducingCommandLine(const RunOptions& options) {
  std::string line = "slamsweep run " + options.config;
  if (options.jobs > 0) line += fmt::format(" --jobs {}", options.jobs);
  if (!options.selection.shard.empty()) line += " --shard " + options.selection.shard;
  if (!options.selection.algorithms.empty()) {
    line += " --only-algorithms " + fmt::format("{}", fmt::join(options.selection.algorithms, ","));
  }
  if (!options.selection.sequences.empty()) {
    line += " --only-sequences " + fmt::format("{}", fmt::join(options.selection.sequences, ","));
  }
  if (options.selection.iterations > 0) line += fmt::format(" --iterations {}", options.selection.iterations);
  if (!options.rerun.empty()) line += " --rerun " + options.rerun;
  if (!options.output.empty()) line += " --output " + options.output;
  if (options.keep_going) line += " --keep-going";
  if (options.reuse_stale) line += " --reuse-stale";
  if (options.allow_unisolated) line += " --allow-unisolated";
  if (options.executor != "local") line += " --executor " + options.executor;
  if (!options.slurm_partition.empty()) line += " --slurm-partition " + options.slurm_partition;
  return line;
}

int Run(const RunOptions& options, const Streams& streams, const std::string& command_line) {
  std::optional<orchestrator::PhaseTimer> plan_phase(std::in_place, "plan");
  LoadedSweep sweep = LoadSweep(options.config, options.selection, /*install_missing_roster=*/true);
  plan_phase.reset();
  for (orchestrator::RunSpec& run : sweep.runs) run.allow_unisolated = options.allow_unisolated;
  // Every reference is in the shared data folder: no program's sandbox may show it.
  orchestrator::AddPrivateDirs({FindCatalog("").shared_root});
  // Whether sandboxes can have a /proc of their own here: probed once, not by every worker.
  if (options.executor == "local") orchestrator::DecideSandboxProcForWorkers();
  orchestrator::SweepSettings settings;
  settings.name = sweep.config.name;
  settings.output_dir = options.output.empty() ? sweep.config.output_dir : std::filesystem::path(options.output);
  settings.jobs = options.jobs > 0 ? options.jobs : DefaultJobs(sweep.config.workers);
  settings.failure_budget = options.keep_going ? 0 : sweep.config.failure_budget;
  settings.rerun_failed = options.rerun == orchestrator::RunStatusName(orchestrator::RunStatus::kFailed);
  settings.reuse_stale = options.reuse_stale;
  settings.config_path = std::filesystem::absolute(options.config).string();
  settings.config_sha = sweep.config_hash;
  settings.command_line = command_line;
  settings.validity_study = sweep.config.validity_study;

  // Signals are caught from here on: Ctrl-C ends the sweep cleanly (exit 130), never half-way.
  orchestrator::InterruptionGuard interruption;
  std::unique_ptr<orchestrator::Executor> executor;
  const std::size_t display_slots = settings.jobs;
  if (options.executor == "slurm") {
    orchestrator::SlurmOptions slurm;
    slurm.worker_program = orchestrator::WorkerProgram();
    slurm.partition = options.slurm_partition;
    executor = orchestrator::MakeSlurmExecutor(slurm);
    // One job array holds every run; Slurm decides how many run at once.
    settings.jobs = std::max<std::size_t>(1, sweep.runs.size());
  } else {
    // One long-lived worker per slot takes the runs one after another (each program still in its own sandbox).
    executor = std::make_unique<orchestrator::WorkerPool>(orchestrator::WorkerProgram());
  }
  const bool smart = &streams.out == &std::cout && orchestrator::IsSmartTerminal(STDOUT_FILENO);
  auto status = orchestrator::MakeStatus(streams.out, smart, display_slots);
  streams.out << fmt::format("sweep {}: {} runs ({} jobs) -> {}\n", settings.name, sweep.runs.size(), settings.jobs,
                             settings.output_dir.string());
  streams.err << orchestrator::OdometryIsReferenceWarnings(sweep.runs);
  // Once per sequence, before any run starts: scans too far apart for scan matching judge the data, not the programs.
  // Read through the sweep's prepared inputs when this program is the workers' (the cache keys an entry by the
  // executable that prepared it): the runs then find each sequence prepared.
  std::error_code not_same;
  const bool worker_is_this_program =
      std::filesystem::equivalent(orchestrator::WorkerProgram(), "/proc/self/exe", not_same) && !not_same;
  streams.err << orchestrator::SparseSequenceWarnings(
      sweep.runs,
      worker_is_this_program ? orchestrator::SweepPreparedInputsDir(settings.output_dir) : std::filesystem::path());
  const orchestrator::SweepOutcome outcome = RunSweep(sweep.runs, settings, *executor, *status);
  streams.out << fmt::format("{} ok, {} failed, {} done earlier, {} not started{}\n", outcome.ok, outcome.failed,
                             outcome.already_done, outcome.not_started, outcome.interrupted ? " (interrupted)" : "");
  if (outcome.stale > 0) {
    streams.out << fmt::format(
        "{} earlier result{} computed by another slamsweep revision, program build or evaluation setting {} {}\n",
        outcome.stale, outcome.stale == 1 ? "" : "s", outcome.stale == 1 ? "was" : "were",
        settings.reuse_stale ? "reused (--reuse-stale)" : "run again");
  }
  streams.out << "results: " << (settings.output_dir / "summary.json").string() << "\n";
  if (!options.no_report && !outcome.interrupted) WriteSweepReport(settings.output_dir, streams);
  return outcome.ExitCode();
}

}  // namespace

void RegisterRunCommand(CLI::App& app, const Streams& streams, int& exit_code) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* command = app.add_subcommand("run", "run a sweep: every run in a worker process, results in OUTPUT");
  command->add_option("CONFIG", options->config, "sweep YAML")->required();
  command->add_option("-j,--jobs", options->jobs, "runs at once (default: the config's workers, else cores)")
      ->check(CLI::PositiveNumber);
  AddMatrixSelectionOptions(*command, options->selection);
  command->add_option("--rerun", options->rerun, "run again the runs an earlier sweep recorded as failed")
      ->check(CLI::IsMember({std::string(orchestrator::RunStatusName(orchestrator::RunStatus::kFailed))}));
  command->add_option("-o,--output", options->output, "output directory (default: the config's output)");
  command->add_flag("-k,--keep-going", options->keep_going, "ignore the config's failure budget");
  command->add_flag("--reuse-stale", options->reuse_stale,
                    "reuse finished runs computed by another slamsweep revision, program build or evaluation setting "
                    "(default: run them again)");
  command->add_flag("--allow-unisolated", options->allow_unisolated,
                    "where no sandbox can be made, run programs without one (their results marked unisolated) "
                    "instead of failing the runs");
  command->add_flag("--no-report", options->no_report, "do not write the HTML report");
  command
      ->add_option("--executor", options->executor, "where runs execute: local worker processes or one Slurm job array")
      ->check(CLI::IsMember({"local", "slurm"}));
  command->add_option("--slurm-partition", options->slurm_partition,
                      "Slurm partition (default: the cluster's default)");
  command->callback(
      [options, &streams, &exit_code] { exit_code = Run(*options, streams, ReproducingCommandLine(*options)); });
}

}  // namespace slamsweep::cli
