#include "report/plots/png_repack.h"

#include <fstream>
#include <optional>
#include <string>
#include <system_error>

#include <opencv2/core.hpp>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/compact_png.h"
#include "evaluator/formats/map/image_file.h"

namespace slamsweep::report::inline plots {

void RepackAsPalettePng(const std::filesystem::path& png) {
  // libpng through the evaluator's reader, not OpenCV's imgcodecs: imgcodecs would load GDAL and
  // dozens of other libraries into every process that links the report (the sweep's workers too).
  cv::Mat rgb;
  try {
    rgb = evaluator::ReadImageFile(png);
  } catch (const evaluator::InputError&) {
    return;
  }
  if (rgb.type() != CV_8UC3 || rgb.empty()) return;
  cv::Mat bgr(rgb.size(), rgb.type());
  constexpr int kRgbToBgr[] = {0, 2, 1, 1, 2, 0};
  cv::mixChannels(&rgb, 1, &bgr, 1, kRgbToBgr, 3);
  const std::optional<std::string> palette = evaluator::EncodePalettePng(bgr);
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

}  // namespace slamsweep::report::inline plots
