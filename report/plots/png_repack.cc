#include "report/plots/png_repack.h"

#include <fstream>
#include <optional>
#include <string>
#include <system_error>

#include <opencv2/imgcodecs.hpp>

#include "evaluator/formats/map/compact_png.h"

namespace slamsweep::report {

void RepackAsPalettePng(const std::filesystem::path& png) {
  const cv::Mat image = cv::imread(png.string(), cv::IMREAD_UNCHANGED);
  if (image.type() != CV_8UC3 || image.empty()) return;
  const std::optional<std::string> palette = evaluator::EncodePalettePng(image);
  std::error_code error;
  const auto size = std::filesystem::file_size(png, error);
  if (!palette || error || palette->size() >= size) return;
  // Written beside it and renamed over it: a reader never sees half a file.
  std::filesystem::path temporary = png;
  temporary += ".repack";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(palette->data(), static_cast<std::streamsize>(palette->size()));
    if (!out.flush()) {
      std::filesystem::remove(temporary, error);
      return;
    }
  }
  std::filesystem::rename(temporary, png, error);
  if (error) std::filesystem::remove(temporary, error);
}

}  // namespace slamsweep::report
