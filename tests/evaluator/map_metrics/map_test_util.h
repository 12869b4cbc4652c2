#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::evaluator::testing {

/// A grid drawn in text, one string per row (row 0 = top): '#' occupied (p = 1), '.' free
/// (p = 0), '?' unknown, a digit d a cell with p = d / 10.
inline OccupancyGrid GridFromText(const std::vector<std::string>& rows) {
  OccupancyGrid grid(static_cast<int>(rows.front().size()), static_cast<int>(rows.size()), 0.05);
  for (int r = 0; r < grid.height; ++r) {
    if (static_cast<int>(rows[r].size()) != grid.width) throw std::invalid_argument("ragged grid text");
    for (int c = 0; c < grid.width; ++c) {
      const char ch = rows[r][c];
      float p = OccupancyGrid::kUnknown;
      if (ch == '#') p = 1.0f;
      if (ch == '.') p = 0.0f;
      if (ch >= '0' && ch <= '9') p = static_cast<float>(ch - '0') / 10.0f;
      grid.at(r, c) = p;
    }
  }
  return grid;
}

/// A reference PGM as the reference README defines it: 205 is unknown, any other value v has
/// p = (255 - v) / 255. Read with OpenCV so as not to depend on the map file readers.
inline OccupancyGrid LoadReferencePgm(const std::filesystem::path& path) {
  const cv::Mat image = cv::imread(path.string(), cv::IMREAD_UNCHANGED);
  if (image.empty() || image.type() != CV_8UC1) throw std::runtime_error("cannot read 8-bit PGM " + path.string());
  OccupancyGrid grid(image.cols, image.rows, 0.05);
  for (int r = 0; r < image.rows; ++r) {
    for (int c = 0; c < image.cols; ++c) {
      const int v = image.at<std::uint8_t>(r, c);
      grid.at(r, c) = v == 205 ? OccupancyGrid::kUnknown : static_cast<float>((255 - v) / 255.0);
    }
  }
  return grid;
}

/// The entry for `map_name` in reference/maps/expected_paper_metrics.json.
inline nlohmann::json ExpectedPaperMetrics(const std::filesystem::path& json_path, const std::string& map_name) {
  std::ifstream in(json_path);
  const nlohmann::json all = nlohmann::json::parse(in);
  for (const nlohmann::json& entry : all.at("maps")) {
    if (entry.at("map") == map_name) return entry;
  }
  throw std::runtime_error("no entry for " + map_name + " in " + json_path.string());
}

/// The reference maps of the shared folder, relative to it.
inline const std::vector<std::string>& ReferenceMapNames() {
  static const std::vector<std::string> names = {"fastslam_thirdparty.pgm", "telecom_icp.pgm", "telecom_rbpf.pgm"};
  return names;
}

}  // namespace slamsweep::evaluator::testing
