#include "report/model/published_figures.h"

#include <cstdlib>
#include <map>

#include <yaml-cpp/yaml.h>

#include "evaluator/core/input_error.h"
#include "evaluator/core/installation.h"

namespace slamsweep::report::inline model {
namespace {

std::optional<std::pair<double, double>> MeanStdOf(const YAML::Node& node, const std::string& where) {
  if (!node.IsDefined() || node.IsNull()) return std::nullopt;
  if (!node.IsSequence() || node.size() != 2) throw evaluator::InputError(where + ": expected [mean, std]");
  return std::pair{node[0].as<double>(), node[1].as<double>()};
}

}  // namespace

std::vector<PublishedFigure> ReadPublishedFigures(const std::filesystem::path& path) {
  try {
    const YAML::Node root = YAML::LoadFile(path.string());
    std::map<std::string, std::pair<std::string, bool>> sources;
    for (const auto& source : root["sources"]) {
      sources[source.first.as<std::string>()] = {source.second["citation"].as<std::string>(""),
                                                 source.second["verified"].as<bool>(false)};
    }
    std::vector<PublishedFigure> figures;
    std::size_t index = 0;
    for (const YAML::Node& entry : root["published"]) {
      const std::string where = path.string() + ": published[" + std::to_string(index++) + "]";
      PublishedFigure figure;
      figure.sequence = entry["sequence"].as<std::string>("");
      figure.label = entry["label"].as<std::string>("");
      figure.source = entry["source"].as<std::string>("");
      const auto source = sources.find(figure.source);
      if (figure.sequence.empty() || figure.label.empty() || source == sources.end()) {
        throw evaluator::InputError(where + ": needs sequence, label and a source listed under sources");
      }
      figure.citation = source->second.first;
      figure.verified = source->second.second;
      figure.trans_abs = MeanStdOf(entry["trans_abs"], where + ".trans_abs");
      figure.rot_abs = MeanStdOf(entry["rot_abs"], where + ".rot_abs");
      figures.push_back(std::move(figure));
    }
    return figures;
  } catch (const YAML::Exception& error) {
    throw evaluator::InputError(path.string() + ": " + error.what());
  }
}

std::vector<PublishedFigure> LoadDefaultPublishedFigures() {
  std::filesystem::path path;
  if (const char* env = std::getenv("SLAMSWEEP_PUBLISHED"); env != nullptr && *env != '\0') {
    path = env;
  } else if (const auto installed = evaluator::FindInstalledData("configs/published.yaml")) {
    path = *installed;
  } else {
    path = SLAMSWEEP_DEFAULT_PUBLISHED;
  }
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return {};
  return ReadPublishedFigures(path);
}

}  // namespace slamsweep::report::inline model
