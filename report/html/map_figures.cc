#include "report/html/map_figures.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <nlohmann/json.hpp>
#include <system_error>

#include "evaluator/core/input_error.h"
#include "report/html/artwork.h"
#include "report/html/number_format.h"
#include "report/html/view_pages.h"
#include "report/html/safe_name.h"
#include "orchestrator/store/json_lookup.h"

namespace slamsweep::report::inline html {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using html_shorthand::E;
using orchestrator::FindField;

std::optional<double> Number(const json* object, const char* key) {
  const json* value = object ? FindField(*object, key) : nullptr;
  if (value == nullptr || !value->is_number()) return std::nullopt;
  return value->get<double>();
}

/// result.json's metric_details (the run record keeps only their top-level numbers).
json MetricDetails(const RunRecord& run) {
  std::ifstream in(run.dir / "result.json", std::ios::binary);
  const json result = json::parse(in, nullptr, false);
  const json* details = FindField(result, "metric_details");
  return details ? *details : json::object();
}

/// The run's place in the reference's frame and how it was found.
std::pair<MapPlacement, std::string> PlacementOf(const json& details) {
  const json* compare = FindField(details, "map_compare");
  const json* transform = compare ? FindField(*compare, "transform") : nullptr;
  const auto x = Number(transform, "x_m"), y = Number(transform, "y_m"), yaw = Number(transform, "yaw_rad");
  if (x && y && yaw) {
    const json* how = FindField(*compare, "placement");
    const std::string by = how && how->is_string() ? how->get<std::string>() : "the map scores' transform";
    return {{*x, *y, *yaw, 1.0}, "placed on the reference by " + by};
  }
  const json* ape = FindField(details, "ape_trans");
  const json* alignment = ape ? FindField(*ape, "alignment") : nullptr;
  const json* rotation = alignment ? FindField(*alignment, "rotation") : nullptr;
  const json* translation = alignment ? FindField(*alignment, "translation") : nullptr;
  if (rotation && translation && rotation->is_array() && rotation->size() >= 2 && (*rotation)[0].is_array() &&
      (*rotation)[1].is_array() && (*rotation)[0].size() >= 1 && (*rotation)[1].size() >= 1 &&
      (*rotation)[0][0].is_number() && (*rotation)[1][0].is_number() && translation->is_array() &&
      translation->size() >= 2 && (*translation)[0].is_number() && (*translation)[1].is_number()) {
    const double scale = Number(alignment, "scale").value_or(1.0);
    // The rotation part of s R: its first column gives the yaw whatever the scale.
    const double yaw_rad = std::atan2((*rotation)[1][0].get<double>(), (*rotation)[0][0].get<double>());
    return {{(*translation)[0].get<double>(), (*translation)[1].get<double>(), yaw_rad, scale > 0.0 ? scale : 1.0},
            "placed on the reference by the ATE alignment"};
  }
  return {{}, "as recorded (no alignment to a reference)"};
}

/// The reference map the run was scored against: the recorded file, else the file of that name in the
/// sweep's reference_maps/ (a result folder that was moved).
fs::path ReferenceMapOf(const RunRecord& run, const json& details, std::string& source) {
  const json* compare = FindField(details, "map_compare");
  const json* reference = compare ? FindField(*compare, "reference_map") : nullptr;
  const json* file = reference ? FindField(*reference, "file") : nullptr;
  if (file == nullptr || !file->is_string() || file->get<std::string>().empty()) return {};
  if (const json* from = FindField(*reference, "source"); from && from->is_string()) source = from->get<std::string>();
  const fs::path recorded = file->get<std::string>();
  if (IsRegularFileNoFollow(recorded)) return recorded;
  const fs::path moved = run.dir.parent_path().parent_path() / "reference_maps" / recorded.filename();
  return IsRegularFileNoFollow(moved) ? moved : fs::path();
}

MapScores ScoresOf(const json& details) {
  const json* compare = FindField(details, "map_compare");
  MapScores scores;
  if (compare == nullptr) return scores;
  scores.f1 = Number(compare, "f1");
  scores.accuracy = Number(compare, "accuracy");
  scores.completeness = Number(compare, "completeness");
  scores.chamfer_m = Number(compare, "chamfer_m");
  scores.iou_occupied = Number(compare, "iou_occupied");
  scores.iou_free = Number(compare, "iou_free");
  return scores;
}

bool ScoredOnMapFile(const json& details) {
  const json* compare = FindField(details, "map_compare");
  const json* scored = compare ? FindField(*compare, "scored_map") : nullptr;
  return scored && scored->is_string() && scored->get<std::string>() == "the run's map file";
}

WallMatchOptions MatchOptionsOf(const json& details) {
  const json* compare = FindField(details, "map_compare");
  const json* specification = compare ? FindField(*compare, "specification") : nullptr;
  WallMatchOptions options;
  options.occupied_threshold = Number(specification, "occupied_threshold").value_or(options.occupied_threshold);
  options.free_threshold = Number(specification, "free_threshold").value_or(options.free_threshold);
  options.match_radius_cells =
      static_cast<int>(Number(specification, "match_radius_cells").value_or(options.match_radius_cells));
  return options;
}

Html ScoresList(const MapScores& scores) {
  Html items;
  const auto add = [&](const char* name, const std::optional<double>& value, const char* unit) {
    if (value) items += Element("li", "", E(std::string(name) + " " + FormatNumber(*value) + unit));
  };
  add("F1", scores.f1, "");
  add("accuracy", scores.accuracy, "");
  add("completeness", scores.completeness, "");
  add("Chamfer", scores.chamfer_m, " m");
  add("IoU occupied", scores.iou_occupied, "");
  add("IoU free", scores.iou_free, "");
  if (items.str().empty()) return Element("p", "note", E("no map-vs-reference scores in result.json"));
  return Element("ul", "map-scores", items);
}

}  // namespace

MapComparisonDrawn Artwork::MapComparison(const MapComparisonJob&) {
  throw std::runtime_error("this image maker draws no map comparisons");
}

std::vector<PlannedMapComparison> PlanMapComparisons(const fs::path& out_dir, SiteData& site, int max_side_px) {
  const SweepModel& model = *site.model;
  std::vector<PlannedMapComparison> planned;
  for (const SequenceModel& sequence : model.sequences) {
    const std::string folder = TableFolder(*site.layout, sequence.key);
    MapsCompared maps;
    MapComparisonJob job;
    job.max_side_px = max_side_px;
    for (std::size_t r = 0; r < sequence.rows.size(); ++r) {
      const AlgorithmRow& row = sequence.rows[r];
      if (!row.median_run) continue;
      const RunRecord& run = model.runs[*row.median_run];
      if (run.status != RunStatus::kOk || !IsRegularFileNoFollow(run.dir / "map.yaml")) continue;
      const json details = MetricDetails(run);
      MapPanelShown shown;
      shown.row = r;
      shown.run = *row.median_run;
      shown.path = folder + fmt::format("map-{}.png", r);
      shown.scores = ScoresOf(details);
      shown.scored_on_map_file = ScoredOnMapFile(details);
      MapPanelRequest request;
      request.map_file = run.dir / "map.yaml";
      std::tie(request.placement, shown.placement) = PlacementOf(details);
      request.png = out_dir / shown.path;
      std::string source;
      request.reference_map_file = ReferenceMapOf(run, details, source);
      if (!request.reference_map_file.empty()) {
        shown.difference_path = folder + fmt::format("map-difference-{}.png", r);
        request.difference_png = out_dir / shown.difference_path;
        request.match = MatchOptionsOf(details);
        shown.match_radius_cells = request.match.match_radius_cells;
        if (job.reference_map_file.empty()) {
          job.reference_map_file = request.reference_map_file;
          maps.reference_path = folder + "map-reference.png";
          maps.reference_source = source;
          job.reference_png = out_dir / maps.reference_path;
        }
      }
      maps.panels.push_back(std::move(shown));
      job.panels.push_back(std::move(request));
    }
    if (job.panels.empty()) continue;
    std::error_code error_code;
    fs::create_directories(out_dir / folder, error_code);
    if (error_code) {
      throw evaluator::InputError((out_dir / folder).string() + ": cannot create folder (" + error_code.message() +
                                  ")");
    }
    maps.error = "no image maker configured";
    site.maps_compared[sequence.key] = std::move(maps);
    planned.push_back({sequence.key, std::move(job)});
  }
  return planned;
}

Html MapsComparedSection(const SiteData& site, const SequenceModel& sequence, std::string_view root) {
  const auto found = site.maps_compared.find(sequence.key);
  if (found == site.maps_compared.end()) return {};
  const MapsCompared& maps = found->second;
  // An anchor, so that a link (or a screenshot) can go straight to the maps.
  Html body = Html::Trusted("<h2 id=\"maps-compared\">") + E("Maps compared") + Html::Trusted("</h2>");
  if (!maps.attempted) return body + Element("p", "note", E("Maps not drawn (" + maps.error + ")."));
  const MapComparisonDrawn& drawn = maps.drawn;
  const std::string by = sequence.rows.empty() || sequence.rows[maps.panels.front().row].median_by.empty()
                             ? "the first successful run"
                             : "median run by " + sequence.rows[maps.panels.front().row].median_by;
  const bool any_placed = std::any_of(maps.panels.begin(), maps.panels.end(),
                                      [](const MapPanelShown& panel) { return panel.placement.starts_with("placed"); });
  body += Element(
      "p", "note",
      E(fmt::format("Each row's {} (the run of the gallery and the trajectories), every panel the same {} x {} m "
                    "window at {} m per pixel, {}{}.",
                    by, FormatNumber(drawn.window_width_m), FormatNumber(drawn.window_height_m),
                    FormatNumber(drawn.metres_per_pixel),
                    any_placed ? "in the reference's frame where the run was aligned to it"
                               : "each map in its own frame (no reference to align it to)",
                    maps.reference_path.empty() ? "" : " (the window is the reference map's known area)")));
  const auto run_caption = [&](const MapPanelShown& panel) {
    const AlgorithmRow& row = sequence.rows[panel.row];
    const RunRecord& run = site.model->runs[panel.run];
    return AlgorithmSwatch(site, row.name) + E(row.algorithm + " · ") +
           Link(std::string(root) + site.layout->RunPage(panel.run), E(run.run_id));
  };
  Html panels;
  if (drawn.reference_made) {
    panels += Element(
        "figure", "map-panel",
        ImageElement(std::string(root) + maps.reference_path, "reference map", "map-panel") +
            Element("figcaption", "",
                    E("reference map" + (maps.reference_source.empty() ? "" : " (" + maps.reference_source + ")"))));
  }
  Html differences;
  for (std::size_t i = 0; i < maps.panels.size(); ++i) {
    const MapPanelShown& panel = maps.panels[i];
    MapPanelDrawn not_drawn;
    not_drawn.note = "the image maker returned no panel";
    const MapPanelDrawn& made = i < drawn.panels.size() ? drawn.panels[i] : not_drawn;
    if (!made.made) {
      panels += Element("p", "note", run_caption(panel) + E(": map not drawn (" + made.note + ")"));
      continue;
    }
    panels += Element(
        "figure", "map-panel",
        ImageElement(std::string(root) + panel.path, "map of " + site.model->runs[panel.run].run_id, "map-panel") +
            Element("figcaption", "", run_caption(panel) + E(" · " + panel.placement)));
    if (panel.difference_path.empty()) continue;
    if (!made.difference_made) {
      differences +=
          Element("p", "note", run_caption(panel) + E(": difference not drawn (" + made.difference_note + ")"));
      continue;
    }
    Html caption = run_caption(panel);
    if (made.counts) {
      caption += Element("p", "map-counts",
                         E(fmt::format("cells: {} only in the run, {} only in the reference, {} in both",
                                       made.counts->run_only, made.counts->reference_only, made.counts->both)));
    }
    caption += ScoresList(panel.scores);
    differences += Element(
        "figure", "map-panel",
        ImageElement(std::string(root) + panel.difference_path,
                     "walls of " + site.model->runs[panel.run].run_id + " against the reference map", "map-panel") +
            Element("figcaption", "", caption));
  }
  body += Element("div", "gallery maps", panels);
  if (!differences.str().empty()) {
    const int radius = maps.panels.front().match_radius_cells;
    const bool all_scored_on_file = std::all_of(maps.panels.begin(), maps.panels.end(), [](const MapPanelShown& panel) {
      return panel.difference_path.empty() || panel.scored_on_map_file;
    });
    const std::string counts_note =
        all_scored_on_file
            ? "The cell counts are recomputed from the run's map file, the file its scores were computed on."
            : "The cell counts are recomputed from the run's map file (8-bit grey levels); some scores below come "
              "from results that were computed on the program's map before it was written, so a cell near a "
              "threshold can count differently.";
    body += Element("h3", "", E("Walls against the reference map"));
    body +=
        Element("p", "legend-note",
                Element("span", "wall-key wall-run-only", E("■")) + E(" only in the run · ") +
                    Element("span", "wall-key wall-reference-only", E("■")) + E(" only in the reference · ") +
                    Element("span", "wall-key wall-both", E("■")) +
                    E(fmt::format(" in both (an occupied cell within {} {} of an occupied cell of the other map, the "
                                  "match radius of the scores below) · white: free · grey: unknown. {}",
                                  radius, radius == 1 ? "cell" : "cells", counts_note)));
    body += Element("div", "gallery maps", differences);
  }
  return body;
}

std::string_view MapsComparedStyleSheet() {
  return R"(img.map-panel { width: 360px; max-width: 100%; height: auto; }
figure.map-panel { max-width: 370px; }
ul.map-scores { margin: 0.2em 0; padding-left: 1.2em; font-size: 0.9em; }
p.map-counts { margin: 0.2em 0; font-size: 0.9em; }
.wall-key { font-size: 1.2em; }
.wall-run-only { color: #0072B2; }
.wall-reference-only { color: #D55E00; }
.wall-both { color: #000000; }
)";
}

}  // namespace slamsweep::report::inline html
