#pragma once

#include <filesystem>
#include <opencv2/core/mat.hpp>
#include <string>
#include <string_view>

namespace slamsweep::evaluator {

/// True when `bytes` starts with the PNG signature.
bool LooksLikePng(std::string_view bytes);

/// Decodes a PNG with libpng into 8-bit samples in SDL_image's channel order, the pixels OpenCV's
/// imdecode(IMREAD_UNCHANGED) gives (in its B, G, R order) for the same file:
///  - grey (1, 2, 4 or 8 bits; a tRNS colour is ignored): CV_8UC1, low depths scaled to 0..255;
///  - RGB, or a palette, without tRNS: CV_8UC3 R, G, B;
///  - RGB or palette with tRNS, RGBA, grey + alpha: CV_8UC4 R, G, B, A (grey + alpha as R = G = B).
/// Throws InputError naming `source` for 16-bit samples and for data libpng refuses (its reason is
/// in the message).
cv::Mat DecodePng(std::string_view bytes, const std::filesystem::path& source);

/// The PNG of an 8-bit image (grey; or B, G, R(, A) in OpenCV's order), byte for byte what OpenCV's
/// imencode(".png") writes with its default parameters: the Sub filter, zlib level 1 and the
/// run-length strategy, no interlacing. Throws InputError for other depths or channel counts.
std::string EncodePngBytes(const cv::Mat& image);

}  // namespace slamsweep::evaluator
