#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <opencv2/core/mat.hpp>

namespace slamsweep::evaluator::inline formats::inline map {

/// The frames of a grey animated PNG (APNG), composed as a browser shows them: what
/// EncodeAnimatedGreyPng writes (stage animations), and any APNG of grey pixels: colour type 0
/// (grey) or 3 (a palette whose colours are all grey), 1, 2, 4 or 8 bits, not interlaced, every
/// filter, fully transparent or opaque pixels (tRNS), every dispose and blend operation. A PNG
/// without acTL is one frame. The canvas starts as 0 everywhere (transparent black); the frames are
/// decoded one at a time, so a long animation of large maps is never held whole.
class AnimatedGreyPngReader {
 public:
  /// Reads the chunks (checking their CRCs) and the frame layout; pixels are decoded by ForEachFrame.
  /// Throws InputError starting with `source` (the file name, for messages) for anything else.
  AnimatedGreyPngReader(std::string bytes, std::string source);

  cv::Size Size() const { return size_; }
  std::size_t FrameCount() const { return frames_.size(); }
  /// Each frame's delay, in 1/100 s (rounded from the fcTL's fraction; 0 for a still PNG).
  std::vector<int> DelaysCs() const;

  /// Calls visit(index, canvas) for every frame in order with the canvas (CV_8UC1) as shown while
  /// that frame is displayed. Throws InputError naming the file for undecodable pixel data.
  void ForEachFrame(const std::function<void(std::size_t, const cv::Mat&)>& visit) const;

 private:
  struct Frame {
    cv::Rect rect;
    int delay_cs = 0;
    std::uint8_t dispose = 0;
    std::uint8_t blend = 0;
    std::vector<std::string_view> data;  ///< pieces of its zlib stream, in order
  };

  cv::Mat DecodeFrame(const Frame& frame, cv::Mat& opaque) const;

  std::string bytes_;
  std::string source_;
  cv::Size size_;
  int bit_depth_ = 8;
  int colour_type_ = 0;
  /// Grey value and opacity of every sample value (palette index or grey sample).
  std::vector<std::uint8_t> grey_of_;
  std::vector<bool> opaque_of_;
  /// Sample values that name a colour (palette entries; every value of a grey image).
  std::size_t palette_entries_ = 0;
  std::vector<Frame> frames_;
};

/// The reader of the file at `path`; InputError naming it when it cannot be read.
AnimatedGreyPngReader OpenAnimatedGreyPng(const std::filesystem::path& path);

/// Every frame of a grey APNG at once (AnimatedGreyPngReader), for small animations and tests.
std::vector<cv::Mat> DecodeAnimatedGreyPng(std::string bytes, std::string source);

}  // namespace slamsweep::evaluator::inline formats::inline map
