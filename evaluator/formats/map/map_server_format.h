#pragma once

#include <filesystem>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/formats/map/map_options.h"

namespace slamsweep::evaluator::inline formats::inline map {

/// Reads a ROS map_server map: the YAML (ParseMapServerYaml) and the image it names, turned into
/// cells with map_server's own rules (MapServerGridFromImage): p = v / 100 for the map_server
/// value v, unknown for -1. A missing image is an InputError naming the YAML (with the line of
/// `image`) and the image path.
OccupancyGrid ReadMapServer(const std::filesystem::path& yaml_path);

/// Writes `grid` the way ROS map_saver does: `<stem>.pgm` (trinary; `<stem>.png` with trinary_png) or
/// `<stem>.png` (scale)
/// beside `yaml_path`, then the YAML with map_saver's keys in its order: image (the file name,
/// relative to the YAML), resolution, origin [x, y, yaw], negate 0, occupied_thresh 0.65,
/// free_thresh 0.196 (and `mode: scale`). Numbers are written with full precision, unlike
/// map_saver's "%f", so that resolution and origin survive a round trip exactly.
/// Trinary: v = round(100 * p); v >= occupied_threshold_percent -> 0, 0 <= v <= free_threshold_percent
/// -> 254, otherwise (and unknown) 205. Read back, that gives the same cells for any grid whose
/// cells are 0, 1 or unknown.
/// Throws InputError for bad options (naming the option), a malformed grid or a file that cannot be written.
void WriteMapServer(const OccupancyGrid& grid, const std::filesystem::path& yaml_path,
                    const MapWriteOptions& options = {});

/// WriteMapServer, returning the grid ReadMapServer reads back from what it wrote. In trinary mode it is
/// computed from the image and YAML still in memory (an image file holds the image's bytes exactly), so
/// the image is not decoded again; in scale mode the files are read back.
OccupancyGrid WriteMapServerAndReadBack(const OccupancyGrid& grid, const std::filesystem::path& yaml_path,
                                        const MapWriteOptions& options = {});

}  // namespace slamsweep::evaluator::inline formats::inline map
