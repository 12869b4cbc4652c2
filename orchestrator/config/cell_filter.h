#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "orchestrator/config/sweep_config.h"

namespace slamsweep::orchestrator::inline config {

/// The `exclude:` or `include:` list (`key`) of a sweep whose algorithms, sequences and noise are already
/// parsed into `config`. Every name must exist, and every parameter must be declared by the named
/// algorithm (or, without one, by some algorithm), so that a typo cannot silently match nothing.
/// An include needs an algorithm and a sequence; an exclude needs at least one field.
std::vector<CellFilter> ParseCellFilters(const std::filesystem::path& file, const YAML::Node& node,
                                         std::string_view key, const SweepConfig& config, bool is_include);

}  // namespace slamsweep::orchestrator::inline config
