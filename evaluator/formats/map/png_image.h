#pragma once

#include <filesystem>
#include <opencv2/core/mat.hpp>
#include <string>
#include <string_view>

namespace slamsweep::evaluator::inline formats::inline map {

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

/// A CV_8UC1 image of few grey levels as a palette PNG: the levels in ascending order as the
/// palette's grey colours, at the smallest bit depth that holds them (1, 2, 4 or 8 bits), filter
/// None, zlib level 1, run-length strategy. It decodes (DecodePng, ReadGreyImageFile) to the same
/// grey values as EncodePngBytes' 8-bit grey PNG, from a quarter of the bytes for a trinary map,
/// which is what makes it quick to write. Not for map_server images: map_server reads the palette
/// indices of a palette image, not its colours. Throws InputError for another image type.
std::string EncodeGreyPalettePng(const cv::Mat& grey);

}  // namespace slamsweep::evaluator::inline formats::inline map
