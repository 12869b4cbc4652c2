// `slamsweep eval map-compare MAP REF`: an estimated map scored against a reference map.
#include <memory>
#include <string>

#include "cli/command.h"
#include "cli/text_table.h"
#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/map_file.h"
#include "evaluator/map_compare/map_compare.h"

namespace slamsweep::cli {

namespace ev = slamsweep::evaluator;

void RegisterEvalMapCompareCommand(CLI::App& eval, const Streams& streams) {
  struct Options {
    std::string map_path;
    std::string reference_path;
    std::string align = "none";
    ev::MapCompareOptions compare;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command =
      eval.add_subcommand("map-compare", "an estimated map against a reference map: distances, F1, IoU");
  command->add_option("MAP", options->map_path, "estimated map (ROS .yaml, MRPT .png, bare image)")->required();
  command->add_option("REF", options->reference_path, "reference map, same formats and cell size")->required();
  command
      ->add_option("--align", options->align,
                   "none: place MAP by --x/--y/--yaw (default identity); se2: refine that by ICP of occupied cells")
      ->check(CLI::IsMember({"none", "se2"}));
  command->add_option("--x", options->compare.transform.x_m, "MAP to REF translation x (m)");
  command->add_option("--y", options->compare.transform.y_m, "MAP to REF translation y (m)");
  command->add_option("--yaw", options->compare.transform.yaw_rad, "MAP to REF rotation (rad)");
  command->add_option("--radius", options->compare.match_radius_cells, "match radius for accuracy/completeness (cells)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  command->add_flag("--json", options->json, "print one JSON object instead of a table");
  command->callback([options, streams] {
    const ev::OccupancyGrid map = ev::ReadMap(options->map_path);
    const ev::OccupancyGrid reference = ev::ReadMap(options->reference_path);
    ev::MapCompareOptions compare = options->compare;
    compare.refine_with_icp = options->align == "se2";
    const ev::MapComparison result = ev::CompareMaps(map, reference, compare);
    if (options->json) {
      streams.out << result.ToJson(compare).dump(2) << "\n";
      return;
    }
    TextTable table("map " + options->map_path + " against " + options->reference_path);
    table.Add("chamfer (m)", result.chamfer_m);
    table.Add("map -> ref mean (m)", result.estimate_to_reference_mean_m);
    table.Add("map -> ref max (m)", result.estimate_to_reference_max_m);
    table.Add("ref -> map mean (m)", result.reference_to_estimate_mean_m);
    table.Add("ref -> map max (m)", result.reference_to_estimate_max_m);
    table.Add("accuracy", result.accuracy);
    table.Add("completeness", result.completeness);
    table.Add("F1", result.f1);
    table.Add("IoU occupied", result.iou_occupied);
    table.Add("IoU free", result.iou_free);
    table.Print(streams.out);
  });
}

}  // namespace slamsweep::cli
