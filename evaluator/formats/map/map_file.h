#pragma once

#include <filesystem>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/formats/map/image8.h"
#include "evaluator/formats/map/map_options.h"
#include "evaluator/formats/map/map_server_format.h"
#include "evaluator/formats/map/mrpt_gridmap_format.h"

namespace slamsweep::evaluator::inline formats::inline map {

/// The format ReadMap will use for `path`: options.format when given, else by name:
/// .yaml/.yml -> ROS map_server; .png with a sibling `<stem>_limits.txt` -> MRPT grid bitmap;
/// other .png and .pgm -> bare image. Any other extension is an InputError listing these.
MapFormat DetectMapFormat(const std::filesystem::path& path, const MapReadOptions& options = {});

/// Reads an occupancy map file in any supported format (DetectMapFormat):
/// - ROS map_server (ReadMapServer): map_server's own rules; unknown_value and default_resolution_m unused.
/// - MRPT bitmap (ReadMrptGridmap): unknown = options.unknown_value, or MRPT's 127.
/// - bare image (ReadBareImage): p = (255 - v) / 255, unknown only where v == options.unknown_value.
/// Every error is an InputError naming the file (and line or option). A map with no known cell is
/// returned as it is: whether it can be scored is for the metrics to say.
OccupancyGrid ReadMap(const std::filesystem::path& path, const MapReadOptions& options = {});

/// A PGM/PNG without metadata: p = (255 - v) / 255; cells equal to options.unknown_value are
/// unknown, and without it every cell is known (never guessed from a grey level). Resolution
/// options.default_resolution_m (0.05 m by default), origin (0, 0, 0). The image must be grey
/// (ReadGreyImageFile).
OccupancyGrid ReadBareImage(const std::filesystem::path& path, const MapReadOptions& options = {});

}  // namespace slamsweep::evaluator::inline formats::inline map
