#pragma once

#include <filesystem>
#include <string>

#include <yaml-cpp/yaml.h>

#include "orchestrator/config/sweep_config.h"

namespace slamsweep::orchestrator::inline config {

/// One entry of `algorithms:` (see sweep_config.h). `path` names it in messages ("algorithms[2]").
/// Checks the adapter name, parameter values (scalars or non-empty lists of scalars), and for the
/// command adapter its argv, formats and placeholders ({param:X} must name a declared parameter).
/// A command adapter that `policy` does not allow is a PolicyError at its `adapter:` value.
AlgorithmConfig ParseAlgorithmConfig(const std::filesystem::path& file, const YAML::Node& node, const std::string& path,
                                     const InputPolicy& policy = {});

}  // namespace slamsweep::orchestrator::inline config
