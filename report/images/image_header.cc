#include "report/images/image_header.h"

#include <array>
#include <cctype>
#include <fstream>
#include <string>

namespace slamsweep::report::inline images {
namespace {

std::optional<cv::Size> PngSize(const std::array<unsigned char, 24>& head) {
  static constexpr std::array<unsigned char, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  for (std::size_t i = 0; i < kSignature.size(); ++i) {
    if (head[i] != kSignature[i]) return std::nullopt;
  }
  if (head[12] != 'I' || head[13] != 'H' || head[14] != 'D' || head[15] != 'R') return std::nullopt;
  const auto big_endian = [&](std::size_t at) {
    return (std::uint32_t{head[at]} << 24) | (std::uint32_t{head[at + 1]} << 16) | (std::uint32_t{head[at + 2]} << 8) |
           std::uint32_t{head[at + 3]};
  };
  const std::uint32_t width = big_endian(16);
  const std::uint32_t height = big_endian(20);
  if (width == 0 || height == 0 || width > 1u << 20 || height > 1u << 20) return std::nullopt;
  return cv::Size(static_cast<int>(width), static_cast<int>(height));
}

/// Reads the next header integer of a PNM file, skipping blanks and # comments.
std::optional<int> PnmNumber(std::istream& in) {
  int c = in.get();
  while (in && (std::isspace(c) || c == '#')) {
    if (c == '#') {
      while (in && c != '\n') c = in.get();
    }
    c = in.get();
  }
  long value = 0;
  bool any = false;
  while (in && std::isdigit(c)) {
    value = value * 10 + (c - '0');
    if (value > (1 << 20)) return std::nullopt;
    any = true;
    c = in.get();
  }
  if (!any || value <= 0) return std::nullopt;
  return static_cast<int>(value);
}

}  // namespace

std::optional<cv::Size> PeekImageSize(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::array<unsigned char, 24> head{};
  in.read(reinterpret_cast<char*>(head.data()), head.size());
  if (in.gcount() >= 24 && head[0] == 0x89) return PngSize(head);
  if (in.gcount() < 3 || head[0] != 'P' || head[1] < '1' || head[1] > '6') return std::nullopt;
  in.clear();
  in.seekg(2);
  const std::optional<int> width = PnmNumber(in);
  const std::optional<int> height = width ? PnmNumber(in) : std::nullopt;
  if (!height) return std::nullopt;
  return cv::Size(*width, *height);
}

}  // namespace slamsweep::report::inline images
