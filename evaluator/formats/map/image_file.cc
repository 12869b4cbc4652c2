#include "evaluator/formats/map/image_file.h"

#include <fmt/format.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/pnm_image.h"

namespace slamsweep::evaluator {
namespace {

std::string ReadBytes(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw InputError(Located(path, 0, "no such image file (expected a readable PGM or PNG file)"));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(Located(path, 0, "cannot open image file for reading"));
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

constexpr std::string_view kPngSignature = "\x89PNG\r\n\x1a\n";
// The IEND chunk every PNG ends with: length 0, type, CRC.
constexpr std::string_view kPngEnd = std::string_view("\0\0\0\0IEND\xae\x42\x60\x82", 12);

cv::Mat DecodeWithOpenCv(const std::string& bytes, const std::filesystem::path& path) {
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw InputError(Located(path, 0, "image file larger than 2 GiB"));
  }
  // Caught here, a cut PNG gets a clear message (libpng would only print to stderr).
  if (bytes.starts_with(kPngSignature) && !bytes.ends_with(kPngEnd)) {
    throw InputError(Located(path, 0, "truncated PNG (the file does not end with the IEND chunk)"));
  }
  cv::Mat decoded;
  try {
    const cv::Mat buffer(1, static_cast<int>(bytes.size()), CV_8UC1, const_cast<char*>(bytes.data()));
    // UNCHANGED keeps the alpha channel and the bit depth, and ignores EXIF rotation.
    decoded = cv::imdecode(buffer, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& exception) {
    throw InputError(Located(path, 0, fmt::format("corrupt image ({})", exception.what())));
  }
  if (decoded.empty()) {
    throw InputError(Located(path, 0, "not a readable image, or a truncated/corrupt one (expected a PGM or PNG map)"));
  }
  if (decoded.depth() != CV_8U) {
    throw InputError(Located(
        path, 0, fmt::format("{}-bit samples; expected an 8-bit image, as map_server reads", decoded.elemSize1() * 8)));
  }
  // OpenCV stores B, G, R(, A); map_server's channel rules are written for SDL's R, G, B(, A).
  const int channels = decoded.channels();
  if (channels == 1) return decoded;
  if (channels < 1 || channels > 4) {
    throw InputError(Located(path, 0, fmt::format("{} channels; expected grey, RGB or RGBA", channels)));
  }
  std::vector<int> from_to;
  if (channels == 2) {
    // Grey + alpha: SDL_image hands map_server R = G = B = grey, then alpha.
    from_to = {0, 0, 0, 1, 0, 2, 1, 3};
  } else if (channels == 3) {
    from_to = {0, 2, 1, 1, 2, 0};
  } else {
    from_to = {0, 2, 1, 1, 2, 0, 3, 3};
  }
  cv::Mat rgb(decoded.rows, decoded.cols, CV_8UC(channels == 2 ? 4 : channels));
  cv::mixChannels(&decoded, 1, &rgb, 1, from_to.data(), from_to.size() / 2);
  return rgb;
}

}  // namespace

cv::Mat ReadImageFile(const std::filesystem::path& path) {
  const std::string bytes = ReadBytes(path);
  if (bytes.empty()) throw InputError(Located(path, 0, "empty file; expected a PGM or PNG image"));
  if (LooksLikePnm(bytes)) return DecodePnm(bytes, path);
  return DecodeWithOpenCv(bytes, path);
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

std::string EncodePng(const cv::Mat& image) {
  std::vector<unsigned char> buffer;
  if (!cv::imencode(".png", image, buffer)) throw InputError("PNG encoding failed");
  return std::string(buffer.begin(), buffer.end());
}

}  // namespace slamsweep::evaluator
