#pragma once

#include <memory>

#include "report/html/artwork.h"

namespace slamsweep::report::inline html {

/// The report's real images: gnuplot plots (report/plots) and giflib GIFs, thumbnails and
/// overlays (report/images). In a build without those libraries it draws nothing and every page
/// says the image is not available.
std::unique_ptr<Artwork> MakeStandardArtwork();

/// False in a build without the plot and image libraries.
bool StandardArtworkDrawsImages();

}  // namespace slamsweep::report::inline html
