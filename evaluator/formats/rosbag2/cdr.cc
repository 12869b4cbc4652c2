#include "evaluator/formats/rosbag2/cdr.h"

#include <fmt/format.h>

#include <bit>
#include <cstring>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline formats::inline rosbag2 {
namespace {

constexpr std::size_t kHeaderSize = 4;

template <typename T>
T FromBytes(const std::uint8_t* bytes, bool big_endian) {
  std::uint8_t ordered[sizeof(T)];
  std::memcpy(ordered, bytes, sizeof(T));
  if (big_endian != (std::endian::native == std::endian::big)) {
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(ordered[i], ordered[sizeof(T) - 1 - i]);
  }
  T value;
  std::memcpy(&value, ordered, sizeof(T));
  return value;
}

std::string DescribeEncapsulation(std::uint8_t first, std::uint8_t second) {
  const unsigned id = (unsigned{first} << 8) | second;
  switch (id) {
    case 0x0002:
    case 0x0003:
      return "a parameter list (PL_CDR)";
    case 0x0006:
    case 0x0007:
      return "XCDR2 (CDR2)";
    case 0x0008:
    case 0x0009:
      return "delimited XCDR2";
    case 0x000a:
    case 0x000b:
      return "an XCDR2 parameter list";
    default:
      return fmt::format("unknown encapsulation {:02x} {:02x}", first, second);
  }
}

}  // namespace

CdrReader::CdrReader(std::span<const std::uint8_t> payload, std::string where) : where_(std::move(where)) {
  if (payload.size() < kHeaderSize) {
    throw InputError(fmt::format("{}: CDR message of {} bytes, shorter than its 4-byte encapsulation header", where_,
                                 payload.size()));
  }
  if (payload[0] != 0 || payload[1] > 1) {
    throw InputError(
        fmt::format("{}: CDR encapsulation is {}; expected plain CDR (00 00 big endian or 00 01 "
                    "little endian), which rosbag2's cdr serialisation writes",
                    where_, DescribeEncapsulation(payload[0], payload[1])));
  }
  big_endian_ = payload[1] == 0;
  body_ = payload.subspan(kHeaderSize);
}

const std::uint8_t* CdrReader::Take(std::size_t size, std::size_t alignment, const char* what) {
  const std::size_t aligned = (offset_ + alignment - 1) / alignment * alignment;
  if (aligned > body_.size() || body_.size() - aligned < size) {
    throw InputError(fmt::format("{}: truncated CDR message: {} ({} bytes) at offset {} of {}", where_, what, size,
                                 aligned + kHeaderSize, body_.size() + kHeaderSize));
  }
  offset_ = aligned + size;
  return body_.data() + aligned;
}

template <typename T>
T CdrReader::Read(const char* what) {
  return FromBytes<T>(Take(sizeof(T), sizeof(T), what), big_endian_);
}

std::int32_t CdrReader::Int32() { return Read<std::int32_t>("int32"); }
std::uint32_t CdrReader::Uint32() { return Read<std::uint32_t>("uint32"); }
float CdrReader::Float32() { return Read<float>("float32"); }
double CdrReader::Float64() { return Read<double>("float64"); }

std::string CdrReader::String() {
  const std::uint32_t length = Read<std::uint32_t>("string length");
  if (length == 0) return {};  // some writers omit the NUL of an empty string
  const auto* bytes = reinterpret_cast<const char*>(Take(length, 1, "string"));
  if (bytes[length - 1] != '\0') {
    throw InputError(fmt::format("{}: CDR string of {} bytes at offset {} lacks its terminating NUL", where_, length,
                                 offset_ - length + kHeaderSize));
  }
  return std::string(bytes, length - 1);
}

std::uint32_t CdrReader::SequenceLength(std::size_t min_element_size) {
  const std::uint32_t count = Read<std::uint32_t>("sequence length");
  const std::size_t left = body_.size() - offset_;
  if (min_element_size > 0 && count > left / min_element_size) {
    throw InputError(fmt::format("{}: CDR sequence of {} elements at offset {} does not fit in the {} bytes left",
                                 where_, count, offset_ - 4 + kHeaderSize, left));
  }
  return count;
}

std::vector<float> CdrReader::Float32Sequence() {
  const std::uint32_t count = SequenceLength(sizeof(float));
  std::vector<float> values;
  values.reserve(count);
  for (std::uint32_t i = 0; i < count; ++i) values.push_back(Float32());
  return values;
}

void CdrReader::Skip(std::size_t count, std::size_t size) {
  for (std::size_t i = 0; i < count; ++i) Take(size, size, "value");
}

CdrWriter::CdrWriter() : bytes_{0x00, 0x01, 0x00, 0x00} {}

void CdrWriter::Align(std::size_t alignment) {
  const std::size_t offset = bytes_.size() - kHeaderSize;
  bytes_.resize(kHeaderSize + (offset + alignment - 1) / alignment * alignment, 0);
}

template <typename T>
void CdrWriter::Write(T value) {
  Align(sizeof(T));
  std::uint8_t raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) {
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
  }
  bytes_.insert(bytes_.end(), raw, raw + sizeof(T));
}

void CdrWriter::Int32(std::int32_t value) { Write(value); }
void CdrWriter::Uint32(std::uint32_t value) { Write(value); }
void CdrWriter::Float32(float value) { Write(value); }
void CdrWriter::Float64(double value) { Write(value); }

void CdrWriter::String(const std::string& value) {
  Write(static_cast<std::uint32_t>(value.size() + 1));
  bytes_.insert(bytes_.end(), value.begin(), value.end());
  bytes_.push_back(0);
}

void CdrWriter::Float32Sequence(const std::vector<float>& values) {
  Write(static_cast<std::uint32_t>(values.size()));
  for (const float value : values) Write(value);
}

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
