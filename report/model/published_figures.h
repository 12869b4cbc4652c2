#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace slamsweep::report::inline model {

/// One published relations error (Kuemmerle et al.'s metric) for a whole log: configs/published.yaml.
struct PublishedFigure {
  std::string sequence;  ///< the catalog name of the log ("intel"); matched with a table by its relations file
  std::string label;     ///< "Cartographer", "graph mapping"
  std::string source;    ///< the source's key ("hess2016")
  std::string citation;
  bool verified = false;                               ///< read in the paper itself
  std::optional<std::pair<double, double>> trans_abs;  ///< mean, std (m)
  std::optional<std::pair<double, double>> rot_abs;    ///< mean, std (deg)
};

/// Reads configs/published.yaml. Throws evaluator::InputError naming the file and the entry that is malformed.
std::vector<PublishedFigure> ReadPublishedFigures(const std::filesystem::path& path);

/// The published figures the report sets beside its tables: $SLAMSWEEP_PUBLISHED, else the installed
/// configs/published.yaml, else the source tree's; none when no such file exists.
std::vector<PublishedFigure> LoadDefaultPublishedFigures();

}  // namespace slamsweep::report::inline model
