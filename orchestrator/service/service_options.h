#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "orchestrator/service/scheduler.h"
#include "orchestrator/service/sweep_planner.h"

namespace slamsweep::orchestrator::service {

/// Limits that keep one client from taking the server: over one, the request gets 413 or 429 with a
/// message and the server goes on serving everyone else.
struct ServiceLimits {
  /// Largest accepted request body (a sweep file): 413 beyond.
  std::size_t max_body_bytes = 256 * 1024;
  /// Most runs one sweep may expand to: 413 beyond.
  std::uint64_t max_runs_per_sweep = 5000;
  /// Most sweeps queued or running at once: 429 beyond (the client retries later).
  std::size_t max_unfinished_sweeps = 100;
};

/// Everything `slamsweep serve` was told.
struct ServiceOptions {
  /// DATA: queue.sqlite, sweeps/<id>/ (one result directory per sweep), server.log.
  std::filesystem::path data_dir;
  std::string host = "127.0.0.1";
  int port = 8420;
  std::string executor = "local";
  std::string slurm_partition;
  SchedulerOptions scheduler;
  ServiceLimits limits;
  /// --token-file: required for a non-loopback --listen.
  std::optional<std::filesystem::path> token_file;
  /// Folders submitted sweeps may read datasets from (InputPolicy::allowed_roots); never empty here.
  std::vector<std::filesystem::path> allowed_roots;
  bool allow_commands = false;
  /// --allow-network: sweeps may give their programs the host's network (`network: true`).
  bool allow_network = false;
  /// --allow-unisolated: where no sandbox can be made, programs run without one (marked unisolated).
  bool allow_unisolated = false;
  /// Folders no program's sandbox may show besides the data folder (the shared data folder).
  std::vector<std::filesystem::path> private_dirs;
  /// The slamsweep binary started as `PROGRAM worker RUN_DIR`.
  std::filesystem::path worker_program;
  /// Called once the server listens (the bound port), e.g. to print it; may be empty.
  std::function<void(int port)> on_listening;
};

}  // namespace slamsweep::orchestrator::service
