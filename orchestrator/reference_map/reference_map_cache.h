#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::orchestrator::inline reference_map {

/// A folder of maps, each stored as <name>.pgm + <name>.yaml (map_server, trinary) with the key it
/// was made for in <name>.key.json; safe for many worker processes at once.
class MapCache {
 public:
  explicit MapCache(std::filesystem::path dir) : dir_(std::move(dir)) {}

  struct Entry {
    evaluator::OccupancyGrid grid;
    std::filesystem::path yaml;
    bool found = false;  ///< false: `render` was called by this process
  };

  /// The map stored under `name` with exactly `key`, else `render()`'s map, stored first and then
  /// read back. Holds an exclusive flock on <name>.lock while it looks and renders, so concurrent
  /// callers render once; each file is written under a temporary name and renamed into place, the
  /// key file last, so a reader that finds the key finds the complete map. An entry that cannot
  /// be read or has another key is rendered again. Throws std::filesystem::filesystem_error or
  /// evaluator::InputError when the folder or files cannot be written; whatever `render` throws.
  Entry LoadOrRender(const std::string& name, const nlohmann::json& key,
                     const std::function<evaluator::OccupancyGrid()>& render) const;

 private:
  std::filesystem::path dir_;
};

}  // namespace slamsweep::orchestrator::inline reference_map
