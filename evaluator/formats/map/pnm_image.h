#pragma once

#include <filesystem>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace slamsweep::evaluator::inline formats::inline map {

/// True when `bytes` starts with a Netpbm magic number "P1" ... "P7" (DecodePnm accepts P2, P3, P5, P6
/// and rejects the others with a clear message).
bool LooksLikePnm(std::string_view bytes);

/// Decodes a PGM (P2 ASCII / P5 binary) to CV_8UC1 or a PPM (P3 / P6) to CV_8UC3 in R, G, B
/// order. Follows SDL_image, which map_server uses: `#` comments in the header, maxval 1..255,
/// samples scaled by 255 / maxval (integer division) when maxval < 255. Rejects with an
/// InputError naming `source`: 16-bit files (maxval > 255), bitmaps (P1/P4, whose bits
/// map_server would misread as near-black grey levels), samples above maxval, a bad header and
/// pixel data shorter than width x height says (a truncated file).
cv::Mat DecodePnm(std::string_view bytes, const std::filesystem::path& source);

/// For a binary PGM (P5) with maxval 255, whose bytes are its pixels: DecodePnm's image as a
/// CV_8UC1 header over `bytes` (valid while they are), without a copy; nothing for other files.
/// Throws as DecodePnm does for a bad header or truncated data.
std::optional<cv::Mat> BinaryGreyPnmView(std::string_view bytes, const std::filesystem::path& source);

/// A binary PGM (P5) of a CV_8UC1 image with one `# comment` line in the header, the
/// layout map_saver writes.
std::string EncodePgm(const cv::Mat& grey, std::string_view comment);

}  // namespace slamsweep::evaluator::inline formats::inline map
