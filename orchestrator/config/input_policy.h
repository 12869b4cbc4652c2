#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator::inline config {

/// What a sweep file may use when it comes from someone the operator does not fully trust (a sweep
/// submitted to `slamsweep serve`). The default trusts the file, as `slamsweep run` does.
struct InputPolicy {
  /// Empty: any path. Else every file the sweep reads (a `catalog:` file, sequence and relations
  /// files) must lie inside one of these folders once symbolic links and ".." are resolved.
  std::vector<std::filesystem::path> allowed_roots;
  /// false: `adapter: command` is refused, since it runs any program the file names.
  bool allow_commands = true;
  /// false: `network: true` is refused (a program reaching the network could fetch the answer).
  bool allow_network = true;
};

/// A well-formed sweep file that asks for something its InputPolicy forbids. The message is
/// "FILE:LINE:COLUMN: field: ..." like every config error; the service answers it with 403.
class PolicyError : public evaluator::InputError {
 public:
  using evaluator::InputError::InputError;
};

/// True when `path` (made absolute, symbolic links resolved as far as it exists) lies inside one of
/// the policy's roots, or the policy has none.
bool IsAllowedPath(const InputPolicy& policy, const std::filesystem::path& path);

/// Throws PolicyError at `node` unless IsAllowedPath; checked before the file is even looked at, so
/// that a refused path tells nothing about what exists outside the roots.
void RequireAllowedPath(const InputPolicy& policy, const std::filesystem::path& file, const YAML::Node& node,
                        std::string_view field, std::string_view what, const std::filesystem::path& path);

}  // namespace slamsweep::orchestrator::inline config
