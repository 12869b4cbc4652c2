#include "orchestrator/config/cell_filter.h"

#include <fmt/format.h>

#include <algorithm>

#include "orchestrator/config/yaml_fields.h"

namespace slamsweep::orchestrator::inline config {
namespace {

template <typename Item, typename NameOf>
std::optional<std::string> KnownName(YamlFields& fields, std::string_view key, const std::vector<Item>& items,
                                     NameOf&& name_of) {
  const YAML::Node node = fields.Get(key);
  if (!node.IsDefined() || node.IsNull()) return std::nullopt;
  std::string known;
  for (const Item& item : items) {
    known += (known.empty() ? "" : ", ") + name_of(item);
    if (node.IsScalar() && name_of(item) == node.Scalar()) return node.Scalar();
  }
  FailExpected(fields.file(), node, fields.PathOf(key), fmt::format("one of the sweep's names ({})", known));
}

bool Declares(const AlgorithmConfig& algorithm, const std::string& parameter) {
  return std::any_of(algorithm.parameters.begin(), algorithm.parameters.end(),
                     [&](const ParameterAxis& axis) { return axis.name == parameter; });
}

}  // namespace

std::vector<CellFilter> ParseCellFilters(const std::filesystem::path& file, const YAML::Node& node,
                                         std::string_view key, const SweepConfig& config, bool is_include) {
  std::vector<CellFilter> filters;
  if (!node.IsDefined() || node.IsNull()) return filters;
  if (!node.IsSequence()) FailExpected(file, node, key, "a list of {algorithm, sequence, noise, parameters}");
  for (std::size_t i = 0; i < node.size(); ++i) {
    YamlFields fields(file, node[i], fmt::format("{}[{}]", key, i));
    CellFilter filter;
    filter.algorithm =
        KnownName(fields, "algorithm", config.algorithms, [](const AlgorithmConfig& a) { return a.name; });
    filter.sequence =
        KnownName(fields, "sequence", config.sequences, [](const SequenceSpec& s) { return s.entry.name; });
    filter.noise = KnownName(fields, "noise", config.noise, [](const NoiseSpec& n) { return n.name; });
    const YAML::Node parameters = fields.Get("parameters");
    if (parameters.IsDefined() && !parameters.IsNull()) {
      const std::string path = fields.PathOf("parameters");
      if (!parameters.IsMap()) FailExpected(file, parameters, path, "a map of parameter names to single values");
      const AlgorithmConfig* algorithm = nullptr;
      for (const AlgorithmConfig& candidate : config.algorithms) {
        if (filter.algorithm && candidate.name == *filter.algorithm) algorithm = &candidate;
      }
      for (const auto& item : parameters) {
        const std::string name = item.first.Scalar();
        const bool declared = algorithm != nullptr
                                  ? Declares(*algorithm, name)
                                  : std::any_of(config.algorithms.begin(), config.algorithms.end(),
                                                [&](const AlgorithmConfig& a) { return Declares(a, name); });
        if (!declared) {
          FailAt(file, item.first,
                 fmt::format("{}.{}: expected a parameter declared by {}, got an undeclared one", path, name,
                             algorithm != nullptr ? "algorithm '" + algorithm->name + "'" : "some algorithm"));
        }
        if (!item.second.IsScalar()) FailExpected(file, item.second, path + "." + name, "a single value");
        filter.parameters[name] = YamlToJson(item.second);
      }
    }
    fields.Finish();
    if (is_include && (!filter.algorithm || !filter.sequence)) {
      FailAt(file, node[i], fmt::format("{}[{}]: expected at least an algorithm and a sequence to add", key, i));
    }
    if (!filter.algorithm && !filter.sequence && !filter.noise && filter.parameters.empty()) {
      FailAt(file, node[i],
             fmt::format("{}[{}]: expected at least one of algorithm, sequence, noise, parameters", key, i));
    }
    filters.push_back(std::move(filter));
  }
  return filters;
}

}  // namespace slamsweep::orchestrator::inline config
