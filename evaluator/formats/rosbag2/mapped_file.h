#pragma once

#include <cstdint>
#include <filesystem>
#include <span>

namespace slamsweep::evaluator::inline formats::inline rosbag2 {

/// A file mapped read-only into memory (mmap), so that a bag of gigabytes is read without copying it.
/// Move-only; unmapped when destroyed.
class MappedFile {
 public:
  /// Throws InputError naming the file when it cannot be opened or mapped.
  explicit MappedFile(const std::filesystem::path& path);
  ~MappedFile();
  MappedFile(MappedFile&& other) noexcept;
  MappedFile& operator=(MappedFile&& other) noexcept;
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::span<const std::uint8_t> Bytes() const { return {data_, size_}; }

 private:
  const std::uint8_t* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
