#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace slamsweep::evaluator::inline formats::inline rosbag2 {

/// Reads one ROS 2 message serialised as plain CDR (XCDR1), the encoding rosbag2 stores ("cdr"): a
/// 4-byte encapsulation header (00 00: big endian, 00 01: little endian; two option bytes), then the
/// fields in order, each primitive aligned to its size (8-byte values to 8) counted from the byte
/// after the header; strings are a uint32 length counting the terminating NUL, then the bytes;
/// sequences a uint32 count, then the elements. Every read is bounds-checked: errors are InputErrors
/// "`where`: ..." naming the offset and what was expected.
class CdrReader {
 public:
  /// Throws InputError for a payload shorter than its header or an encapsulation other than plain
  /// CDR (e.g. XCDR2 or a parameter list), naming it.
  CdrReader(std::span<const std::uint8_t> payload, std::string where);

  bool BigEndian() const { return big_endian_; }
  std::int32_t Int32();
  std::uint32_t Uint32();
  float Float32();
  double Float64();
  std::string String();
  /// A sequence's element count, checked against the bytes left (each element takes at least
  /// `min_element_size` bytes), so that a corrupt count cannot ask for gigabytes.
  std::uint32_t SequenceLength(std::size_t min_element_size);
  std::vector<float> Float32Sequence();
  /// Skips `count` values of `size` bytes each (aligned to `size`).
  void Skip(std::size_t count, std::size_t size);

 private:
  const std::uint8_t* Take(std::size_t size, std::size_t alignment, const char* what);
  template <typename T>
  T Read(const char* what);

  std::span<const std::uint8_t> body_;
  std::size_t offset_ = 0;
  bool big_endian_ = false;
  std::string where_;
};

/// Writes plain little-endian CDR (the encapsulation 00 01 00 00), as ROS 2 publishers do.
class CdrWriter {
 public:
  CdrWriter();
  void Int32(std::int32_t value);
  void Uint32(std::uint32_t value);
  void Float32(float value);
  void Float64(double value);
  void String(const std::string& value);
  void Float32Sequence(const std::vector<float>& values);
  /// The message so far, header included.
  const std::vector<std::uint8_t>& Bytes() const { return bytes_; }

 private:
  void Align(std::size_t alignment);
  template <typename T>
  void Write(T value);

  std::vector<std::uint8_t> bytes_;
};

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
