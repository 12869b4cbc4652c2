#pragma once

#include <filesystem>

namespace slamsweep::report::inline images {

/// Writes a gallery thumbnail of a map image (PGM/PNG, e.g. map_saver's map.pgm) as a grey PNG:
/// cropped to the cells that are not map_saver's unknown grey 205 (with a margin of 4 % of the
/// map, at least 2 pixels), because saved maps are mostly unknown border; then shrunk (area
/// interpolation) so its longer side is at most max_side_px, never enlarged. A map with no such
/// cell is kept whole. Colour images are turned grey.
/// Throws evaluator::InputError naming the file for an unreadable map or an unwritable PNG, and
/// naming max_side_px when it is below 1.
void WriteThumbnail(const std::filesystem::path& map_image, const std::filesystem::path& png, int max_side_px);

}  // namespace slamsweep::report::inline images
