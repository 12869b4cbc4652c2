#pragma once

// Small builders for map-format tests: files are written byte by byte here, independently of
// the encoders under test.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::evaluator::map_test {

/// A binary PGM (P5) with a minimal header.
inline std::string Pgm(int width, int height, const std::vector<std::uint8_t>& values) {
  std::string out = "P5\n" + std::to_string(width) + " " + std::to_string(height) + "\n255\n";
  out.append(values.begin(), values.end());
  return out;
}

inline std::string ReadAll(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Writes an image with OpenCV (channels in OpenCV's B, G, R, A order).
inline void WriteImage(const std::filesystem::path& path, const cv::Mat& image) {
  ASSERT_TRUE(cv::imwrite(path.string(), image)) << path;
}

/// A 1-row RGBA image given as R, G, B, A per pixel, converted to OpenCV's order for writing.
inline cv::Mat RgbaRow(std::initializer_list<cv::Vec4b> rgba_pixels) {
  cv::Mat image(1, static_cast<int>(rgba_pixels.size()), CV_8UC4);
  int col = 0;
  for (const cv::Vec4b& p : rgba_pixels) image.at<cv::Vec4b>(0, col++) = cv::Vec4b(p[2], p[1], p[0], p[3]);
  return image;
}

/// A 1-row RGB image given as R, G, B per pixel.
inline cv::Mat RgbRow(std::initializer_list<cv::Vec3b> rgb_pixels) {
  cv::Mat image(1, static_cast<int>(rgb_pixels.size()), CV_8UC3);
  int col = 0;
  for (const cv::Vec3b& p : rgb_pixels) image.at<cv::Vec3b>(0, col++) = cv::Vec3b(p[2], p[1], p[0]);
  return image;
}

/// The message of the InputError `action` throws; fails the test when it throws nothing.
template <typename Action>
std::string InputErrorOf(Action&& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return {};
}

inline std::vector<float> Cells(const OccupancyGrid& grid) { return grid.cells; }

}  // namespace slamsweep::evaluator::map_test
