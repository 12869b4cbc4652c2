#include "orchestrator/files/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator::inline files {
namespace {

[[noreturn]] void Fail(const std::filesystem::path& file, const char* doing, int error) {
  throw evaluator::InputError(fmt::format("{}: cannot {}: {}", file.string(), doing, std::strerror(error)));
}

}  // namespace

void WriteFileAtomically(const std::filesystem::path& file, std::string_view content, Durability durability) {
  const bool durable = durability == Durability::kMachineCrash;
  // The pid keeps two processes writing the same file (two merges) from sharing one temporary.
  const std::filesystem::path temporary = file.string() + fmt::format(".tmp.{}", ::getpid());
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) Fail(temporary, "create", errno);
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      ::close(fd);
      ::unlink(temporary.c_str());
      Fail(temporary, "write", error);
    }
    written += static_cast<std::size_t>(n);
  }
  const int sync_error = durable && ::fsync(fd) != 0 ? errno : 0;
  const int close_error = ::close(fd) != 0 ? errno : 0;
  if (sync_error != 0 || close_error != 0) {
    const int error = sync_error != 0 ? sync_error : close_error;
    ::unlink(temporary.c_str());
    Fail(temporary, "flush", error);
  }
  if (::rename(temporary.c_str(), file.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    Fail(file, "replace", error);
  }
  // The rename itself is durable only once the folder holding it is synced.
  if (!durable) return;
  const std::filesystem::path folder = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
  const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

}  // namespace slamsweep::orchestrator::inline files
