// `slamsweep serve --data DIR`: the long-running service (orchestrator/service) with this program's
// sweep loading and report writing, so that a submitted sweep is read and reported exactly as
// `slamsweep plan/run` read and report a sweep file.
#include <fstream>
#include <memory>
#include <sstream>

#include <fmt/format.h>

#include "cli/command.h"
#include "cli/data_sources.h"
#include "cli/sweep_loading.h"
#include "evaluator/core/input_error.h"
#include "orchestrator/files/atomic_file.h"
#include "orchestrator/service/server.h"
#include "orchestrator/sweep/local_executor.h"
#include "orchestrator/worker/program_sandbox.h"

namespace slamsweep::cli {
namespace {

struct ServeOptions {
  std::string data;
  std::string listen = "127.0.0.1:8420";
  std::size_t jobs = 0;
  std::string executor = "local";
  std::string slurm_partition;
  std::string token_file;
  std::vector<std::string> allow_roots;
  bool allow_commands = false;
  bool allow_network = false;
  bool allow_unisolated = false;
  double drain_timeout_s = 600.0;
  std::size_t max_body_kb = 256;
  std::uint64_t max_runs = 5000;
  std::size_t max_queued = 100;
  std::string port_file;
};

/// HOST:PORT (IPv6 in brackets); throws InputError naming the option.
std::pair<std::string, int> ParseListen(const std::string& text) {
  const auto colon = text.rfind(':');
  std::string host = colon == std::string::npos ? "" : text.substr(0, colon);
  const std::string port_text = colon == std::string::npos ? "" : text.substr(colon + 1);
  if (host.size() >= 2 && host.front() == '[' && host.back() == ']') host = host.substr(1, host.size() - 2);
  const bool digits =
      !port_text.empty() && port_text.size() <= 5 && port_text.find_first_not_of("0123456789") == std::string::npos;
  if (host.empty() || !digits || std::stoi(port_text) > 65535) {
    throw evaluator::InputError("--listen: expected HOST:PORT such as 127.0.0.1:8420, got '" + text + "'");
  }
  return {host, std::stoi(port_text)};
}

/// What submitted sweeps may read when --allow-root is not given: the shared data folder and the
/// folders of the dataset catalog's entries (the operator's own data).
std::vector<std::filesystem::path> DefaultAllowedRoots() {
  const CatalogLocation location = FindCatalog("");
  std::vector<std::filesystem::path> roots = {location.shared_root};
  try {
    const evaluator::Catalog catalog = evaluator::ReadCatalog(location.catalog);
    for (const evaluator::CatalogEntry& entry : catalog.entries) {
      if (entry.path.empty()) continue;
      std::filesystem::path path =
          evaluator::ResolveCatalogPath(entry.path, {{"SHARED", location.shared_root.string()}});
      if (path.is_relative()) path = location.catalog.parent_path() / path;
      roots.push_back(path.lexically_normal().parent_path());
    }
  } catch (const evaluator::InputError&) {
    // Without a readable catalog only the shared folder is allowed.
  }
  return roots;
}

int Serve(const ServeOptions& options) {
  orchestrator::service::ServiceOptions service;
  service.data_dir = std::filesystem::absolute(options.data).lexically_normal();
  std::tie(service.host, service.port) = ParseListen(options.listen);
  service.executor = options.executor;
  service.slurm_partition = options.slurm_partition;
  service.scheduler.jobs = DefaultJobs(options.jobs);
  service.scheduler.drain_grace_s = options.drain_timeout_s;
  service.limits.max_body_bytes = options.max_body_kb * 1024;
  service.limits.max_runs_per_sweep = options.max_runs;
  service.limits.max_unfinished_sweeps = options.max_queued;
  if (!options.token_file.empty()) service.token_file = options.token_file;
  for (const std::string& root : options.allow_roots) {
    if (!std::filesystem::is_directory(root)) throw evaluator::InputError("--allow-root " + root + ": not a folder");
    service.allowed_roots.push_back(std::filesystem::absolute(root).lexically_normal());
  }
  if (service.allowed_roots.empty()) service.allowed_roots = DefaultAllowedRoots();
  service.allow_commands = options.allow_commands;
  service.allow_network = options.allow_network;
  service.allow_unisolated = options.allow_unisolated;
  service.private_dirs = {FindCatalog("").shared_root};
  // Whether sandboxes can have a /proc of their own here: probed once, not by every worker.
  if (service.executor == "local") orchestrator::DecideSandboxProcForWorkers();
  service.worker_program = orchestrator::WorkerProgram();
  if (!options.port_file.empty()) {
    service.on_listening = [file = options.port_file](int port) {
      orchestrator::WriteFileAtomically(file, std::to_string(port) + "\n");
    };
  }
  const orchestrator::service::SweepPlanner planner = [](std::string_view text, const std::filesystem::path& file,
                                                         const orchestrator::service::PlanLimits& limits) {
    SweepLimits sweep_limits;
    sweep_limits.policy = limits.policy;
    sweep_limits.max_runs = limits.max_runs;
    LoadedSweep loaded = LoadSweepText(text, file.string(), {}, sweep_limits);
    return orchestrator::service::PlannedSweep{loaded.config.name, std::move(loaded.runs), loaded.config_hash,
                                               loaded.config.validity_study};
  };
  const orchestrator::service::ReportWriter reports = [](const std::filesystem::path& result_dir) {
    std::ostringstream out, err;
    WriteSweepReport(result_dir, Streams{out, err});
  };
  return orchestrator::service::RunService(service, planner, reports);
}

}  // namespace

void RegisterServeCommand(CLI::App& app, const Streams& streams, int& exit_code) {
  auto options = std::make_shared<ServeOptions>();
  CLI::App* command = app.add_subcommand(
      "serve", "run submitted sweeps from one queue on a shared worker pool, with an HTTP API and a status page");
  command->add_option("--data", options->data, "folder of the queue (queue.sqlite) and of every sweep's results")
      ->required();
  command->add_option("--listen", options->listen,
                      "HOST:PORT to listen on (default 127.0.0.1:8420; port 0: any free port)");
  command->add_option("-j,--jobs", options->jobs, "runs at once, shared by every sweep (default: the number of cores)")
      ->check(CLI::PositiveNumber);
  command->add_option("--executor", options->executor, "where runs execute: local worker processes or Slurm job arrays")
      ->check(CLI::IsMember({"local", "slurm"}));
  command->add_option("--slurm-partition", options->slurm_partition,
                      "Slurm partition (default: the cluster's default)");
  command->add_option("--token-file", options->token_file,
                      "file (mode 0600) with the bearer token that submissions and cancellations must send");
  command->add_option("--allow-root", options->allow_roots,
                      "folder submitted sweeps may read datasets from (repeatable; default: the shared data folder "
                      "and the catalog's dataset folders)");
  command->add_flag("--allow-commands", options->allow_commands,
                    "accept sweeps with `adapter: command` (they run any program the sweep names)");
  command->add_flag("--allow-network", options->allow_network,
                    "accept sweeps whose algorithms ask for `network: true` (their programs reach the host's network)");
  command->add_flag("--allow-unisolated", options->allow_unisolated,
                    "where no sandbox can be made, run programs without one (their results marked unisolated) "
                    "instead of failing the runs");
  command
      ->add_option("--drain-timeout", options->drain_timeout_s,
                   "seconds running runs may finish after SIGTERM before they are stopped and queued again")
      ->check(CLI::NonNegativeNumber);
  command->add_option("--max-body-kb", options->max_body_kb, "largest sweep file accepted, in KiB (413 beyond)")
      ->check(CLI::PositiveNumber);
  command->add_option("--max-runs", options->max_runs, "most runs one sweep may have (413 beyond)")
      ->check(CLI::PositiveNumber);
  command->add_option("--max-queued", options->max_queued, "most sweeps queued or running at once (429 beyond)")
      ->check(CLI::PositiveNumber);
  command->add_option("--port-file", options->port_file, "write the port listened on into this file once listening");
  command->callback([options, &streams, &exit_code] {
    static_cast<void>(streams);
    exit_code = Serve(*options);
  });
}

}  // namespace slamsweep::cli
