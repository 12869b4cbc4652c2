#include "report/plots/gnuplot_process.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace slamsweep::report {
namespace {

std::string ErrnoText(int error) { return std::strerror(error); }

/// A file descriptor closed when it goes out of scope.
class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

/// An anonymous temporary file: created and unlinked at once, so nothing is left behind even
/// when this process is killed.
int AnonymousTempFile() {
  std::string pattern = (std::filesystem::temp_directory_path() / "slamsweep-gnuplot-XXXXXX").string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkostemp(name.data(), O_CLOEXEC);
  if (fd < 0) throw std::runtime_error("cannot create a temporary file for gnuplot: " + ErrnoText(errno));
  ::unlink(name.data());
  return fd;
}

void WriteAll(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd, bytes.data(), bytes.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("cannot write the gnuplot script to a temporary file: " + ErrnoText(errno));
    }
    bytes.remove_prefix(static_cast<std::size_t>(written));
  }
}

std::string ReadAll(int fd) {
  std::string text;
  if (::lseek(fd, 0, SEEK_SET) < 0) return text;
  char buffer[8192];
  for (;;) {
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;
    text.append(buffer, static_cast<std::size_t>(got));
  }
  return text;
}

}  // namespace

GnuplotOutcome RunGnuplot(std::string_view script, const std::filesystem::path& program) {
  const Fd input(AnonymousTempFile());
  const Fd errors(AnonymousTempFile());
  WriteAll(input.get(), script);
  if (::lseek(input.get(), 0, SEEK_SET) < 0) {
    throw std::runtime_error("cannot rewind the gnuplot script file: " + ErrnoText(errno));
  }

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, input.get(), STDIN_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, errors.get(), STDERR_FILENO);

  const std::string program_text = program.string();
  std::string arg0 = "gnuplot";
  std::string arg1 = "-d";
  char* argv[] = {arg0.data(), arg1.data(), nullptr};
  pid_t pid = 0;
  const int spawn_error = ::posix_spawn(&pid, program_text.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawn_error != 0) {
    throw std::runtime_error("cannot start gnuplot (" + program_text + "): " + ErrnoText(spawn_error) +
                             "; install gnuplot-nox");
  }

  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("cannot wait for gnuplot: " + ErrnoText(errno));
  }
  GnuplotOutcome outcome;
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  outcome.stderr_text = ReadAll(errors.get());
  return outcome;
}

}  // namespace slamsweep::report
