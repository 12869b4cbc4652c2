#include "orchestrator/config/input_policy.h"

#include <algorithm>

#include <fmt/format.h>

#include "orchestrator/config/yaml_fields.h"

namespace slamsweep::orchestrator::inline config {
namespace {

/// The path as the kernel will see it: absolute, ".." folded, every existing symbolic link followed.
std::filesystem::path Resolved(const std::filesystem::path& path) {
  std::error_code error;
  std::filesystem::path resolved = std::filesystem::weakly_canonical(std::filesystem::absolute(path), error);
  if (error) resolved = std::filesystem::absolute(path).lexically_normal();
  return resolved;
}

bool IsInside(const std::filesystem::path& path, const std::filesystem::path& root) {
  // Whole components: /data/sets-private is not inside /data/sets.
  auto root_it = root.begin();
  auto path_it = path.begin();
  for (; root_it != root.end(); ++root_it, ++path_it) {
    if (root_it->empty()) continue;  // the trailing "" of a root written with a final '/'
    if (path_it == path.end() || *path_it != *root_it) return false;
  }
  return true;
}

}  // namespace

bool IsAllowedPath(const InputPolicy& policy, const std::filesystem::path& path) {
  if (policy.allowed_roots.empty()) return true;
  const std::filesystem::path resolved = Resolved(path);
  return std::any_of(policy.allowed_roots.begin(), policy.allowed_roots.end(),
                     [&](const std::filesystem::path& root) { return IsInside(resolved, Resolved(root)); });
}

void RequireAllowedPath(const InputPolicy& policy, const std::filesystem::path& file, const YAML::Node& node,
                        std::string_view field, std::string_view what, const std::filesystem::path& path) {
  if (IsAllowedPath(policy, path)) return;
  throw PolicyError(LocatedAt(file, node,
                              fmt::format("{}: expected a {} inside the allowed dataset roots, got {} (outside them)",
                                          field, what, path.string())));
}

}  // namespace slamsweep::orchestrator::inline config
