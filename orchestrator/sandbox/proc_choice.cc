#include "orchestrator/sandbox/proc_choice.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>
#include <string_view>
#include <vector>

extern char** environ;

namespace slamsweep::orchestrator::inline sandbox {
namespace {

struct Attempt {
  bool ok = false;
  /// The last line bubblewrap wrote.
  std::string message;
};

/// bwrap ARGS... true, its stderr read back; stdin and stdout /dev/null.
Attempt RunBwrap(const std::filesystem::path& bwrap, const std::vector<std::string>& args) {
  Attempt attempt;
  int pipe_fds[2];
  if (::pipe2(pipe_fds, O_CLOEXEC) != 0) return attempt;
  std::vector<std::string> argv = {bwrap.string()};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<char*> pointers;
  for (std::string& item : argv) pointers.push_back(item.data());
  pointers.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  ::posix_spawn_file_actions_init(&actions);
  ::posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  ::posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  ::posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 2);
  pid_t child = -1;
  const int spawned = ::posix_spawn(&child, argv.front().c_str(), &actions, nullptr, pointers.data(), environ);
  ::posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_fds[1]);
  std::string output;
  char buffer[512];
  for (ssize_t n; (n = ::read(pipe_fds[0], buffer, sizeof(buffer))) != 0;) {
    if (n > 0 && output.size() < 4096) output.append(buffer, static_cast<std::size_t>(n));
    if (n < 0 && errno != EINTR) break;
  }
  ::close(pipe_fds[0]);
  if (spawned != 0) {
    attempt.message = "cannot start " + bwrap.string();
    return attempt;
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  attempt.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  while (!output.empty() && output.back() == '\n') output.pop_back();
  attempt.message = output.substr(output.rfind('\n') == std::string::npos ? 0 : output.rfind('\n') + 1);
  return attempt;
}

}  // namespace

SandboxProcChoice SandboxProcFromVariable(std::string_view value) {
  SandboxProcChoice choice;
  if (value == "own") return choice;
  if (value.substr(0, 4) == "none" && (value.size() == 4 || value[4] == ':')) {
    choice.fresh_proc = false;
    std::string why(value.size() > 5 ? value.substr(5) : std::string_view());
    why.erase(0, why.find_first_not_of(' '));
    choice.why = why.empty() ? std::string(kSandboxProcVariable) + "=none" : why;
    return choice;
  }
  throw std::invalid_argument(std::string(kSandboxProcVariable) + "='" + std::string(value) +
                              "': expected own or none (how each sandbox gets its /proc)");
}

SandboxProcChoice ProbeSandboxProc(const std::filesystem::path& bwrap) {
  // The namespaces a sandbox has that decide whether the kernel mounts a proc for it; the whole file system
  // read-only, so that `true` is found wherever it is.
  const std::vector<std::string> base = {"--unshare-user", "--unshare-pid", "--die-with-parent", "--ro-bind", "/", "/"};
  std::vector<std::string> with_proc = base;
  with_proc.insert(with_proc.end(), {"--proc", "/proc", "true"});
  const Attempt fresh = RunBwrap(bwrap, with_proc);
  if (fresh.ok) return {};
  std::vector<std::string> without_proc = base;
  without_proc.push_back("true");
  if (!RunBwrap(bwrap, without_proc).ok) return {};
  return {false, "a fresh /proc cannot be mounted here (" + fresh.message + ")"};
}

const SandboxProcChoice& ChosenSandboxProc(const std::filesystem::path& bwrap) {
  static const SandboxProcChoice choice = [&bwrap] {
    const char* value = std::getenv(kSandboxProcVariable);
    if (value != nullptr && *value != '\0') return SandboxProcFromVariable(value);
    return ProbeSandboxProc(bwrap);
  }();
  return choice;
}

SandboxProcChoice DecideSandboxProcForWorkers(const std::filesystem::path& bwrap) {
  const SandboxProcChoice& choice = ChosenSandboxProc(bwrap);
  const std::string value = choice.fresh_proc ? "own" : "none: " + choice.why;
  ::setenv(kSandboxProcVariable, value.c_str(), 1);
  return choice;
}

}  // namespace slamsweep::orchestrator::inline sandbox
