// Boost 1.74 compiles its vfork launcher only for old POSIX levels, although glibc has vfork; the
// flag must be set before any Boost.Process header (see SpawnChild for why vfork).
#define BOOST_POSIX_HAS_VFORK 1

#include "orchestrator/process/spawn.h"

#include "orchestrator/sandbox/bwrap_command.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <exception>
#include <optional>
#include <string_view>
#include <system_error>

#include <boost/process.hpp>
#include <boost/process/extend.hpp>
#include <boost/process/posix.hpp>

namespace slamsweep::orchestrator::inline process {
namespace bp = boost::process;
namespace {

/// The child's environment, NAME=VALUE: the supervisor's without the removed prefixes, then the spec's own.
/// Built here rather than with bp::environment, whose lookup by name (operator[], erase) reads past the end
/// of an entry shorter than the name (Boost 1.74's basic_environment_impl::find; AddressSanitizer reports it).
std::vector<std::string> ChildEnvironment(const ProcessSpec& spec) {
  std::vector<std::string> entries;
  for (char** entry = ::environ; *entry != nullptr; ++entry) {
    const std::string_view text(*entry);
    const std::string_view name = text.substr(0, text.find('='));
    const bool removed = std::ranges::any_of(spec.removed_env_prefixes,
                                             [&](const std::string& prefix) { return name.starts_with(prefix); });
    const bool replaced = std::ranges::any_of(spec.extra_env, [&](const auto& extra) { return extra.first == name; });
    if (!removed && !replaced) entries.emplace_back(text);
  }
  for (auto extra = spec.extra_env.begin(); extra != spec.extra_env.end(); ++extra) {
    const bool set_again = std::any_of(std::next(extra), spec.extra_env.end(),
                                       [&](const auto& later) { return later.first == extra->first; });
    if (!set_again) entries.push_back(extra->first + "=" + extra->second);  // the last setting wins
  }
  return entries;
}

/// Hands the child the environment above (execve's envp).
struct ExplicitEnvironment : bp::extend::handler {
  char** envp = nullptr;
  template <typename Executor>
  void on_setup(Executor& exec) const {
    exec.env = envp;
  }
};

/// What the child does between fork and exec (async-signal-safe calls only).
struct ChildSetup : bp::extend::handler {
  pid_t supervisor = 0;
  /// The sandbox's status pipe, the one descriptor above 2 the child keeps; -1 for none.
  int kept_fd = -1;
  /// The user the child becomes before exec (a sandbox started by root); nullopt: the runner's.
  std::optional<SandboxSpec::User> user;
  /// A pids cgroup's cgroup.procs the child joins before exec; nullptr: none.
  const char* cgroup_procs = nullptr;

  template <typename Executor>
  void on_exec_setup(Executor&) const {
    // Own group: timeouts and interruption signal the program and everything it started, and a
    // Ctrl-C at the terminal reaches the supervisor only, which then stops the groups in order.
    ::setpgid(0, 0);
    // Both survive exec: a blocked or ignored signal in the program would make it unkillable by TERM.
    sigset_t empty;
    sigemptyset(&empty);
    ::sigprocmask(SIG_SETMASK, &empty, nullptr);
    for (int signal_number = 1; signal_number < NSIG; ++signal_number) {
      if (signal_number != SIGKILL && signal_number != SIGSTOP) ::signal(signal_number, SIG_DFL);
    }
    // Descriptors the supervisor opened without O_CLOEXEC (a database, another run's log) must not
    // reach the program. Marked close-on-exec rather than closed: Boost's exec-error pipe must stay
    // open until exec, and the standard streams set up later by dup2 are below 3.
    ::close_range(3, ~0U, CLOSE_RANGE_CLOEXEC);
    if (kept_fd >= 0) ::fcntl(kept_fd, F_SETFD, 0);
    if (cgroup_procs != nullptr) {
      // "0": the writing process; everything it starts from now on is counted there.
      const int procs = ::open(cgroup_procs, O_WRONLY | O_CLOEXEC);
      const bool joined = procs >= 0 && ::write(procs, "0", 1) == 1;
      if (procs >= 0) ::close(procs);
      if (!joined) ::_exit(126);
    }
    if (user) {
      // Raw system calls: glibc's wrappers would signal every thread of the (vfork-shared) parent.
      if (::syscall(SYS_setgroups, 0, nullptr) != 0 || ::syscall(SYS_setresgid, user->gid, user->gid, user->gid) != 0 ||
          ::syscall(SYS_setresuid, user->uid, user->uid, user->uid) != 0) {
        ::_exit(126);
      }
    }
    // After the change of user, which clears it.
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    // The supervisor may have died before prctl took effect; then nobody would send the signal.
    if (::getppid() != supervisor) ::_exit(127);
  }

  template <typename Executor>
  void on_error(Executor& executor, const std::error_code&) const {
    // Boost.Process does not reap a child whose exec failed; it has exited, so this does not block long.
    if (executor.pid > 0) ::waitpid(executor.pid, nullptr, 0);
  }
};

/// ChildStreams' replacements of the standard streams. Given after Boost's stream handlers, so its
/// dup2 calls come last.
struct StreamRedirection : bp::extend::handler {
  int stdin_fd = -1;
  int stdout_fd = -1;
  int stderr_fd = -1;

  template <typename Executor>
  void on_exec_setup(Executor&) const {
    Redirect(stdin_fd, STDIN_FILENO);
    Redirect(stdout_fd, STDOUT_FILENO);
    Redirect(stderr_fd, STDERR_FILENO);
  }

  static void Redirect(int from, int to) {
    if (from < 0) return;
    // dup2 onto itself would keep the close-on-exec flag that ChildSetup set.
    if (from == to) {
      ::fcntl(to, F_SETFD, 0);
    } else {
      ::dup2(from, to);
    }
  }
};

std::string ResolveProgram(const std::string& program, std::string& error) {
  if (program.find('/') != std::string::npos) {
    if (::access(program.c_str(), F_OK) != 0) error = std::strerror(errno);
    return program;
  }
  const boost::filesystem::path found = bp::search_path(program);
  if (found.empty()) error = "No such file or directory (not found in PATH)";
  return found.string();
}

}  // namespace

SpawnResult SpawnChild(const ProcessSpec& spec, const ChildStreams& streams) {
  SpawnResult result;
  if (spec.argv.empty() || spec.argv.front().empty()) {
    result.error = "empty command";
    return result;
  }
  const std::string program = ResolveProgram(spec.argv.front(), result.error);
  if (!result.error.empty()) return result;
  if (!spec.working_dir.empty()) {
    std::error_code ec;
    if (!std::filesystem::is_directory(spec.working_dir, ec)) {
      result.error = "working directory '" + spec.working_dir.string() + "' does not exist";
      return result;
    }
  }

  int null_output = -1;
  if (streams.discard_stdout) {
    null_output = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (null_output < 0) {
      result.error = std::strerror(errno);
      return result;
    }
  }
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    result.error = std::string("pipe: ") + std::strerror(errno);
    if (null_output >= 0) ::close(null_output);
    return result;
  }
  int status_write = -1;
  try {
    // Close-on-exec ends: no other child (started later) inherits this child's pipe, which would
    // otherwise keep it open after the child ends. dup2 onto 1 and 2 clears the flag for the child.
    bp::pipe pipe(fds[0], fds[1]);
    const std::vector<std::string> environment = ChildEnvironment(spec);
    std::vector<char*> envp;
    for (const std::string& entry : environment) envp.push_back(const_cast<char*>(entry.c_str()));
    envp.push_back(nullptr);
    const std::string working_dir = spec.working_dir.empty() ? std::string(".") : spec.working_dir.string();
    std::string executable = program;
    std::vector<std::string> args(spec.argv.begin() + 1, spec.argv.end());
    if (spec.sandbox) {
      // bubblewrap starts the program (by the path resolved here, which the sandbox must show) under
      // slamsweep-sandbox-init, which reports its exact status on this pipe.
      int status_pipe[2];
      if (::pipe2(status_pipe, O_CLOEXEC) != 0) throw std::system_error(errno, std::system_category(), "pipe");
      result.status_fd = status_pipe[0];
      status_write = status_pipe[1];
      std::vector<std::string> program_argv = spec.argv;
      program_argv.front() = program;
      const std::vector<std::string> command = BwrapCommand(
          *spec.sandbox, program_argv, std::filesystem::absolute(working_dir).lexically_normal(), status_write);
      executable = command.front();
      args.assign(command.begin() + 1, command.end());
    }
    std::error_code ec;
    // vfork: the supervisor links OpenCV and MRPT, and copying its page tables for every fork is the
    // largest part of the per-run overhead (bench/sweep_bench). ChildSetup writes no shared memory.
    std::optional<SandboxSpec::User> user;
    const char* cgroup_procs = nullptr;
    if (spec.sandbox) {
      user = spec.sandbox->user;
      if (!spec.sandbox->pids_cgroup_procs.empty()) cgroup_procs = spec.sandbox->pids_cgroup_procs.c_str();
    }
    bp::child child(ChildSetup{{}, ::getpid(), status_write, user, cgroup_procs}, bp::posix::use_vfork,
                    bp::exe = executable, bp::args = args, bp::std_in<bp::null, (bp::std_out & bp::std_err)> pipe,
                    bp::start_dir = working_dir, ExplicitEnvironment{{}, envp.data()},
                    StreamRedirection{{}, streams.stdin_fd, null_output, streams.stderr_fd}, ec);
    if (status_write >= 0) ::close(status_write);
    status_write = -1;
    if (ec || !child.valid()) {
      result.error = ec ? ec.message() : "unknown error";  // `pipe` closes both ends
    } else {
      // We reap with wait4() ourselves (rusage) and send TERM before KILL; Boost must not touch it.
      child.detach();
      result.pid = child.id();
      if (!streams.OutputElsewhere()) {  // else `pipe` closes both ends: nothing writes to it
        result.output_fd = pipe.native_source();
        pipe.assign_source(-1);
        ::fcntl(result.output_fd, F_SETFL, ::fcntl(result.output_fd, F_GETFL) | O_NONBLOCK);
      }
    }
  } catch (const std::exception& error) {
    result.error = error.what();
  }
  if (status_write >= 0) ::close(status_write);
  if (null_output >= 0) ::close(null_output);
  if (!result.error.empty() && result.status_fd >= 0) {
    ::close(result.status_fd);
    result.status_fd = -1;
  }
  return result;
}

}  // namespace slamsweep::orchestrator::inline process
