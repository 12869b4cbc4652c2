#include "evaluator/formats/map/pnm_image.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline formats::inline map {
namespace {

bool IsPnmSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

/// Walks the bytes of a PNM file; every error names the file and what was expected.
class PnmReader {
 public:
  PnmReader(std::string_view bytes, const std::filesystem::path& source) : bytes_(bytes), source_(source) {}

  /// Next unsigned decimal number, skipping whitespace and `#` comments (which run to the end of the line).
  long long Number(std::string_view what) {
    while (position_ < bytes_.size()) {
      const char c = bytes_[position_];
      if (IsPnmSpace(c)) {
        ++position_;
      } else if (c == '#') {
        while (position_ < bytes_.size() && bytes_[position_] != '\n' && bytes_[position_] != '\r') ++position_;
      } else {
        break;
      }
    }
    if (position_ >= bytes_.size()) Fail(fmt::format("file ends before the {} (truncated file?)", what));
    if (!std::isdigit(static_cast<unsigned char>(bytes_[position_]))) {
      Fail(fmt::format("expected the {} as a decimal number, got '{}'", what, bytes_[position_]));
    }
    long long value = 0;
    while (position_ < bytes_.size() && std::isdigit(static_cast<unsigned char>(bytes_[position_]))) {
      value = value * 10 + (bytes_[position_] - '0');
      if (value > std::numeric_limits<int>::max()) Fail(fmt::format("{} is too large", what));
      ++position_;
    }
    return value;
  }

  /// The single whitespace byte that separates a binary header from the pixel data.
  void HeaderEnd() {
    if (position_ >= bytes_.size() || !IsPnmSpace(bytes_[position_])) {
      Fail("expected one whitespace byte after maxval, before the pixel data");
    }
    ++position_;
  }

  std::string_view Rest() const { return bytes_.substr(position_); }

  [[noreturn]] void Fail(std::string_view message) const {
    throw InputError(Located(source_, 0, fmt::format("PNM image: {}", message)));
  }

 private:
  std::string_view bytes_;
  const std::filesystem::path& source_;
  std::size_t position_ = 2;  // after the magic number
};

}  // namespace

bool LooksLikePnm(std::string_view bytes) {
  return bytes.size() >= 2 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '7';
}

namespace {

/// A PNM file's header, checked: what its pixel data holds and where it starts.
struct PnmLayout {
  bool ascii = false;
  int channels = 1;
  long long width = 0;
  long long height = 0;
  long long maxval = 0;
  unsigned long long samples = 0;
  std::string_view data;  // after the header
};

PnmLayout ReadPnmLayout(PnmReader& reader, std::string_view bytes) {
  if (!LooksLikePnm(bytes)) {
    reader.Fail("expected the magic number P2, P3, P5 or P6 at the start of the file");
  }
  const char kind = bytes[1];
  if (kind == '1' || kind == '4') {
    reader.Fail("bitmap (PBM) files are not supported; expected an 8-bit PGM (P5) or PPM (P6)");
  }
  if (kind == '7') reader.Fail("PAM (P7) files are not supported; expected an 8-bit PGM (P5) or PPM (P6)");
  PnmLayout layout;
  layout.ascii = kind == '2' || kind == '3';
  layout.channels = (kind == '3' || kind == '6') ? 3 : 1;

  layout.width = reader.Number("width");
  layout.height = reader.Number("height");
  if (layout.width <= 0 || layout.height <= 0)
    reader.Fail(fmt::format("image size {} x {}; expected a positive size", layout.width, layout.height));
  layout.maxval = reader.Number("maxval");
  if (layout.maxval > 255) {
    reader.Fail(fmt::format("16-bit image (maxval {}); expected 8-bit samples (maxval <= 255), as map_server reads",
                            layout.maxval));
  }
  if (layout.maxval <= 0) reader.Fail("maxval 0; expected 1..255");

  layout.samples = static_cast<unsigned long long>(layout.width) * static_cast<unsigned long long>(layout.height) *
                   static_cast<unsigned long long>(layout.channels);
  if (layout.samples > static_cast<unsigned long long>(std::numeric_limits<int>::max())) {
    reader.Fail(fmt::format("image size {} x {} is too large", layout.width, layout.height));
  }
  if (!layout.ascii) reader.HeaderEnd();
  // Every sample takes at least one byte, so a short file is reported before allocating for it.
  if (reader.Rest().size() < layout.samples) {
    reader.Fail(
        fmt::format("pixel data truncated: the header announces {} x {} pixels x {} channel(s) = {} samples, "
                    "the file holds {} bytes after the header",
                    layout.width, layout.height, layout.channels, layout.samples, reader.Rest().size()));
  }
  layout.data = reader.Rest();
  return layout;
}

}  // namespace

cv::Mat DecodePnm(std::string_view bytes, const std::filesystem::path& source) {
  PnmReader reader(bytes, source);
  const PnmLayout layout = ReadPnmLayout(reader, bytes);
  const long long maxval = layout.maxval;
  const int channels = layout.channels;
  const unsigned long long samples = layout.samples;
  cv::Mat image(static_cast<int>(layout.height), static_cast<int>(layout.width), channels == 1 ? CV_8UC1 : CV_8UC3);
  std::uint8_t* out = image.ptr<std::uint8_t>();  // freshly allocated, hence continuous
  const std::string_view data = layout.data;
  if (!layout.ascii && maxval == 255) {
    // Every byte is a sample within maxval and is kept as it is.
    std::memcpy(out, data.data(), samples);
    return image;
  }
  for (unsigned long long i = 0; i < samples; ++i) {
    long long value = 0;
    if (layout.ascii) {
      value = reader.Number("pixel data");
    } else {
      value = static_cast<unsigned char>(data[i]);
    }
    if (value > maxval) {
      reader.Fail(fmt::format("sample {} (pixel row {}, column {}) is {}, above maxval {}", i + 1,
                              i / channels / static_cast<unsigned long long>(layout.width),
                              i / channels % static_cast<unsigned long long>(layout.width), value, maxval));
    }
    // SDL_image stretches a smaller range to 0..255 with integer arithmetic.
    out[i] = static_cast<std::uint8_t>(maxval < 255 ? value * 255 / maxval : value);
  }
  return image;
}

std::optional<cv::Mat> BinaryGreyPnmView(std::string_view bytes, const std::filesystem::path& source) {
  if (bytes.size() < 2 || bytes[0] != 'P' || bytes[1] != '5') return std::nullopt;
  PnmReader reader(bytes, source);
  const PnmLayout layout = ReadPnmLayout(reader, bytes);
  if (layout.maxval != 255) return std::nullopt;
  return cv::Mat(static_cast<int>(layout.height), static_cast<int>(layout.width), CV_8UC1,
                 const_cast<char*>(layout.data.data()));
}

std::string EncodePgm(const cv::Mat& grey, std::string_view comment) {
  if (grey.type() != CV_8UC1) throw InputError("EncodePgm: expected an 8-bit single-channel image");
  std::string out = fmt::format("P5\n# {}\n{} {}\n255\n", comment, grey.cols, grey.rows);
  const std::size_t header = out.size();
  out.resize(header + static_cast<std::size_t>(grey.cols) * static_cast<std::size_t>(grey.rows));
  for (int row = 0; row < grey.rows; ++row) {
    const std::uint8_t* line = grey.ptr<std::uint8_t>(row);
    std::copy(line, line + grey.cols,
              out.begin() + static_cast<std::ptrdiff_t>(header + static_cast<std::size_t>(row) * grey.cols));
  }
  return out;
}

}  // namespace slamsweep::evaluator::inline formats::inline map
