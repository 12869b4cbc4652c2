#include "report/plots/gnuplot_process.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "orchestrator/process/run_to_exit.h"

namespace slamsweep::report::inline plots {
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

  const std::string program_text = program.string();
  orchestrator::ChildStreams streams;
  streams.stdin_fd = input.get();
  streams.stderr_fd = errors.get();
  streams.discard_stdout = true;
  orchestrator::ExitStatus exit;
  try {
    exit = orchestrator::RunToExit({program_text, "-d"}, streams);
  } catch (const std::system_error& error) {
    throw std::runtime_error("cannot wait for gnuplot: " + ErrnoText(error.code().value()));
  }
  if (!exit.start_error.empty()) {
    throw std::runtime_error("cannot start gnuplot (" + program_text + "): " + exit.start_error +
                             "; install gnuplot-nox");
  }
  GnuplotOutcome outcome;
  outcome.exit_code = exit.exit_code;
  outcome.stderr_text = ReadAll(errors.get());
  return outcome;
}

}  // namespace slamsweep::report::inline plots
