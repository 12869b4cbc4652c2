#include "evaluator/formats/map/image_file.h"

#include <fmt/format.h>

#include <cstdint>
#include <fstream>
#include <opencv2/core.hpp>
#include <optional>

#include "evaluator/core/input_error.h"
#include "evaluator/core/mapped_file.h"
#include "evaluator/formats/map/png_image.h"
#include "evaluator/formats/map/pnm_image.h"

namespace slamsweep::evaluator::inline formats::inline map {
namespace {

MappedFile ReadBytes(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw InputError(Located(path, 0, "no such image file (expected a readable PGM or PNG file)"));
  }
  std::optional<MappedFile> file = MappedFile::Open(path);
  if (!file) throw InputError(Located(path, 0, "cannot open image file for reading"));
  return std::move(*file);
}

// The IEND chunk every PNG ends with: length 0, type, CRC.
constexpr std::string_view kPngEnd = std::string_view("\0\0\0\0IEND\xae\x42\x60\x82", 12);

/// What a file that is neither PNM nor PNG is, when its magic bytes tell.
std::string_view OtherImageKind(std::string_view bytes) {
  if (bytes.starts_with("BM")) return "a BMP image";
  if (bytes.starts_with("\xff\xd8\xff")) return "a JPEG image";
  if (bytes.starts_with("II*") || bytes.starts_with(std::string_view("MM\0*", 4))) return "a TIFF image";
  if (bytes.starts_with("GIF8")) return "a GIF image";
  return {};
}

cv::Mat DecodeImage(std::string_view bytes, const std::filesystem::path& path) {
  if (bytes.empty()) throw InputError(Located(path, 0, "empty file; expected a PGM or PNG image"));
  if (LooksLikePnm(bytes)) return DecodePnm(bytes, path);
  if (LooksLikePng(bytes)) {
    // Caught here, a cut PNG gets a clear message before libpng reports a missing chunk.
    if (!bytes.ends_with(kPngEnd)) {
      throw InputError(Located(path, 0, "truncated PNG (the file does not end with the IEND chunk)"));
    }
    return DecodePng(bytes, path);
  }
  if (const std::string_view kind = OtherImageKind(bytes); !kind.empty()) {
    throw InputError(Located(path, 0, fmt::format("{}; slamsweep reads PGM and PNG maps (convert it to PNG)", kind)));
  }
  throw InputError(Located(path, 0, "not a readable image, or a truncated/corrupt one (expected a PGM or PNG map)"));
}

}  // namespace

cv::Mat ReadImageFile(const std::filesystem::path& path) {
  const MappedFile file = ReadBytes(path);
  return DecodeImage(file.bytes(), path);
}

void WithImageFile(const std::filesystem::path& path, const std::function<void(const cv::Mat&)>& use) {
  const MappedFile file = ReadBytes(path);
  if (const std::optional<cv::Mat> view = BinaryGreyPnmView(file.bytes(), path)) {
    use(*view);
    return;
  }
  use(DecodeImage(file.bytes(), path));
}

cv::Mat ReadGreyImageFile(const std::filesystem::path& path) {
  const cv::Mat image = ReadImageFile(path);
  const int channels = image.channels();
  if (channels == 1) return image;
  cv::Mat grey(image.rows, image.cols, CV_8UC1);
  for (int row = 0; row < image.rows; ++row) {
    const std::uint8_t* pixel = image.ptr<std::uint8_t>(row);
    std::uint8_t* out = grey.ptr<std::uint8_t>(row);
    for (int col = 0; col < image.cols; ++col, pixel += channels) {
      const bool opaque = channels != 4 || pixel[3] == 255;
      if (pixel[0] != pixel[1] || pixel[0] != pixel[2] || !opaque) {
        throw InputError(Located(
            path, 0,
            fmt::format("colour image: pixel (row {}, column {}) is not an opaque grey; expected an 8-bit grey map",
                        row, col)));
      }
      out[col] = pixel[0];
    }
  }
  return grey;
}

void WriteBinaryFile(const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(Located(path, 0, "cannot open for writing"));
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) throw InputError(Located(path, 0, "write failed"));
}

std::string EncodePng(const cv::Mat& image) { return EncodePngBytes(image); }

}  // namespace slamsweep::evaluator::inline formats::inline map
