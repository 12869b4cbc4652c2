#include "orchestrator/sweep/worker_pool.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "orchestrator/phase_times/phase_times.h"
#include "orchestrator/process/interruption.h"
#include "orchestrator/process/outcome_reason.h"
#include "orchestrator/process/signal_wakeup.h"
#include "orchestrator/process/socket_send.h"
#include "orchestrator/process/wake_up.h"
#include "orchestrator/sweep/worker_environment.h"
#include "orchestrator/worker/worker.h"
#include "orchestrator/worker/worker_service.h"

namespace slamsweep::orchestrator::inline sweep {
namespace {

/// The grace a stopped worker gets to stop its program and remove partial outputs (LocalExecutor's).
constexpr double kGraceS = 10.0;
constexpr auto kMaxSleep = std::chrono::seconds(1);

std::vector<char*> Pointers(std::vector<std::string>& strings) {
  std::vector<char*> pointers;
  for (std::string& text : strings) pointers.push_back(text.data());
  pointers.push_back(nullptr);
  return pointers;
}

}  // namespace

WorkerPool::WorkerPool(std::filesystem::path worker_program, double worker_overhead_s)
    : worker_program_(std::move(worker_program)), worker_overhead_s_(worker_overhead_s) {}

WorkerPool::~WorkerPool() {
  for (Worker& worker : workers_) {
    if (worker.pid <= 0) continue;
    ::close(worker.channel);
    ::kill(-worker.pid, SIGKILL);
    while (::waitpid(worker.pid, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
}

void WorkerPool::Spawn(Worker& worker) {
  int ends[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) {
    throw std::runtime_error(std::string("cannot create a worker's socket: ") + std::strerror(errno));
  }
  // Above the descriptor the child gets it at, so that dup2 onto it really copies (and clears close-on-exec).
  const int child_end = ::fcntl(ends[1], F_DUPFD_CLOEXEC, kWorkerPoolChannelFd + 1);
  ::close(ends[1]);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawn_file_actions_adddup2(&actions, child_end, kWorkerPoolChannelFd);
  posix_spawn_file_actions_addclosefrom_np(&actions, kWorkerPoolChannelFd + 1);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  // Its own process group (stopped as a whole), every signal unblocked and at its default: the supervisor
  // blocks the ones it waits for.
  sigset_t none;
  sigemptyset(&none);
  sigset_t defaults;
  sigemptyset(&defaults);
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP, SIGCHLD, SIGPIPE}) sigaddset(&defaults, signal_number);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  posix_spawnattr_setpgroup(&attributes, 0);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  std::vector<std::string> arguments = {worker_program_.string(), "worker", "--serve"};
  std::vector<std::string> environment = WorkerEnvironmentBlock();
  pid_t pid = -1;
  const int error = ::posix_spawn(&pid, arguments[0].c_str(), &actions, &attributes, Pointers(arguments).data(),
                                  Pointers(environment).data());
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(child_end);
  if (error != 0) {
    ::close(ends[0]);
    throw std::runtime_error(StartFailureReason(arguments[0], std::strerror(error)));
  }
  worker = Worker{};
  worker.pid = pid;
  worker.channel = ends[0];
  ++started_;
}

WorkerPool::Worker& WorkerPool::IdleWorker() {
  for (Worker& worker : workers_) {
    if (worker.pid > 0 && !worker.job && !worker.exiting && worker.stopping == Worker::Stopping::kNo) return worker;
  }
  auto free = std::find_if(workers_.begin(), workers_.end(), [](const Worker& worker) { return worker.pid <= 0; });
  Worker& worker = free != workers_.end() ? *free : workers_.emplace_back();
  Spawn(worker);
  return worker;
}

void WorkerPool::Start(const RunSpec& run, const std::filesystem::path& run_dir) {
  const std::string line = run_dir.string() + "\n";
  Worker* worker = &IdleWorker();
  if (!SendAll(worker->channel, line)) {
    // It died while idle: a new worker takes the run.
    Bury(*worker);
    worker = &IdleWorker();
    if (!SendAll(worker->channel, line)) {
      Bury(*worker);
      throw std::runtime_error("the worker " + worker_program_.string() + " ended before it took a run");
    }
  }
  const double timeout_s = run.algorithm.timeout_s + worker_overhead_s_;
  const Clock::time_point now = Clock::now();
  worker->job =
      Job{run.run_id, now, now + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout_s)),
          timeout_s};
}

void WorkerPool::Finish(Worker& worker, WorkerEnding ending) {
  worker.job.reset();
  if (!worker.exiting) worker.stopping = Worker::Stopping::kNo;
  ended_.push_back(std::move(ending));
}

void WorkerPool::ReadFrom(Worker& worker) {
  char chunk[512];
  for (;;) {
    const ssize_t n = ::recv(worker.channel, chunk, sizeof chunk, MSG_DONTWAIT);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
    if (n <= 0) {
      Bury(worker);
      return;
    }
    worker.received.append(chunk, static_cast<std::size_t>(n));
  }
  for (std::size_t newline; (newline = worker.received.find('\n')) != std::string::npos;) {
    std::istringstream answer(worker.received.substr(0, newline));
    worker.received.erase(0, newline + 1);
    int code = -1;
    double wall_s = 0.0;
    double cpu_s = 0.0;
    answer >> code >> wall_s >> cpu_s;
    if (!worker.job) continue;
    // The run as a whole (its worker's part and its program's), beside the phases the worker times itself.
    AddPhaseTime("worker_process", wall_s, cpu_s);
    WorkerEnding ending;
    ending.run_id = worker.job->run_id;
    if (code == kWorkerInterrupted) {
      worker.exiting = true;  // an interrupted worker takes no other run
      if (worker.stopping == Worker::Stopping::kTimedOut) {
        ending.reason = "worker: " + TimeoutReason(worker.job->timeout_s, worker.killed, kGraceS);
      } else {
        ending.interrupted = true;
        ending.reason = "worker: " + InterruptReason(InterruptionGuard::Signal(), worker.killed, kGraceS);
      }
    } else {
      ending.reason = "worker: " + ExitReason(code);
    }
    Finish(worker, std::move(ending));
  }
}

void WorkerPool::Bury(Worker& worker) {
  if (worker.pid <= 0) return;
  ::close(worker.channel);
  int status = 0;
  pid_t reaped;
  while ((reaped = ::waitpid(worker.pid, &status, WNOHANG)) < 0 && errno == EINTR) {
  }
  if (reaped == 0) {
    // Its socket closed while it lives on (it cannot answer any more): it is ended.
    ::kill(-worker.pid, SIGKILL);
    while (::waitpid(worker.pid, &status, 0) < 0 && errno == EINTR) {
    }
  }
  if (worker.job) {
    WorkerEnding ending;
    ending.run_id = worker.job->run_id;
    if (worker.stopping == Worker::Stopping::kTimedOut) {
      ending.reason = "worker: " + TimeoutReason(worker.job->timeout_s, worker.killed, kGraceS);
    } else if (worker.stopping == Worker::Stopping::kInterrupted) {
      ending.interrupted = true;
      ending.reason = "worker: " + InterruptReason(InterruptionGuard::Signal(), worker.killed, kGraceS);
    } else if (WIFSIGNALED(status)) {
      ending.reason = "worker: " + SignalReason(WTERMSIG(status));
    } else {
      const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      ending.interrupted = code == kWorkerInterrupted;
      ending.reason = "worker: " + ExitReason(code) + " before it answered";
    }
    worker.exiting = true;
    Finish(worker, std::move(ending));
  }
  worker = Worker{};
}

void WorkerPool::AskToStop(Worker& worker, Worker::Stopping why, Clock::time_point now) {
  if (worker.pid <= 0 || worker.stopping != Worker::Stopping::kNo) return;
  ::kill(-worker.pid, SIGTERM);
  worker.stopping = why;
  worker.kill_at = now + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(kGraceS));
}

void WorkerPool::EnforceDeadlines(Clock::time_point now) {
  for (Worker& worker : workers_) {
    if (worker.pid <= 0) continue;
    if (worker.job && worker.stopping == Worker::Stopping::kNo && now >= worker.job->deadline) {
      AskToStop(worker, Worker::Stopping::kTimedOut, now);
    }
    if (worker.stopping != Worker::Stopping::kNo && !worker.killed && now >= worker.kill_at) {
      ::kill(-worker.pid, SIGKILL);
      worker.killed = true;
    }
  }
}

void WorkerPool::Poll() {
  std::vector<pollfd> fds = {{SignalWakeupFd(), POLLIN, 0}};
  std::vector<Worker*> owners = {nullptr};
  Clock::time_point until = Clock::now() + kMaxSleep;
  for (Worker& worker : workers_) {
    if (worker.pid <= 0) continue;
    fds.push_back({worker.channel, POLLIN, 0});
    owners.push_back(&worker);
    if (worker.job && worker.stopping == Worker::Stopping::kNo) until = std::min(until, worker.job->deadline);
    if (worker.stopping != Worker::Stopping::kNo && !worker.killed) until = std::min(until, worker.kill_at);
  }
  const auto wait_ns =
      std::max<std::int64_t>(0, std::chrono::duration_cast<std::chrono::nanoseconds>(until - Clock::now()).count());
  timespec timeout = {static_cast<time_t>(wait_ns / 1000000000), static_cast<long>(wait_ns % 1000000000)};
  // The signals the supervisor handles are blocked outside this call and open inside it only (ProcessSet's
  // way), so one that arrives after the last check still ends this wait.
  sigset_t open_mask;
  pthread_sigmask(SIG_SETMASK, nullptr, &open_mask);
  for (const int signal_number : {SIGCHLD, SIGINT, SIGTERM, SIGHUP}) sigdelset(&open_mask, signal_number);
  if (::ppoll(fds.data(), fds.size(), &timeout, &open_mask) <= 0) return;
  if (fds[0].revents != 0) DrainSignalWakeup();
  for (std::size_t i = 1; i < fds.size(); ++i) {
    if (fds[i].revents != 0) ReadFrom(*owners[i]);
  }
}

std::size_t WorkerPool::Running() const {
  std::size_t busy = 0;
  for (const Worker& worker : workers_) busy += worker.job ? 1 : 0;
  return busy + ended_.size();
}

std::vector<WorkerEnding> WorkerPool::Wait() {
  for (;;) {
    EnforceDeadlines(Clock::now());
    if (!ended_.empty() || Running() == 0 || InterruptionPending() || TakeWakeUpRequest()) {
      return std::exchange(ended_, {});
    }
    Poll();
  }
}

void WorkerPool::Stop(const std::string& run_id) {
  for (Worker& worker : workers_) {
    if (worker.job && worker.job->run_id == run_id) AskToStop(worker, Worker::Stopping::kInterrupted, Clock::now());
  }
}

std::vector<WorkerEnding> WorkerPool::TerminateAll() {
  const Clock::time_point now = Clock::now();
  for (Worker& worker : workers_) {
    if (worker.pid <= 0) continue;
    if (worker.job) {
      AskToStop(worker, Worker::Stopping::kInterrupted, now);
    } else {
      ::kill(-worker.pid, SIGTERM);
      Bury(worker);
    }
  }
  while (std::any_of(workers_.begin(), workers_.end(), [](const Worker& worker) { return worker.job.has_value(); })) {
    EnforceDeadlines(Clock::now());
    Poll();
  }
  return std::exchange(ended_, {});
}

bool WorkerPool::Interrupted() const { return InterruptionGuard::Interrupted(); }

}  // namespace slamsweep::orchestrator::inline sweep
