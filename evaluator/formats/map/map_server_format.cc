#include "evaluator/formats/map/map_server_format.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <utility>

#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "evaluator/formats/map/compact_png.h"
#include "evaluator/formats/map/image8.h"
#include "evaluator/formats/map/image_file.h"
#include "evaluator/formats/map/map_server_pixels.h"
#include "evaluator/formats/map/map_server_yaml.h"
#include "evaluator/formats/map/pnm_image.h"

namespace slamsweep::evaluator::inline formats::inline map {
namespace {

// map_saver's fixed values: the YAML thresholds it writes and the grey levels of a trinary PGM.
constexpr std::string_view kSavedThresholds = "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
constexpr std::uint8_t kTrinaryOccupied = 0;
constexpr std::uint8_t kTrinaryFree = 254;
constexpr std::uint8_t kTrinaryUnknown = 205;

void CheckOptions(const MapWriteOptions& options) {
  if (options.occupied_threshold_percent < 1 || options.occupied_threshold_percent > 100) {
    throw InputError(fmt::format("option occupied_threshold_percent: expected 1..100 (as map_saver --occ), got {}",
                                 options.occupied_threshold_percent));
  }
  if (options.free_threshold_percent < 0 || options.free_threshold_percent > 100) {
    throw InputError(fmt::format("option free_threshold_percent: expected 0..100 (as map_saver --free), got {}",
                                 options.free_threshold_percent));
  }
  if (options.free_threshold_percent >= options.occupied_threshold_percent) {
    throw InputError(
        fmt::format("option free_threshold_percent: expected below occupied_threshold_percent ({}), got {}",
                    options.occupied_threshold_percent, options.free_threshold_percent));
  }
}

void CheckGeometry(const OccupancyGrid& grid, const std::filesystem::path& yaml_path) {
  if (!std::isfinite(grid.resolution_m) || grid.resolution_m <= 0.0) {
    throw InputError(Located(
        yaml_path, 0, fmt::format("cannot write a grid of resolution {} m/cell; expected > 0", grid.resolution_m)));
  }
  if (!std::isfinite(grid.origin.x_m) || !std::isfinite(grid.origin.y_m) || !std::isfinite(grid.origin.yaw_rad)) {
    throw InputError(Located(yaml_path, 0, "cannot write a grid whose origin is not finite"));
  }
}

cv::Mat TrinaryImage(const OccupancyGrid& grid, const MapWriteOptions& options) {
  RequireValidGrid(grid);
  cv::Mat image(grid.height, grid.width, CV_8UC1);
  for (int row = 0; row < grid.height; ++row) {
    std::uint8_t* out = image.ptr<std::uint8_t>(row);
    for (int col = 0; col < grid.width; ++col) {
      const float p = grid.at(row, col);
      if (OccupancyGrid::IsUnknown(p)) {
        out[col] = kTrinaryUnknown;
        continue;
      }
      // The int8 value a ROS OccupancyGrid would hold for this cell, then map_saver's tests.
      const long value = std::lround(100.0 * static_cast<double>(p));
      if (value >= 0 && value <= options.free_threshold_percent) {
        out[col] = kTrinaryFree;
      } else if (value >= options.occupied_threshold_percent) {
        out[col] = kTrinaryOccupied;
      } else {
        out[col] = kTrinaryUnknown;
      }
    }
  }
  return image;
}

/// B, G, R, A (OpenCV's order for imencode): grey kept, alpha 0 marks unknown.
cv::Mat ScaleImage(const OccupancyGrid& grid) {
  const cv::Mat grey = ToImage8(grid, kTrinaryUnknown);
  cv::Mat image(grid.height, grid.width, CV_8UC4);
  for (int row = 0; row < grid.height; ++row) {
    const std::uint8_t* in = grey.ptr<std::uint8_t>(row);
    cv::Vec4b* out = image.ptr<cv::Vec4b>(row);
    for (int col = 0; col < grid.width; ++col) {
      const std::uint8_t alpha = OccupancyGrid::IsUnknown(grid.at(row, col)) ? 0 : 255;
      out[col] = cv::Vec4b(in[col], in[col], in[col], alpha);
    }
  }
  return image;
}

std::string YamlScalar(const std::string& text) {
  YAML::Emitter emitter;
  emitter << text;  // quotes the name only when YAML needs it
  return emitter.c_str();
}

}  // namespace

OccupancyGrid ReadMapServer(const std::filesystem::path& yaml_path) {
  const MapServerMetadata metadata = ParseMapServerYaml(ReadTextFile(yaml_path), yaml_path);
  std::error_code error;
  if (!std::filesystem::is_regular_file(metadata.image, error)) {
    throw InputError(Located(yaml_path, metadata.image_line,
                             fmt::format("field 'image': image file '{}' not found", metadata.image.string())));
  }
  OccupancyGrid grid;
  WithImageFile(metadata.image, [&](const cv::Mat& image) { grid = MapServerGridFromImage(image, metadata); });
  return grid;
}

namespace {

/// Writes the files of WriteMapServer; returns the trinary image it wrote (empty in scale mode) and the YAML.
std::pair<cv::Mat, std::string> WriteMapServerFiles(const OccupancyGrid& grid, const std::filesystem::path& yaml_path,
                                                    const MapWriteOptions& options) {
  CheckOptions(options);
  CheckGeometry(grid, yaml_path);
  if (!yaml_path.has_filename()) throw InputError(Located(yaml_path, 0, "expected a YAML file name, got a folder"));
  const bool scale = options.mode == MapWriteOptions::Mode::kScale;
  const std::string image_name = yaml_path.stem().string() + (scale || options.trinary_png ? ".png" : ".pgm");
  const std::filesystem::path image_path = yaml_path.parent_path() / image_name;

  // The image first, so that a YAML never names an image that is not there.
  cv::Mat trinary;
  if (scale) {
    WriteBinaryFile(image_path, EncodePng(ScaleImage(grid)));
  } else if (options.trinary_png) {
    trinary = TrinaryImage(grid, options);
    WriteBinaryFile(image_path, EncodeCompactGreyPng(trinary));
  } else {
    trinary = TrinaryImage(grid, options);
    WriteBinaryFile(image_path, EncodePgm(trinary, fmt::format("CREATOR: slamsweep (map_saver layout) {:.3f} m/pix",
                                                               grid.resolution_m)));
  }

  // "{}" prints the shortest text that reads back as the same double.
  std::string yaml =
      fmt::format("image: {}\nresolution: {}\norigin: [{}, {}, {}]\n{}", YamlScalar(image_name), grid.resolution_m,
                  grid.origin.x_m, grid.origin.y_m, grid.origin.yaw_rad, kSavedThresholds);
  if (scale) {
    yaml += "mode: scale\n";
    yaml += "# unknown cells: alpha 0 (grey 205); known cells: grey = round(255 * (1 - p)), alpha 255\n";
  } else {
    yaml += "\n";
  }
  WriteBinaryFile(yaml_path, yaml);
  return {trinary, yaml};
}

}  // namespace

void WriteMapServer(const OccupancyGrid& grid, const std::filesystem::path& yaml_path, const MapWriteOptions& options) {
  WriteMapServerFiles(grid, yaml_path, options);
}

OccupancyGrid WriteMapServerAndReadBack(const OccupancyGrid& grid, const std::filesystem::path& yaml_path,
                                        const MapWriteOptions& options) {
  const auto [trinary, yaml] = WriteMapServerFiles(grid, yaml_path, options);
  if (trinary.empty()) return ReadMapServer(yaml_path);
  // A PGM or PNG holds the image's bytes exactly: decoding the file would give this image back.
  return MapServerGridFromImage(trinary, ParseMapServerYaml(yaml, yaml_path));
}

}  // namespace slamsweep::evaluator::inline formats::inline map
