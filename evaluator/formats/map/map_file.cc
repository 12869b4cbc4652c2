#include "evaluator/formats/map/map_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/image_file.h"

namespace slamsweep::evaluator::inline formats::inline map {
namespace {

std::string LowerExtension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

void CheckOptions(const MapReadOptions& options) {
  if (options.unknown_value && (*options.unknown_value < 0 || *options.unknown_value > 255)) {
    throw InputError(fmt::format("option unknown_value: expected a grey level 0..255, got {}", *options.unknown_value));
  }
  if (!std::isfinite(options.default_resolution_m) || options.default_resolution_m <= 0.0) {
    throw InputError(fmt::format("option default_resolution_m: expected a positive number of metres per cell, got {}",
                                 options.default_resolution_m));
  }
}

}  // namespace

MapFormat DetectMapFormat(const std::filesystem::path& path, const MapReadOptions& options) {
  if (options.format != MapFormat::kAuto) return options.format;
  const std::string extension = LowerExtension(path);
  if (extension == ".yaml" || extension == ".yml") return MapFormat::kRosMapServer;
  if (extension == ".png") {
    std::error_code error;
    return std::filesystem::is_regular_file(MrptLimitsPath(path), error) ? MapFormat::kMrptGridmap
                                                                         : MapFormat::kBareImage;
  }
  if (extension == ".pgm") return MapFormat::kBareImage;
  throw InputError(Located(path, 0,
                           "unknown map format; expected .yaml/.yml (ROS map_server), .png with <stem>_limits.txt "
                           "(MRPT) or a bare .pgm/.png image"));
}

OccupancyGrid ReadMap(const std::filesystem::path& path, const MapReadOptions& options) {
  CheckOptions(options);
  switch (DetectMapFormat(path, options)) {
    case MapFormat::kRosMapServer:
      return ReadMapServer(path);
    case MapFormat::kMrptGridmap:
      return ReadMrptGridmap(path, options.unknown_value.value_or(kMrptUnknownValue));
    case MapFormat::kAuto:  // DetectMapFormat never returns it
    case MapFormat::kBareImage:
      break;
  }
  return ReadBareImage(path, options);
}

OccupancyGrid ReadBareImage(const std::filesystem::path& path, const MapReadOptions& options) {
  CheckOptions(options);
  return FromImage8(ReadGreyImageFile(path), options.unknown_value, options.default_resolution_m);
}

}  // namespace slamsweep::evaluator::inline formats::inline map
