#include "orchestrator/worker/run_outputs.h"

#include <algorithm>
#include <filesystem>
#include <optional>

#include <opencv2/core.hpp>

#include "evaluator/formats/map/compact_png.h"
#include "evaluator/formats/map/image_file.h"
#include "evaluator/formats/map/map_server_format.h"
#include "evaluator/formats/trajectory/output_file.h"
#include "evaluator/formats/trajectory/tum_format.h"
#include "orchestrator/phase_times/phase_times.h"

namespace slamsweep::orchestrator::inline worker {

namespace ev = slamsweep::evaluator;
namespace fs = std::filesystem;

namespace {

constexpr int kUnknownGrey = 205;

// The stages on one canvas of the largest width and height, smaller ones centred on unknown cells (a
// stage image carries no origin to align it by; the report's animations have always centred them).
std::vector<cv::Mat> OnCommonCanvas(const std::vector<cv::Mat>& stages) {
  cv::Size canvas(0, 0);
  for (const cv::Mat& stage : stages) {
    canvas.width = std::max(canvas.width, stage.cols);
    canvas.height = std::max(canvas.height, stage.rows);
  }
  std::vector<cv::Mat> placed;
  placed.reserve(stages.size());
  for (const cv::Mat& stage : stages) {
    if (stage.size() == canvas) {
      placed.push_back(stage);
      continue;
    }
    cv::Mat frame(canvas, CV_8UC1, cv::Scalar(kUnknownGrey));
    stage.copyTo(
        frame(cv::Rect((canvas.width - stage.cols) / 2, (canvas.height - stage.rows) / 2, stage.cols, stage.rows)));
    placed.push_back(frame);
  }
  return placed;
}

}  // namespace

nlohmann::json WriteRunOutputs(const RunPaths& paths, const CollectedOutputs& collected,
                               const ev::Trajectory* reference) {
  nlohmann::json outputs = nlohmann::json::object();
  std::optional<PhaseTimer> phase(std::in_place, "outputs_map");
  ev::MapWriteOptions map_options;
  map_options.trinary_png = true;
  ev::WriteMapServer(collected.map, paths.MapYaml(), map_options);
  outputs["map"] = paths.MapYaml().filename().string();
  phase.emplace("outputs_trajectories");
  if (collected.trajectory) {
    ev::WriteTum(*collected.trajectory, paths.TrajectoryTum());
    outputs["trajectory"] = paths.TrajectoryTum().filename().string();
  }
  if (reference) {
    ev::WriteTum(*reference, paths.ReferenceTum());
    outputs["reference"] = paths.ReferenceTum().filename().string();
  }

  // One file for every stage: each change of the map is stored once, not once per stage image.
  phase.emplace("outputs_stages");
  outputs["stages"] = nlohmann::json::array();
  if (!collected.stages.empty()) {
    ev::WriteBinaryFile(paths.StageAnimation(), ev::EncodeAnimatedGreyPng(OnCommonCanvas(collected.stages)));
    outputs["stage_animation"] = paths.StageAnimation().filename().string();
    outputs["stage_count"] = collected.stages.size();
  }

  std::error_code error;
  if (fs::is_regular_file(paths.Log(), error)) outputs["log"] = paths.Log().filename().string();
  return outputs;
}

}  // namespace slamsweep::orchestrator::inline worker
