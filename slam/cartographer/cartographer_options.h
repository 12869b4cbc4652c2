#pragma once

#include <string>

#include <cartographer/mapping/proto/map_builder_options.pb.h>
#include <cartographer/mapping/proto/trajectory_builder_options.pb.h>

#include "slam/common/parameters.h"

namespace slamsweep::slam::cartographer_driver {

/// The options a run starts from: slam/cartographer/slamsweep_2d.lua (which includes upstream's
/// configuration_files), then every key=value parameter as a Lua assignment to its path in the
/// returned `options` table. A path the options do not have is refused before anything runs. An
/// installed driver reads both from PREFIX/share/slamsweep/cartographer (slam/cartographer/CMakeLists.txt).
struct CartographerOptions {
  ::cartographer::mapping::proto::MapBuilderOptions map_builder;
  ::cartographer::mapping::proto::TrajectoryBuilderOptions trajectory_builder;
};

CartographerOptions ReadCartographerOptions(Parameters& parameters);

}  // namespace slamsweep::slam::cartographer_driver
