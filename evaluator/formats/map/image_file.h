#pragma once

#include <filesystem>
#include <functional>
#include <opencv2/core/mat.hpp>
#include <string>
#include <string_view>

namespace slamsweep::evaluator::inline formats::inline map {

/// An image file as map_server's loader (SDL_image) sees it: 8-bit samples, 1 channel (grey),
/// 3 (R, G, B) or 4 (R, G, B, A) in that order. Grey + alpha images are widened to R = G = B
/// plus alpha, as SDL_image does. PGM/PPM are decoded by DecodePnm, PNG by DecodePng (libpng; a
/// palette PNG gives its colours). Throws InputError naming the file when it is missing, empty,
/// not a PGM/PPM or PNG (naming BMP, JPEG, TIFF and GIF files as such), truncated or corrupt, or
/// holds 16-bit samples.
cv::Mat ReadImageFile(const std::filesystem::path& path);

/// Calls use(image) with the image ReadImageFile returns; a binary PGM with maxval 255 is handed
/// over where the file is mapped, without decoding it into a copy. Errors as ReadImageFile.
void WithImageFile(const std::filesystem::path& path, const std::function<void(const cv::Mat&)>& use);

/// ReadImageFile for formats whose pixels are grey levels (MRPT bitmaps, bare maps): CV_8UC1.
/// An RGB or RGBA file is accepted when every pixel has R = G = B and is opaque (a grey map
/// saved in colour); any other colour is an InputError naming the file and the first such pixel.
cv::Mat ReadGreyImageFile(const std::filesystem::path& path);

/// Writes `bytes` to `path` (replacing it); InputError naming the file on failure.
void WriteBinaryFile(const std::filesystem::path& path, std::string_view bytes);

/// PNG encoding of an 8-bit image (grey, or B, G, R, A in OpenCV's order): EncodePngBytes.
std::string EncodePng(const cv::Mat& image);

}  // namespace slamsweep::evaluator::inline formats::inline map
