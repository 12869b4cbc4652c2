#include "orchestrator/worker/run_outputs.h"

#include <algorithm>
#include <cmath>
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
/// The stage animation's longer side at most and its bytes at most: a larger canvas, or an animation of more
/// bytes, is reduced by the next whole factor (up to kStageAnimationMaxFactor). Its size on disk and its
/// encoding time grow with the pixels; map.png keeps the final map at full resolution.
constexpr int kStageAnimationMaxSidePx = 256;
constexpr std::size_t kStageAnimationMaxBytes = 14 << 10;
constexpr int kStageAnimationMaxFactor = 8;

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

// Trinary greys plus this (modulo 256) order as the reduction ranks them: unknown 205 -> 0, free 254 -> 49,
// occupied 0 -> 51. A plain byte maximum then picks occupied over free over unknown, and vectorises.
constexpr std::uint8_t kRankShift = 51;

// The blocks of `reduced` (factor x factor cells of the trinary `stage` each) in the rows and columns of
// `blocks`, each the grey of the highest-ranked cell in it: walls one cell thick and the explored area stay
// visible.
void ReduceBlocks(const cv::Mat& stage, int factor, const cv::Rect& blocks, cv::Mat& reduced) {
  const int first_col = blocks.x * factor;
  const int end_col = std::min(stage.cols, (blocks.x + blocks.width) * factor);
  std::vector<std::uint8_t> ranks(static_cast<std::size_t>(end_col - first_col));
  for (int block_row = blocks.y; block_row < blocks.y + blocks.height; ++block_row) {
    std::fill(ranks.begin(), ranks.end(), std::uint8_t{0});
    const int end_row = std::min(stage.rows, (block_row + 1) * factor);
    for (int row = block_row * factor; row < end_row; ++row) {
      const std::uint8_t* in = stage.ptr<std::uint8_t>(row) + first_col;
      for (std::size_t i = 0; i < ranks.size(); ++i) {
        ranks[i] = std::max(ranks[i], static_cast<std::uint8_t>(in[i] + kRankShift));
      }
    }
    std::uint8_t* out = reduced.ptr<std::uint8_t>(block_row);
    for (int block_col = blocks.x; block_col < blocks.x + blocks.width; ++block_col) {
      const auto begin = ranks.begin() + (block_col - blocks.x) * factor;
      const auto end = std::min(begin + factor, ranks.end());
      out[block_col] = static_cast<std::uint8_t>(*std::max_element(begin, end) - kRankShift);
    }
  }
}

// The stages on their common canvas reduced by `factor`; changed[i] is the rectangle of cells stage i changed
// (evaluator::ChangedRect), and only its blocks are reduced again.
std::vector<cv::Mat> ReducedFrames(const std::vector<cv::Mat>& frames, const std::vector<cv::Rect>& changed,
                                   int factor) {
  if (factor <= 1) return frames;
  const cv::Mat& first = frames.front();
  std::vector<cv::Mat> reduced;
  reduced.reserve(frames.size());
  reduced.emplace_back((first.rows + factor - 1) / factor, (first.cols + factor - 1) / factor, CV_8UC1);
  ReduceBlocks(first, factor, cv::Rect(0, 0, reduced.back().cols, reduced.back().rows), reduced.back());
  for (std::size_t i = 1; i < frames.size(); ++i) {
    reduced.push_back(reduced.back().clone());
    const cv::Rect& cells = changed[i];
    if (cells.empty()) continue;
    const cv::Rect blocks(cells.x / factor, cells.y / factor,
                          (cells.x + cells.width - 1) / factor - cells.x / factor + 1,
                          (cells.y + cells.height - 1) / factor - cells.y / factor + 1);
    ReduceBlocks(frames[i], factor, blocks, reduced.back());
  }
  return reduced;
}

// The stage animation: the stages on their common canvas, reduced by the smallest whole factor that brings
// its longer side within kStageAnimationMaxSidePx and, while it can, its bytes within kStageAnimationMaxBytes.
std::string StageAnimation(const std::vector<cv::Mat>& stages) {
  const std::vector<cv::Mat> frames = OnCommonCanvas(stages);
  std::vector<cv::Rect> changed(frames.size());
  for (std::size_t i = 1; i < frames.size(); ++i) changed[i] = ev::ChangedRect(frames[i - 1], frames[i]);
  const int side = std::max(frames.front().cols, frames.front().rows);
  int factor = std::max(1, (side + kStageAnimationMaxSidePx - 1) / kStageAnimationMaxSidePx);
  std::string animation = ev::EncodeAnimatedGreyPng(ReducedFrames(frames, changed, factor));
  while (animation.size() > kStageAnimationMaxBytes && factor < kStageAnimationMaxFactor && side / factor > 1) {
    // The bytes of a stage animation fall about as factor^1.5 (the stages of bench/scale): the factor expected
    // to fit, so that most animations are encoded at most twice.
    const double over = static_cast<double>(animation.size()) / static_cast<double>(kStageAnimationMaxBytes);
    const int expected = static_cast<int>(std::ceil(factor * std::pow(over, 1.0 / 1.5)));
    factor = std::min(kStageAnimationMaxFactor, std::max(factor + 1, expected));
    animation = ev::EncodeAnimatedGreyPng(ReducedFrames(frames, changed, factor));
  }
  return animation;
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
    ev::WriteBinaryFile(paths.StageAnimation(), StageAnimation(collected.stages));
    outputs["stage_animation"] = paths.StageAnimation().filename().string();
    outputs["stage_count"] = collected.stages.size();
  }

  std::error_code error;
  if (fs::is_regular_file(paths.Log(), error)) outputs["log"] = paths.Log().filename().string();
  return outputs;
}

}  // namespace slamsweep::orchestrator::inline worker
