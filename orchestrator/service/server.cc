#include "orchestrator/service/server.h"

#include <signal.h>

#include <atomic>
#include <cstdlib>
#include <thread>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/process/interruption.h"
#include "orchestrator/service/auth.h"
#include "orchestrator/service/http_api.h"
#include "orchestrator/service/leftover_workers.h"
#include "orchestrator/service/queue_store.h"
#include "orchestrator/service/scheduler.h"
#include "orchestrator/slurm/slurm_executor.h"
#include "orchestrator/sweep/local_executor.h"
#include "orchestrator/sweep/output_lock.h"
#include "orchestrator/worker/program_sandbox.h"

// Last: see http_api.h.
#include <httplib.h>

namespace slamsweep::orchestrator::service {
namespace {

/// Grace for the processes a killed server left: as long as a worker's own grace for its program.
constexpr double kLeftoverGraceS = 15.0;

std::unique_ptr<Executor> MakeExecutor(const ServiceOptions& options) {
  if (options.executor == "slurm") {
    SlurmOptions slurm;
    slurm.worker_program = options.worker_program;
    slurm.partition = options.slurm_partition;
    slurm.state_dir = options.data_dir / "slurm";
    slurm.poll_interval_s = 2.0;
    return MakeSlurmExecutor(slurm);
  }
  return std::make_unique<LocalExecutor>(options.worker_program);
}

/// Writes the reports of finished sweeps one at a time, beside the scheduler so that a slow report
/// never delays a run's start.
class ReportThread {
 public:
  ReportThread(Scheduler& scheduler, const ReportWriter& writer)
      : scheduler_(scheduler), writer_(writer), thread_([this] { Loop(); }) {}
  ~ReportThread() {
    stop_ = true;
    thread_.join();
  }

 private:
  void Loop() {
    while (!stop_) {
      const std::optional<QueuedSweep> job = scheduler_.TakeReportJob();
      if (!job) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        continue;
      }
      bool ok = false;
      try {
        if (writer_) writer_(job->result_dir);
        ok = static_cast<bool>(writer_);
      } catch (const std::exception& error) {
        spdlog::error("sweep {}: report not written: {}", job->id, error.what());
      }
      scheduler_.ReportWritten(job->id, ok);
    }
  }

  Scheduler& scheduler_;
  const ReportWriter& writer_;
  std::atomic<bool> stop_ = false;
  std::thread thread_;
};

}  // namespace

int RunService(const ServiceOptions& options, const SweepPlanner& planner, const ReportWriter& report_writer) {
  std::optional<std::string> token;
  if (options.token_file) token = ReadTokenFile(*options.token_file);
  if (!token && !IsLoopbackAddress(options.host)) {
    throw evaluator::InputError(fmt::format(
        "--listen {}: refusing to serve a non-loopback address without --token-file (anyone reaching it could run "
        "sweeps); give a token file (mode 0600) or listen on 127.0.0.1",
        options.host));
  }
  std::filesystem::create_directories(options.data_dir / "sweeps");
  OutputLock data_lock(options.data_dir);  // one server per data folder
  QueueStore queue = QueueStore::Open(options.data_dir / "queue.sqlite");
  std::mutex queue_mutex;
  const std::size_t leftovers = EndLeftoverProcesses(options.data_dir / "sweeps", kLeftoverGraceS);
  if (leftovers > 0) spdlog::info("ended {} processes left by the previous server", leftovers);
  if (options.executor == "slurm") {
    for (const std::string& job : EndLeftoverSlurmJobs(options.data_dir / "slurm", 90.0)) {
      spdlog::info("cancelled Slurm job {} left by the previous server", job);
    }
  }

  ServiceMetrics metrics;
  Scheduler scheduler(queue, queue_mutex, options.data_dir, options.scheduler, metrics);
  scheduler.Recover();

  // From here SIGTERM/SIGINT/SIGHUP only set a flag, and every thread started below inherits the
  // blocked mask: the signals are taken inside the scheduler's waits alone.
  InterruptionGuard interruption;
  ::signal(SIGPIPE, SIG_IGN);  // a client that hangs up must not end the server
  // Every sweep's results are in the data folder: no sandbox of a program that workers start may
  // show it (orchestrator/worker/program_sandbox). Set before any thread starts; workers inherit it.
  std::vector<std::filesystem::path> private_dirs = {options.data_dir};
  private_dirs.insert(private_dirs.end(), options.private_dirs.begin(), options.private_dirs.end());
  AddPrivateDirs(private_dirs);
  std::unique_ptr<Executor> executor = MakeExecutor(options);

  httplib::Server http;
  ApiContext context{scheduler, metrics, planner, options, BearerAuth(token)};
  RegisterRoutes(http, context);
  int port = options.port;
  if (port == 0) {
    port = http.bind_to_any_port(options.host);
    if (port <= 0) throw evaluator::InputError(fmt::format("--listen {}:0: cannot listen", options.host));
  } else if (!http.bind_to_port(options.host, port)) {
    throw evaluator::InputError(
        fmt::format("--listen {}:{}: cannot listen (in use, or not an address of this machine)", options.host, port));
  }
  std::thread http_thread([&http] { http.listen_after_bind(); });
  spdlog::info("slamsweep service on http://{}:{} ({} worker slots, {} executor, data in {}){}", options.host, port,
               options.scheduler.jobs, options.executor, options.data_dir.string(),
               token ? ", bearer token required for writes" : "");
  if (options.on_listening) options.on_listening(port);
  {
    ReportThread reports(scheduler, report_writer);
    scheduler.Run(*executor);
  }
  http.stop();
  http_thread.join();
  spdlog::info("drained; exiting");
  return 0;
}

}  // namespace slamsweep::orchestrator::service
