// slamsweep-sandbox-init: process 1 of a run's sandbox (bubblewrap --as-pid-1). It sets the run's
// limits inside the sandbox's own user namespace, starts the program, reaps every process of the
// sandbox and, once the program has ended, ends what it left behind and reports the program's exact
// wait status to the worker. Usage:
//   slamsweep-sandbox-init --status-fd FD [--process-limit N] [--file-size-limit BYTES] -- PROGRAM ARGS...
// Status lines on FD: "status <wait status>" after the program ended; "exec <errno>" when it could
// not be started. No line at all: the sandbox never got this far.
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

constexpr int kUsageError = 125;

bool ParseNumber(const char* text, unsigned long long& value) {
  if (text == nullptr || *text == '\0') return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtoull(text, &end, 10);
  return errno == 0 && end != nullptr && *end == '\0';
}

void WriteLine(int fd, const char* what, long long value) {
  char line[64];
  const int n = std::snprintf(line, sizeof(line), "%s %lld\n", what, value);
  if (n > 0) (void)!::write(fd, line, static_cast<std::size_t>(n));
}

/// Sets soft and hard limit to `value`, never above the hard limit it inherited.
bool Limit(int resource, unsigned long long value) {
  rlimit current{};
  if (::getrlimit(resource, &current) != 0) return false;
  const rlim_t wanted = current.rlim_max == RLIM_INFINITY ? value : std::min<rlim_t>(value, current.rlim_max);
  const rlimit limit{wanted, wanted};
  return ::setrlimit(resource, &limit) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  int status_fd = -1;
  unsigned long long process_limit = 0, file_size_limit = 0, number = 0;
  int first = 1;
  for (; first < argc; ++first) {
    const char* option = argv[first];
    const char* value = first + 1 < argc ? argv[first + 1] : nullptr;
    if (std::strcmp(option, "--") == 0) {
      ++first;
      break;
    }
    if (!ParseNumber(value, number)) {
      std::fprintf(stderr, "slamsweep-sandbox-init: %s needs a number\n", option);
      return kUsageError;
    }
    if (std::strcmp(option, "--status-fd") == 0) {
      status_fd = static_cast<int>(number);
    } else if (std::strcmp(option, "--process-limit") == 0) {
      process_limit = number;
    } else if (std::strcmp(option, "--file-size-limit") == 0) {
      file_size_limit = number;
    } else {
      std::fprintf(stderr, "slamsweep-sandbox-init: unknown option %s\n", option);
      return kUsageError;
    }
    ++first;
  }
  if (status_fd < 0 || first >= argc) {
    std::fprintf(stderr, "usage: slamsweep-sandbox-init --status-fd FD [--process-limit N] "
                         "[--file-size-limit BYTES] -- PROGRAM ARGS...\n");
    return kUsageError;
  }
  // The program must not inherit the status pipe, nor read this process's memory, descriptors or
  // root through /proc/1 (a process that is not dumpable is out of ptrace's reach for it).
  ::fcntl(status_fd, F_SETFD, FD_CLOEXEC);
  ::prctl(PR_SET_DUMPABLE, 0);
  // Counted per user of this user namespace: the sandbox's processes and threads only.
  if (process_limit > 0 && !Limit(RLIMIT_NPROC, process_limit)) {
    std::perror("slamsweep-sandbox-init: RLIMIT_NPROC");
    return kUsageError;
  }
  if (file_size_limit > 0 && !Limit(RLIMIT_FSIZE, file_size_limit)) {
    std::perror("slamsweep-sandbox-init: RLIMIT_FSIZE");
    return kUsageError;
  }

  const pid_t program = ::fork();
  if (program < 0) {
    WriteLine(status_fd, "exec", errno);
    return kUsageError;
  }
  if (program == 0) {
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    ::execvp(argv[first], argv + first);
    WriteLine(status_fd, "exec", errno);
    ::_exit(127);
  }
  // Process 1 of a PID namespace gets no signal it has no handler for: nothing inside can stop it.
  int program_status = 0;
  for (;;) {
    int status = 0;
    const pid_t ended = ::wait(&status);
    if (ended == program) {
      program_status = status;
      break;
    }
    if (ended < 0 && errno != EINTR) break;
  }
  // Whatever the program left running ends with it, before the status says the run is over.
  ::kill(-1, SIGKILL);
  while (::wait(nullptr) > 0 || errno == EINTR) {
  }
  WriteLine(status_fd, "status", program_status);
  if (WIFEXITED(program_status)) return WEXITSTATUS(program_status);
  return 128 + (WIFSIGNALED(program_status) ? WTERMSIG(program_status) : 0);
}
