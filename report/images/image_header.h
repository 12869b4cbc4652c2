#pragma once

#include <filesystem>
#include <opencv2/core/types.hpp>
#include <optional>

namespace slamsweep::report::inline images {

/// The pixel size of a PNG (from its IHDR chunk) or a binary/ASCII PGM/PPM/PBM (from its header)
/// without decoding the pixels, or nullopt when the file is not one of those or its header cannot
/// be read (callers then decode the image, which reports the problem properly).
/// Lets a long list of large stage maps be sized before any is held in memory.
std::optional<cv::Size> PeekImageSize(const std::filesystem::path& path);

}  // namespace slamsweep::report::inline images
