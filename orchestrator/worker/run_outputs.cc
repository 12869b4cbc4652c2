#include "orchestrator/worker/run_outputs.h"

#include <algorithm>
#include <cstdint>
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
constexpr int kFreeGrey = 254;
constexpr int kOccupiedGrey = 0;
/// The stage animation's longer side at most: a larger canvas is reduced by a whole factor (its size on
/// disk and its encoding time grow with the pixels; map.png keeps the final map at full resolution).
constexpr int kStageAnimationMaxSidePx = 400;

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

// A trinary stage reduced by `factor` on each side: a pixel of the result is occupied when a cell of its block
// is, else free when one is, else unknown (walls one cell thick and the explored area stay visible).
cv::Mat ReducedStage(const cv::Mat& stage, int factor) {
  cv::Mat reduced((stage.rows + factor - 1) / factor, (stage.cols + factor - 1) / factor, CV_8UC1,
                  cv::Scalar(kUnknownGrey));
  for (int row = 0; row < stage.rows; ++row) {
    const std::uint8_t* in = stage.ptr<std::uint8_t>(row);
    std::uint8_t* out = reduced.ptr<std::uint8_t>(row / factor);
    for (int col = 0; col < stage.cols; ++col) {
      std::uint8_t& pixel = out[col / factor];
      if (in[col] == kOccupiedGrey || pixel == kOccupiedGrey) {
        pixel = kOccupiedGrey;
      } else if (in[col] == kFreeGrey) {
        pixel = kFreeGrey;
      } else if (pixel != kFreeGrey) {
        pixel = in[col];
      }
    }
  }
  return reduced;
}

// The stages on their common canvas, reduced by the smallest whole factor that brings its longer side
// within kStageAnimationMaxSidePx.
std::vector<cv::Mat> AnimationFrames(const std::vector<cv::Mat>& stages) {
  std::vector<cv::Mat> frames = OnCommonCanvas(stages);
  const int side = std::max(frames.front().cols, frames.front().rows);
  const int factor = (side + kStageAnimationMaxSidePx - 1) / kStageAnimationMaxSidePx;
  if (factor <= 1) return frames;
  for (cv::Mat& frame : frames) frame = ReducedStage(frame, factor);
  return frames;
}

}  // namespace

nlohmann::json WriteRunOutputs(const RunPaths& paths, const CollectedOutputs& collected,
                               const ev::Trajectory* reference, ev::OccupancyGrid* written_map) {
  nlohmann::json outputs = nlohmann::json::object();
  std::optional<PhaseTimer> phase(std::in_place, "outputs_map");
  ev::MapWriteOptions map_options;
  map_options.trinary_png = true;
  if (written_map != nullptr) {
    *written_map = ev::WriteMapServerAndReadBack(collected.map, paths.MapYaml(), map_options);
  } else {
    ev::WriteMapServer(collected.map, paths.MapYaml(), map_options);
  }
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
    ev::WriteBinaryFile(paths.StageAnimation(), ev::EncodeAnimatedGreyPng(AnimationFrames(collected.stages)));
    outputs["stage_animation"] = paths.StageAnimation().filename().string();
    outputs["stage_count"] = collected.stages.size();
  }

  std::error_code error;
  if (fs::is_regular_file(paths.Log(), error)) outputs["log"] = paths.Log().filename().string();
  return outputs;
}

}  // namespace slamsweep::orchestrator::inline worker
