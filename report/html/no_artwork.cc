// MakeStandardArtwork for a build without report/plots and report/images: no images at all.
#include "report/html/standard_artwork.h"

namespace slamsweep::report {

std::unique_ptr<Artwork> MakeStandardArtwork() { return nullptr; }

bool StandardArtworkDrawsImages() { return false; }

}  // namespace slamsweep::report
