// `slamsweep eval map`: the paper's ground-truth-free map metrics.
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>

#include "cli/command.h"
#include "cli/text_table.h"
#include "evaluator/formats/map/map_file.h"
#include "evaluator/map_metrics/paper_metrics.h"
#include "evaluator/map_compare/map_resample.h"

namespace slamsweep::cli {

namespace ev = slamsweep::evaluator;

void RegisterEvalMapCommand(CLI::App& eval, const Streams& streams) {
  struct Options {
    std::string map_path;
    std::optional<int> unknown_value;
    bool no_crop = false;
    int crop_margin_cells = 2;
    std::optional<double> resolution_m;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = eval.add_subcommand("map", "occupied proportion, corners and enclosed areas (paper profile)");
  command
      ->add_option("MAP", options->map_path, "map: ROS .yaml (+ PGM/PNG), MRPT .png (+ _limits.txt) or bare .pgm/.png")
      ->required();
  command
      ->add_option("--unknown-value", options->unknown_value,
                   "grey value (0-255) that marks unknown cells in a bare PGM/PNG (map_saver: 205)")
      ->check(CLI::Range(0, 255));
  command->add_flag("--no-crop", options->no_crop,
                    "score the grid as it is (the raw-grid profile) instead of its known cells' bounding box");
  command->add_option("--crop-margin", options->crop_margin_cells, "cells kept around the known cells when cropping")
      ->check(CLI::NonNegativeNumber);
  command
      ->add_option("--resolution", options->resolution_m,
                   "score the map resampled to cells of this size in metres (grey levels kept), as a sweep does "
                   "at evaluation.map_resolution_m; default: the map's own")
      ->check(CLI::PositiveNumber);
  command->add_flag("--json", options->json, "print one JSON object instead of a table");
  command->callback([options, streams] {
    ev::MapReadOptions read_options;
    read_options.unknown_value = options->unknown_value;
    ev::OccupancyGrid grid = ev::ReadMap(options->map_path, read_options);
    const double map_resolution_m = grid.resolution_m;
    if (options->resolution_m) grid = ev::ResampleKeepingProbabilities(grid, *options->resolution_m);
    ev::PaperMetricsOptions metric_options;
    metric_options.canvas.crop = !options->no_crop;
    metric_options.canvas.crop_margin_cells = options->crop_margin_cells;
    nlohmann::json j = ev::ComputePaperMetrics(std::move(grid), metric_options).ToJson();
    j["map_resolution_m"] = map_resolution_m;
    j["resolution_m"] = options->resolution_m.value_or(map_resolution_m);
    if (options->json) {
      streams.out << j.dump() << "\n";
      return;
    }
    TextTable table("paper map metrics — " + options->map_path);
    for (const char* key :
         {"occupied_to_free_unknown", "occupied_to_all", "unknown_to_all", "corners", "enclosed_areas", "width",
          "height", "cropped_width", "cropped_height", "resolution_m", "map_resolution_m"}) {
      table.Add(key, j.at(key).dump());
    }
    table.Add("parameters", j.at("parameters").dump());
    table.Print(streams.out);
  });
}

}  // namespace slamsweep::cli
