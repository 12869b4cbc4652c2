#pragma once

namespace slamsweep::report::inline images {

/// The grey of unknown cells in every map image the report draws (map_server's convention).
inline constexpr int kUnknownGrey = 205;

}  // namespace slamsweep::report::inline images
