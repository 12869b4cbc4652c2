#pragma once

#include <filesystem>
#include <memory>
#include <string_view>

#include "slam/common/driver_main.h"

namespace slamsweep::slam::slam_constructor {

/// A slam-constructor SLAM (tinySLAM, vinySLAM) configured from one of its properties files
/// (config/slams/<name>.properties of the installed upstream, with the files it includes). Every
/// property the files set is a parameter under its own name ("slam/mapping/blur=0.4"); anything
/// else is refused. The Monte-Carlo scan matcher's seed (slam/scmtch/MC/seed) comes from --seed.
/// slam-constructor's config/<relative>: an installed driver's copy (PREFIX/share/slamsweep/slam-constructor/config,
/// where the image's runtime stage has it), else the one of the upstream this build used (`built_root`).
std::filesystem::path ConfigFile(std::string_view relative, const std::filesystem::path& built_root);

std::unique_ptr<Algorithm> ConfigureFromProperties(const std::filesystem::path& properties_file, Parameters& parameters,
                                                   const DriverArgs& args);

}  // namespace slamsweep::slam::slam_constructor
