#include "orchestrator/worker/run_outputs.h"

#include <cstdio>
#include <filesystem>

#include "evaluator/borders/vector_map.h"
#include "evaluator/borders/vector_map_export.h"
#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/image_file.h"
#include "evaluator/formats/map/map_server_format.h"
#include "evaluator/formats/map/png_image.h"
#include "evaluator/formats/trajectory/output_file.h"
#include "evaluator/formats/trajectory/tum_format.h"

namespace slamsweep::orchestrator {

namespace ev = slamsweep::evaluator;
namespace fs = std::filesystem;

nlohmann::json WriteRunOutputs(const RunPaths& paths, const CollectedOutputs& collected,
                               const ev::Trajectory* reference, std::vector<std::string>& warnings) {
  nlohmann::json outputs = nlohmann::json::object();
  ev::WriteMapServer(collected.map, paths.MapYaml());
  outputs["map"] = paths.MapYaml().filename().string();
  if (collected.trajectory) {
    ev::WriteTum(*collected.trajectory, paths.TrajectoryTum());
    outputs["trajectory"] = paths.TrajectoryTum().filename().string();
  }
  if (reference) {
    ev::WriteTum(*reference, paths.ReferenceTum());
    outputs["reference"] = paths.ReferenceTum().filename().string();
  }

  nlohmann::json stages = nlohmann::json::array();
  if (!collected.stages.empty()) fs::create_directories(paths.StagesDir());
  for (std::size_t i = 0; i < collected.stages.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof(name), "stage_%04zu.png", i);
    ev::WriteBinaryFile(paths.StagesDir() / name, ev::EncodeGreyPalettePng(collected.stages[i]));
    stages.push_back("stages/" + std::string(name));
  }
  outputs["stages"] = stages;

  try {
    const ev::VectorMap vector_map = ev::Vectorize(collected.map, ev::VectorizeOptions{});
    ev::WriteOutputFile(paths.GeoJson(), [&](std::ostream& out) { ev::WriteGeoJson(vector_map, out); });
    outputs["vector_map"] = paths.GeoJson().filename().string();
  } catch (const ev::InputError& error) {
    warnings.push_back(std::string("vector map: ") + error.what());
  }

  std::error_code error;
  if (fs::is_regular_file(paths.Log(), error)) outputs["log"] = paths.Log().filename().string();
  return outputs;
}

}  // namespace slamsweep::orchestrator
