#pragma once

#include <optional>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

namespace slamsweep::evaluator::inline formats::inline map {

/// An 8-bit grey image as a small PNG: grey colour type, filter None, deflate level 6 (libdeflate). For a
/// map_saver trinary map it is the map_server image that stores the map in the fewest bytes (map_server
/// reads grey PNGs as it reads PGMs; a palette PNG it would read as indices). Throws InputError for
/// another image type.
std::string EncodeCompactGreyPng(const cv::Mat& grey);

/// An 8-bit BGR image (as OpenCV reads a PNG) of at most 256 colours as a palette PNG (colours in order of
/// first appearance, the smallest bit depth that holds them, filter None, deflate level 6): the same pixels in
/// a third to a half of the bytes of a drawn figure's RGB PNG. nullopt when the image has more colours.
/// Throws InputError for another image type.
std::optional<std::string> EncodePalettePng(const cv::Mat& bgr);

/// The rectangle of pixels that differ between two 8-bit grey images of one size; empty when none do.
cv::Rect ChangedRect(const cv::Mat& before, const cv::Mat& after);

/// Frame timing of EncodeAnimatedGreyPng, in 1/100 s (the GIF unit, as the report's animations use).
struct AnimatedPngTiming {
  int frame_delay_cs = 15;
  int last_frame_delay_cs = 150;
};

/// Grey images of one size (stage maps: 0, 205, 254) as one animated PNG (APNG: what browsers play; viewers
/// without APNG support show the first frame). Palette of the grey levels in ascending order, at the smallest
/// bit depth that holds them, and one transparent entry after them. The first frame is whole; every later one
/// is the rectangle of pixels that changed since the frame before (one pixel when none did), blended over what
/// is under it with its unchanged pixels transparent, so an unchanged part of the map is not stored again
/// (with all 256 levels in use, the rectangle replaces what is under it). Decoded, frame i is exactly
/// frames[i]. Loops forever.
/// Throws InputError for an empty list or frames of other types or sizes.
std::string EncodeAnimatedGreyPng(const std::vector<cv::Mat>& frames, const AnimatedPngTiming& timing = {});

}  // namespace slamsweep::evaluator::inline formats::inline map
