#pragma once

#include <cstdint>
#include <opencv2/core/mat.hpp>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/formats/map/map_server_yaml.h"

namespace slamsweep::evaluator::inline formats::inline map {

/// map_server's byte for value -1 (unknown) before it is stored in the int8 map.
inline constexpr std::uint8_t kMapServerUnknownByte = 255;

/// The value ROS 1 map_server (image_loader.cpp) computes for one pixel, as the unsigned byte
/// it stores into the int8 cell: 0..100 = occupancy percent, kMapServerUnknownByte = -1.
/// `samples` are the pixel's `channels` (1, 3 or 4) samples in R, G, B, A order.
/// - The channels are averaged: all of them in trinary mode or without alpha; without the alpha
///   channel (the 4th) in scale and raw mode.
/// - negate: average = 255 - average. raw mode returns the average, truncated, as it is.
/// - occ = (255 - average) / 255; occ > occupied_thresh -> 100; occ < free_thresh -> 0;
///   otherwise unknown in trinary mode and for a transparent pixel (alpha 0) in scale mode, else
///   99 * (occ - free_thresh) / (occupied_thresh - free_thresh), truncated.
/// map_server takes "alpha" from the last channel even without an alpha channel, i.e. from
/// blue in an RGB image; that is kept, so a colour map reads as it does in ROS.
std::uint8_t MapServerPixelValue(const std::uint8_t* samples, int channels, const MapServerMetadata& metadata);

/// The grid of a map_server map from its image (ReadImageFile layout), with resolution and
/// origin from the YAML. Cell p = v / 100 for v in 0..100; -1 is unknown. Row 0 stays the top
/// image row (map_server flips to put row 0 at the bottom; OccupancyGrid keeps image order).
/// A raw-mode pixel outside 0..100 and 255 has no occupancy meaning: InputError naming the
/// image, pixel and value.
OccupancyGrid MapServerGridFromImage(const cv::Mat& image, const MapServerMetadata& metadata);

}  // namespace slamsweep::evaluator::inline formats::inline map
