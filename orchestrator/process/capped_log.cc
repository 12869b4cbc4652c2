#include "orchestrator/process/capped_log.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

#include <fmt/format.h>

namespace slamsweep::orchestrator::inline process {

CappedLog::CappedLog(std::uint64_t cap_bytes) {
  if (cap_bytes == 0) {
    head_cap_ = 0;
    tail_cap_ = 0;
    return;
  }
  const std::uint64_t cap = std::max(cap_bytes, kMinCapBytes);
  head_cap_ = cap / 2;
  tail_cap_ = cap - head_cap_ - kMarkerReserveBytes;
}

CappedLog::~CappedLog() { Finish(); }

CappedLog::CappedLog(CappedLog&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)),
      finished_(std::exchange(other.finished_, true)),
      head_cap_(other.head_cap_),
      tail_cap_(other.tail_cap_),
      received_(other.received_),
      written_(other.written_),
      omitted_(other.omitted_),
      head_used_(other.head_used_),
      tail_(std::move(other.tail_)),
      tail_next_(other.tail_next_),
      tail_seen_(other.tail_seen_) {}

std::string CappedLog::Open(const std::filesystem::path& path) {
  if (path.empty()) return "";
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) return fmt::format("cannot open log '{}': {}", path.string(), std::strerror(errno));
  return "";
}

void CappedLog::Write(std::string_view bytes) {
  while (fd_ >= 0 && !bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return;  // a full disk loses log lines, not the run
    }
    written_ += static_cast<std::uint64_t>(n);
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
}

void CappedLog::Append(std::string_view bytes) {
  if (finished_) return;
  received_ += bytes.size();
  if (head_cap_ == 0) {
    Write(bytes);
    return;
  }
  if (head_used_ < head_cap_) {
    const std::size_t to_head = static_cast<std::size_t>(std::min<std::uint64_t>(head_cap_ - head_used_, bytes.size()));
    Write(bytes.substr(0, to_head));
    head_used_ += to_head;
    bytes.remove_prefix(to_head);
  }
  if (bytes.empty()) return;
  tail_seen_ += bytes.size();
  // Only the last tail_cap_ bytes of this chunk can survive.
  if (bytes.size() > tail_cap_) bytes = bytes.substr(bytes.size() - tail_cap_);
  while (!bytes.empty()) {
    if (tail_.size() < tail_cap_) {
      const std::size_t n = std::min<std::size_t>(tail_cap_ - tail_.size(), bytes.size());
      tail_.append(bytes.substr(0, n));
      bytes.remove_prefix(n);
      tail_next_ = tail_.size() % tail_cap_;
      continue;
    }
    const std::size_t n = std::min(tail_.size() - tail_next_, bytes.size());
    std::memcpy(tail_.data() + tail_next_, bytes.data(), n);
    tail_next_ = (tail_next_ + n) % tail_.size();
    bytes.remove_prefix(n);
  }
}

void CappedLog::Finish() {
  if (finished_) return;
  finished_ = true;
  if (tail_seen_ > tail_.size()) {
    omitted_ = tail_seen_ - tail_.size();
    Write(fmt::format("\n... {} bytes omitted ...\n", omitted_));
  }
  if (tail_.size() < tail_cap_) {
    Write(tail_);
  } else {
    // Oldest bytes start at tail_next_ once the ring has wrapped.
    Write(std::string_view(tail_).substr(tail_next_));
    Write(std::string_view(tail_).substr(0, tail_next_));
  }
  tail_.clear();
  tail_.shrink_to_fit();
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

namespace {

/// `size` bytes of `fd` from `offset`; fewer when the file ends early or a read fails.
std::string ReadAt(int fd, std::uint64_t offset, std::uint64_t size) {
  std::string bytes(static_cast<std::size_t>(size), '\0');
  std::size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = ::pread(fd, bytes.data() + got, bytes.size() - got, static_cast<off_t>(offset + got));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  bytes.resize(got);
  return bytes;
}

}  // namespace

bool CapLogFile(const std::filesystem::path& path, std::uint64_t cap_bytes) {
  std::error_code error;
  const std::uint64_t size = std::filesystem::file_size(path, error);
  if (error || cap_bytes == 0 || size <= std::max(cap_bytes, CappedLog::kMinCapBytes)) return false;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const std::uint64_t cap = std::max(cap_bytes, CappedLog::kMinCapBytes);
  const std::uint64_t head_cap = cap / 2;
  const std::uint64_t tail_cap = cap - head_cap - CappedLog::kMarkerReserveBytes;
  const std::string head = ReadAt(fd, 0, head_cap);
  const std::string tail = ReadAt(fd, size - tail_cap, tail_cap);
  ::close(fd);
  if (head.size() != head_cap || tail.size() != tail_cap) return false;
  const std::filesystem::path temporary = path.string() + ".capping";
  {
    CappedLog log(0);
    if (!log.Open(temporary).empty()) return false;
    log.Append(head);
    // CappedLog's marker line for what lies between, which is counted, never read.
    log.Append(fmt::format("\n... {} bytes omitted ...\n", size - head_cap - tail_cap));
    log.Append(tail);
    log.Finish();
  }
  std::filesystem::rename(temporary, path, error);
  if (error) std::filesystem::remove(temporary, error);
  return !error;
}

}  // namespace slamsweep::orchestrator::inline process
