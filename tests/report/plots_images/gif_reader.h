#pragma once

#include <filesystem>
#include <opencv2/core/mat.hpp>
#include <vector>

namespace slamsweep::report::gif_check {

/// A GIF read back with giflib's decoder (DGifOpen + DGifSlurp), independent of the writer.
struct DecodedGif {
  int width = 0;
  int height = 0;
  bool loops_forever = false;
  /// Frame delays (1/100 s) from the graphics control blocks.
  std::vector<int> delays_cs;
  /// The full canvas after each frame is drawn (every palette colour grey, checked).
  std::vector<cv::Mat> canvases;
};

/// Fails the current test (ADD_FAILURE) and returns what it could when the file does not decode.
DecodedGif DecodeGif(const std::filesystem::path& path);

}  // namespace slamsweep::report::gif_check
