#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace slamsweep::orchestrator::inline process {

/// A child's output log of bounded size: the first half of the cap is written as it arrives (so a
/// running program's log can be watched), the last part is kept in memory and written at Finish(),
/// with the marker line "... N bytes omitted ..." between them when something had to be left out.
/// The file never grows beyond the cap (0 = no cap; caps below kMinCapBytes count as kMinCapBytes).
class CappedLog {
 public:
  static constexpr std::uint64_t kMinCapBytes = 256;
  /// Room kept for the marker line, which holds at most 20 digits.
  static constexpr std::uint64_t kMarkerReserveBytes = 64;

  explicit CappedLog(std::uint64_t cap_bytes);
  ~CappedLog();
  CappedLog(CappedLog&& other) noexcept;
  CappedLog& operator=(CappedLog&&) = delete;
  CappedLog(const CappedLog&) = delete;
  CappedLog& operator=(const CappedLog&) = delete;

  /// Creates or truncates `path` (close-on-exec, so no child inherits it). Empty path: output is
  /// counted but discarded. Returns an empty string, or why the file cannot be opened.
  std::string Open(const std::filesystem::path& path);
  /// Takes more output. Write errors (a full disk) drop output but never stop the child.
  void Append(std::string_view bytes);
  /// Writes the kept tail and closes the file. Idempotent.
  void Finish();

  std::uint64_t bytes_received() const { return received_; }
  /// What the file holds after Finish().
  std::uint64_t bytes_written() const { return written_; }
  bool truncated() const { return omitted_ > 0; }
  std::uint64_t bytes_omitted() const { return omitted_; }

 private:
  void Write(std::string_view bytes);

  int fd_ = -1;
  bool finished_ = false;
  std::uint64_t head_cap_;  // 0 = unlimited
  std::uint64_t tail_cap_;
  std::uint64_t received_ = 0;
  std::uint64_t written_ = 0;
  std::uint64_t omitted_ = 0;
  std::uint64_t head_used_ = 0;
  // Ring buffer of the last tail_cap_ bytes after the head; grows lazily so small logs stay small.
  std::string tail_;
  std::size_t tail_next_ = 0;  // where the next byte goes once tail_ is full
  std::uint64_t tail_seen_ = 0;
};

/// Cuts a finished log file down to `cap_bytes` as CappedLog would have written it: its first half of the cap,
/// the marker line "... N bytes omitted ...", its last part (0 = no cap). Only the kept bytes are read.
/// Returns whether anything was left out; a file that cannot be read or replaced is left as it is.
bool CapLogFile(const std::filesystem::path& path, std::uint64_t cap_bytes);

}  // namespace slamsweep::orchestrator::inline process
