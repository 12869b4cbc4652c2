#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace slamsweep::evaluator::inline core {

/// A whole file's bytes for parsing in place: a regular file is mapped read-only (no copy, no
/// freshly cleared pages); a file the kernel cannot map (size 0 in /proc, for one) is read into
/// memory instead. Move-only; the bytes live as long as the object.
class MappedFile {
 public:
  /// Nothing when the file cannot be opened or read (the caller says what it expected).
  static std::optional<MappedFile> Open(const std::filesystem::path& path);

  MappedFile(MappedFile&& other) noexcept;
  MappedFile& operator=(MappedFile&& other) noexcept;
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  ~MappedFile();

  std::string_view bytes() const { return mapping_ != nullptr ? std::string_view(mapping_, size_) : read_; }

 private:
  MappedFile() = default;
  void Release() noexcept;

  const char* mapping_ = nullptr;
  std::size_t size_ = 0;
  std::string read_;
};

}  // namespace slamsweep::evaluator::inline core
