// slamsweep-sandbox-init: process 1 of a run's sandbox (bubblewrap --as-pid-1). It sets the run's
// limits inside the sandbox's own user namespace, starts the program, reaps every process of the
// sandbox and, once the program has ended, ends what it left behind and reports the program's exact
// wait status to the worker. Usage:
//   slamsweep-sandbox-init --status-fd FD [--process-limit N] [--file-size-limit BYTES] [--no-user-namespaces]
//                          -- PROGRAM ARGS...
// --no-user-namespaces: a seccomp filter refuses new user namespaces to everything it starts, where
// bubblewrap's --disable-userns cannot be used (a sandbox without /proc).
// Status lines on FD: "status <wait status>" after the program ended; "exec <errno>" when it could
// not be started. No line at all: the sandbox never got this far.
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <sched.h>
#include <seccomp.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
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

/// Refuses unshare and clone with CLONE_NEWUSER (EPERM) and clone3, whose flags a filter cannot read (ENOSYS: the
/// C library falls back to clone), for this process and all it starts (bubblewrap set no_new_privs). Other
/// system calls are allowed: the container's profile and the sandbox's namespaces bound them already.
bool RefuseUserNamespaces() {
  scmp_filter_ctx filter = ::seccomp_init(SCMP_ACT_ALLOW);
  if (filter == nullptr) return false;
  const scmp_datum_t user = CLONE_NEWUSER;
  bool ok = true;
  // The 32-bit ABIs of an x86-64 kernel too: a program could switch to them to pass a filter of the native one.
  for (const std::uint32_t arch : {SCMP_ARCH_X86, SCMP_ARCH_X32}) {
    if (::seccomp_arch_native() == SCMP_ARCH_X86_64) {
      const int added = ::seccomp_arch_add(filter, arch);
      ok = ok && (added == 0 || added == -EEXIST);
    }
  }
  ok = ok && ::seccomp_rule_add(filter, SCMP_ACT_ERRNO(EPERM), SCMP_SYS(unshare), 1,
                                SCMP_A0(SCMP_CMP_MASKED_EQ, user, user)) == 0;
  ok = ok && ::seccomp_rule_add(filter, SCMP_ACT_ERRNO(EPERM), SCMP_SYS(clone), 1,
                                SCMP_A0(SCMP_CMP_MASKED_EQ, user, user)) == 0;
  ok = ok && ::seccomp_rule_add(filter, SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(clone3), 0) == 0;
  ok = ok && ::seccomp_load(filter) == 0;
  ::seccomp_release(filter);
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  int status_fd = -1;
  unsigned long long process_limit = 0, file_size_limit = 0, number = 0;
  bool no_user_namespaces = false;
  int first = 1;
  for (; first < argc; ++first) {
    const char* option = argv[first];
    const char* value = first + 1 < argc ? argv[first + 1] : nullptr;
    if (std::strcmp(option, "--") == 0) {
      ++first;
      break;
    }
    if (std::strcmp(option, "--no-user-namespaces") == 0) {
      no_user_namespaces = true;
      continue;
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
    std::fprintf(stderr,
                 "usage: slamsweep-sandbox-init --status-fd FD [--process-limit N] "
                 "[--file-size-limit BYTES] [--no-user-namespaces] -- PROGRAM ARGS...\n");
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

  if (no_user_namespaces && !RefuseUserNamespaces()) {
    std::fprintf(stderr, "slamsweep-sandbox-init: cannot install the seccomp filter against user namespaces\n");
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
