// `slamsweep vectorize`: obstacle borders as polygons (GeoJSON or SVG, world metres).
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "cli/command.h"
#include "cli/text_table.h"
#include "evaluator/borders/vector_map.h"
#include "evaluator/borders/vector_map_export.h"
#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/map_file.h"

namespace slamsweep::cli {

namespace ev = slamsweep::evaluator;

void RegisterVectorizeCommand(CLI::App& app, const Streams& streams) {
  struct Options {
    std::string map_path;
    double threshold = 75.0;
    double tolerance_cells = 1.0;
    std::optional<int> unknown_value;
    std::string output_path;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand("vectorize", "trace obstacle borders and export polygons");
  command->add_option("MAP", options->map_path, "map file (as for `eval map`)")->required();
  command->add_option("--threshold", options->threshold, "obstacle when occupancy (0-100) exceeds this")
      ->required()
      ->check(CLI::Range(0.0, 100.0));
  command->add_option("--tolerance-cells", options->tolerance_cells, "Douglas-Peucker tolerance (cells)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  command->add_option("--unknown-value", options->unknown_value, "unknown grey value of a bare PGM/PNG")
      ->check(CLI::Range(0, 255));
  command->add_option("-o,--output", options->output_path, "OUT.geojson or OUT.svg")->required();
  command->add_flag("--json", options->json, "print the statistics as one JSON object");
  command->callback([options, streams] {
    const std::filesystem::path output = options->output_path;
    const std::string extension = output.extension().string();
    if (extension != ".geojson" && extension != ".json" && extension != ".svg") {
      throw ev::InputError("--output " + output.string() + ": expected a .geojson or .svg file name");
    }
    ev::MapReadOptions read_options;
    read_options.unknown_value = options->unknown_value;
    const ev::OccupancyGrid grid = ev::ReadMap(options->map_path, read_options);
    ev::VectorizeOptions vectorize_options;
    vectorize_options.threshold = options->threshold;
    vectorize_options.simplify_tolerance_cells = options->tolerance_cells;
    const ev::VectorMap vector_map = ev::Vectorize(grid, vectorize_options);
    std::ofstream out(output);
    if (!out) throw ev::InputError(output.string() + ": cannot open for writing");
    if (extension == ".svg") {
      ev::WriteSvg(vector_map, out);
    } else {
      ev::WriteGeoJson(vector_map, out);
    }
    out.close();
    if (!out) throw ev::InputError(output.string() + ": write failed");
    const nlohmann::json stats = vector_map.StatsJson();
    if (options->json) {
      streams.out << stats.dump() << "\n";
      return;
    }
    TextTable table("vector map — " + output.string());
    for (const auto& [key, value] : stats.items()) table.Add(key, value.dump());
    table.Print(streams.out);
  });
}

}  // namespace slamsweep::cli
