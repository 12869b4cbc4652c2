#pragma once

#include <filesystem>

namespace slamsweep::report::inline html {

/// The run's map borders as GeoJSON (`slamsweep vectorize`'s default options, world metres), traced from the
/// run folder's map (map.yaml) and written to `out`: the report derives the download instead of every run
/// folder storing it. Throws evaluator::InputError when the map cannot be read or the file written.
void WriteVectorMapDownload(const std::filesystem::path& map_yaml, const std::filesystem::path& out);

}  // namespace slamsweep::report::inline html
