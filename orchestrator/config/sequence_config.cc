#include "orchestrator/config/sequence_config.h"

#include <fmt/format.h>

#include <array>
#include <optional>

#include "evaluator/core/input_error.h"
#include "orchestrator/config/yaml_fields.h"

namespace slamsweep::orchestrator::inline config {
namespace {

const evaluator::CatalogEntry& LookUp(const std::filesystem::path& file, const YAML::Node& node,
                                      const std::string& path, const evaluator::Catalog& catalog) {
  const std::string name = node.Scalar();
  for (const evaluator::CatalogEntry& entry : catalog.entries) {
    if (entry.name == name) return entry;
  }
  std::string known;
  for (const evaluator::CatalogEntry& entry : catalog.entries) known += (known.empty() ? "" : ", ") + entry.name;
  if (catalog.entries.empty()) {
    FailAt(file, node,
           fmt::format("{}: expected a sequence of the catalog {}, got '{}' (the catalog is missing or empty)", path,
                       catalog.source.string(), name));
  }
  FailAt(file, node,
         fmt::format("{}: expected a sequence of the catalog {} ({}), got '{}'", path, catalog.source.string(), known,
                     name));
}

/// A path of `entry` with variables replaced, made absolute against `base`, and required to exist.
std::string ResolveExisting(const std::filesystem::path& file, const YAML::Node& node, const std::string& path,
                            const evaluator::CatalogEntry& entry, std::string_view what, const std::string& text,
                            const std::filesystem::path& base, const evaluator::CatalogVariables& variables,
                            const InputPolicy& policy) {
  std::filesystem::path resolved;
  try {
    resolved = evaluator::ResolveCatalogPath(text, variables);
  } catch (const evaluator::InputError& error) {
    FailAt(file, node, fmt::format("{}: sequence '{}': {}", path, entry.name, error.what()));
  }
  if (resolved.is_relative()) resolved = base / resolved;
  resolved = resolved.lexically_normal();
  RequireAllowedPath(policy, file, node, path, fmt::format("sequence {}", what), resolved);
  std::error_code error;
  if (!std::filesystem::is_regular_file(resolved, error)) {
    FailAt(file, node,
           fmt::format("{}: sequence '{}': expected its {} {}, got no such file{}", path, entry.name, what,
                       resolved.string(), entry.download_hint.empty() ? "" : "; get it from: " + entry.download_hint));
  }
  return resolved.string();
}

std::optional<std::size_t> MaxScans(const std::filesystem::path& file, const YAML::Node& node,
                                    const std::string& path) {
  if (!node.IsDefined() || node.IsNull()) return std::nullopt;
  const bool ok = node.IsScalar() && node.Tag() != "!" && !node.Scalar().empty() &&
                  node.Scalar().find_first_not_of("0123456789") == std::string::npos && node.Scalar() != "0" &&
                  node.Scalar().size() < 19;
  if (!ok) FailExpected(file, node, path, "a whole number of scans >= 1");
  return static_cast<std::size_t>(std::stoull(node.Scalar()));
}

/// `relations_window: [from, to]` (seconds on the relations' clock, from < to).
std::optional<std::array<double, 2>> RelationsWindow(const std::filesystem::path& file, const YAML::Node& node,
                                                     const std::string& path) {
  if (!node.IsDefined() || node.IsNull()) return std::nullopt;
  const nlohmann::json value = node.IsSequence() ? YamlToJson(node) : nlohmann::json();
  if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number() ||
      !(value[0].get<double>() < value[1].get<double>())) {
    FailExpected(file, node, path, "[from, to], two stamps in seconds on the relations' clock with from < to");
  }
  return std::array<double, 2>{value[0].get<double>(), value[1].get<double>()};
}

}  // namespace

SequenceSpec ParseSequenceConfig(const std::filesystem::path& file, YAML::Node node, const std::string& path,
                                 const evaluator::Catalog& catalog, const evaluator::CatalogVariables& variables,
                                 const InputPolicy& policy) {
  SequenceSpec spec;
  std::filesystem::path base;
  const YAML::Node& view = node;  // const lookups never insert keys
  if (node.IsScalar()) {
    spec.entry = LookUp(file, node, path, catalog);
    base = catalog.source.parent_path();
  } else if (node.IsMap() && view["catalog"].IsDefined()) {
    YamlFields fields(file, node, path);
    const YAML::Node name = fields.Get("catalog");
    if (!name.IsScalar()) FailExpected(file, name, fields.PathOf("catalog"), "a catalog sequence name");
    spec.entry = LookUp(file, name, fields.PathOf("catalog"), catalog);
    spec.entry.name = fields.Text("name", spec.entry.name);
    if (spec.entry.name.empty()) FailExpected(file, fields.Get("name"), fields.PathOf("name"), "a non-empty name");
    spec.max_scans = MaxScans(file, fields.Get("max_scans"), fields.PathOf("max_scans"));
    if (const auto window = RelationsWindow(file, fields.Get("relations_window"), fields.PathOf("relations_window"))) {
      if (spec.entry.relations_path.empty()) {
        FailAt(file, fields.Get("relations_window"),
               fmt::format("{}: sequence '{}' has no relations", fields.PathOf("relations_window"), spec.entry.name));
      }
      spec.entry.relations_window_s = window;
    }
    if (const YAML::Node odometry = fields.Get("odometry"); odometry.IsDefined() && !odometry.IsNull()) {
      if (!odometry.IsScalar()) FailExpected(file, odometry, fields.PathOf("odometry"), "recorded or reference");
      try {
        spec.entry.odometry = evaluator::ParseOdometryMode(odometry.Scalar(), fields.PathOf("odometry"));
      } catch (const evaluator::InputError& error) {
        FailAt(file, odometry, error.what());
      }
      if (*spec.entry.odometry == evaluator::OdometryMode::kReference && !evaluator::OdometryModeApplies(spec.entry)) {
        FailAt(file, odometry,
               fmt::format("{}: reference applies only to CARMEN logs whose logged pose is the corrected pose; "
                           "sequence '{}' has only its recorded odometry",
                           fields.PathOf("odometry"), spec.entry.name));
      }
    }
    fields.Finish();
    base = catalog.source.parent_path();
  } else if (node.IsMap()) {
    // max_scans is ours, not a catalog key: read it, then hand the rest to the catalog's own reader.
    spec.max_scans = MaxScans(file, view["max_scans"], path + ".max_scans");
    node.remove("max_scans");
    spec.entry = evaluator::ParseCatalogEntry(file, node);
    base = file.parent_path();
  } else {
    FailExpected(file, node, path, "a catalog name, {catalog: NAME, ...} or an inline sequence entry");
  }
  if (spec.entry.format != "simulated") {
    spec.entry.path = ResolveExisting(file, node, path, spec.entry, "file", spec.entry.path, base, variables, policy);
  }
  if (!spec.entry.relations_path.empty()) {
    spec.entry.relations_path = ResolveExisting(file, node, path, spec.entry, "relations file",
                                                spec.entry.relations_path, base, variables, policy);
  }
  if (spec.entry.corrected_log) {
    spec.entry.corrected_log->path = ResolveExisting(file, node, path, spec.entry, "corrected log",
                                                     spec.entry.corrected_log->path, base, variables, policy);
  }
  if (!spec.entry.reference_map_path.empty()) {
    spec.entry.reference_map_path = ResolveExisting(file, node, path, spec.entry, "reference map",
                                                    spec.entry.reference_map_path, base, variables, policy);
  }
  return spec;
}

}  // namespace slamsweep::orchestrator::inline config
