#include "cli/segment_rpe_output.h"

#include <fmt/format.h>

#include <charconv>
#include <nlohmann/json.hpp>

#include "cli/text_table.h"
#include "evaluator/core/input_error.h"
#include "evaluator/trajectory_metrics/rpe.h"
#include "evaluator/trajectory_metrics/segment_rpe.h"

namespace slamsweep::cli {

namespace ev = slamsweep::evaluator;

std::optional<std::vector<double>> ParseSegmentsOption(const std::string& text) {
  if (text == "auto") return std::nullopt;
  std::vector<double> lengths;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string_view item(text.data() + start, comma - start);
    double value = 0.0;
    const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), value);
    if (item.empty() || error != std::errc() || end != item.data() + item.size()) {
      throw ev::InputError("--segments: expected auto or segment lengths in metres such as 5,10,20, got '" + text +
                           "'");
    }
    lengths.push_back(value);
    start = comma + 1;
  }
  try {
    ev::ValidateSegmentLengths(lengths);
  } catch (const ev::InputError& error) {
    throw ev::InputError(std::string("--segments: ") + error.what());
  }
  return lengths;
}

void PrintSegmentRpe(const ev::Trajectory& reference, const ev::Trajectory& estimate,
                     const std::optional<std::vector<double>>& lengths_m, const ev::AssociationOptions& association,
                     bool json, std::ostream& out) {
  const double path_m = ev::PathLengthM(reference);
  ev::SegmentRpeOptions options;
  options.lengths_m = lengths_m ? *lengths_m : ev::DefaultSegmentLengthsM(path_m);
  if (options.lengths_m.empty()) {
    throw ev::InputError(
        fmt::format("--segments auto: the reference path ({:.3g} m) is too short for segments of 1 m; "
                    "give lengths with --segments 0.2,0.5",
                    path_m));
  }
  options.association = association;
  options.relative_tolerance = ev::kRpeDeltaTolerance;
  const ev::SegmentRpeResult result = ev::SegmentRpe(options).Compute(reference, estimate);
  nlohmann::json j = result.ToJson();
  j["specification"]["lengths_from"] = lengths_m ? "--segments" : "reference path";
  j["specification"]["reference_path_m"] = path_m;
  if (json) {
    out << j.dump() << "\n";
    return;
  }
  TextTable table(
      fmt::format("segment RPE over {} ({:.1f} m reference path; segments chosen on the reference, as "
                  "--delta L --delta-unit m --all-pairs --pairs-from-reference)",
                  lengths_m ? "the given lengths" : "10-50 % of the reference path", path_m));
  for (const ev::SegmentLengthResult& segments : result.lengths) {
    const std::string name = fmt::format("{} m", segments.length_m);
    if (!segments.translation_m_statistics) {
      table.Add(name, "no segment of this length in the associated poses");
      continue;
    }
    table.Add(name,
              fmt::format("n {}, translation mean {:.4g} m ({:.4g} %, median {:.4g} %), rotation mean {:.4g} deg/m",
                          segments.pairs.size(), segments.translation_m_statistics->mean,
                          segments.translation_pct_statistics->mean, segments.translation_pct_statistics->median,
                          segments.rotation_deg_per_m_statistics->mean));
  }
  table.Add("pairs", fmt::format("{} (reference unpaired {}, estimate unpaired {})", result.pairs,
                                 result.reference_unpaired, result.estimate_unpaired));
  table.Print(out);
}

}  // namespace slamsweep::cli
