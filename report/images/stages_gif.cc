#include "report/images/stages_gif.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <string>
#include <system_error>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/animated_png_reader.h"
#include "evaluator/formats/map/image_file.h"
#include "report/images/area_shrink.h"
#include "report/images/frame_selection.h"
#include "report/images/grey_gif_writer.h"
#include "report/images/image_header.h"
#include "report/images/map_greys.h"

namespace slamsweep::report::inline images {
namespace {

using evaluator::InputError;

constexpr std::size_t kComfortFrames = 8;
constexpr int kComfortSidePx = 120;
constexpr int kMinSidePx = 8;
/// Aim a little below the cap: the size after a change is only estimated.
constexpr double kSafety = 0.9;
/// Largest stage map accepted (and largest canvas: at most twice that), pixels: 16384 x 16384.
constexpr double kMaxStagePixels = 16384.0 * 16384.0;

/// The canvas every stage is put on: the largest width and height. Read from the file headers
/// where possible, so that long lists of large maps are never all held at full size.
cv::Size CanvasSize(const std::vector<std::filesystem::path>& paths) {
  cv::Size canvas(0, 0);
  for (const auto& path : paths) {
    const std::optional<cv::Size> size = PeekImageSize(path);
    const cv::Size known = size ? *size : evaluator::ReadGreyImageFile(path).size();
    // A corrupt header can claim any size; the canvas is allocated from it, so it is bounded.
    if (static_cast<double>(known.width) * known.height > kMaxStagePixels) {
      throw InputError(evaluator::Located(path, 0,
                                          "stage map of " + std::to_string(known.width) + " x " +
                                              std::to_string(known.height) + " pixels; expected at most " +
                                              std::to_string(static_cast<long>(kMaxStagePixels)) + " pixels"));
    }
    canvas.width = std::max(canvas.width, known.width);
    canvas.height = std::max(canvas.height, known.height);
  }
  return canvas;
}

/// The union of the known cells (plus the metrics' 2-cell margin) inside `canvas`; the whole canvas when
/// nothing is known.
cv::Rect GrownKnownWindow(const cv::Rect& known, cv::Size canvas) {
  constexpr int kMarginPx = 2;
  const cv::Rect whole(0, 0, canvas.width, canvas.height);
  if (known.empty()) return whole;
  const cv::Rect grown(known.x - kMarginPx, known.y - kMarginPx, known.width + 2 * kMarginPx,
                       known.height + 2 * kMarginPx);
  return grown & whole;
}

/// Adds a frame's known cells to `known`.
void AddKnownCells(const cv::Mat& frame, cv::Rect& known) {
  const cv::Rect box = cv::boundingRect(frame != kUnknownGrey);
  known = known.empty() ? box : (box.empty() ? known : (known | box));
}

/// Stages of one size share one frame of the world: the canvas rule crops them all to the union of
/// their known cells (plus the metrics' 2-cell margin), so the animation shows the map, not the
/// program's padding, at the scale of every other map in the report. Stages of different sizes carry
/// no origin to align them by, so they are not cropped. Returns the whole canvas when nothing is known.
cv::Rect CommonKnownWindow(const std::vector<std::filesystem::path>& paths, cv::Size canvas) {
  const cv::Rect whole(0, 0, canvas.width, canvas.height);
  cv::Rect known;
  for (const auto& path : paths) {
    const std::optional<cv::Size> size = PeekImageSize(path);
    if (!size || *size != canvas) return whole;
  }
  for (const auto& path : paths) {
    const cv::Mat stage = evaluator::ReadGreyImageFile(path);
    if (stage.size() != canvas) return whole;
    AddKnownCells(stage, known);
  }
  return GrownKnownWindow(known, canvas);
}

/// The frames a GIF is made of, each cropped to the common known window and shrunk to max_side_px.
class StageFrames {
 public:
  virtual ~StageFrames() = default;
  virtual std::size_t size() const = 0;
  /// Longer side of a frame before any further shrinking.
  virtual int SidePx() const = 0;
  virtual const cv::Mat& At(std::size_t index) = 0;
};

/// Stage images, each read only when first needed (a size cap may leave most of a long list out),
/// put on the common canvas, cropped to CommonKnownWindow and shrunk to max_side_px, then kept.
class StageFileFrames final : public StageFrames {
 public:
  StageFileFrames(const std::vector<std::filesystem::path>& paths, int max_side_px)
      : paths_(paths),
        canvas_size_(CanvasSize(paths)),
        window_(CommonKnownWindow(paths, canvas_size_)),
        max_side_px_(max_side_px),
        frames_(paths.size()) {}

  std::size_t size() const override { return paths_.size(); }
  int SidePx() const override {
    const cv::Size size = ShrunkSize(window_.size(), max_side_px_);
    return std::max(size.width, size.height);
  }

  const cv::Mat& At(std::size_t index) override {
    cv::Mat& frame = frames_[index];
    if (!frame.empty()) return frame;
    const std::filesystem::path& path = paths_[index];
    cv::Mat stage = evaluator::ReadGreyImageFile(path);
    if (stage.cols > canvas_size_.width || stage.rows > canvas_size_.height) {
      throw InputError(evaluator::Located(path, 0, "image size changed while the GIF was being made"));
    }
    if (stage.size() != canvas_size_) {
      cv::Mat canvas(canvas_size_, CV_8UC1, cv::Scalar(kUnknownGrey));
      stage.copyTo(canvas(cv::Rect((canvas_size_.width - stage.cols) / 2, (canvas_size_.height - stage.rows) / 2,
                                   stage.cols, stage.rows)));
      stage = canvas;
    }
    frame = ShrinkToFit(stage(window_), max_side_px_);
    return frame;
  }

 private:
  const std::vector<std::filesystem::path>& paths_;
  cv::Size canvas_size_;
  cv::Rect window_;
  int max_side_px_;
  std::vector<cv::Mat> frames_;
};

/// The frames of a stage animation (an animated PNG, every frame on one canvas), decoded twice: once for
/// the known window, once to keep each frame cropped and shrunk, so no full-size frame is held but one.
class AnimationFrames final : public StageFrames {
 public:
  AnimationFrames(const std::filesystem::path& animation, int max_side_px) {
    const evaluator::AnimatedGreyPngReader reader = evaluator::OpenAnimatedGreyPng(animation);
    cv::Rect known;
    reader.ForEachFrame([&](std::size_t, const cv::Mat& canvas) { AddKnownCells(canvas, known); });
    const cv::Rect window = GrownKnownWindow(known, reader.Size());
    reader.ForEachFrame(
        [&](std::size_t, const cv::Mat& canvas) { frames_.push_back(ShrinkToFit(canvas(window), max_side_px)); });
  }

  std::size_t size() const override { return frames_.size(); }
  int SidePx() const override { return std::max(frames_.front().cols, frames_.front().rows); }
  const cv::Mat& At(std::size_t index) override { return frames_[index]; }

 private:
  std::vector<cv::Mat> frames_;
};

/// Removes the temporary file unless it was renamed into place.
struct TempFileGuard {
  std::filesystem::path path;
  ~TempFileGuard() {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
  }
};

}  // namespace

void ValidateGifOptions(const GifOptions& options) {
  if (options.max_side_px < kMinSidePx) {
    throw InputError("GifOptions.max_side_px: expected at least 8 pixels, got " + std::to_string(options.max_side_px));
  }
  if (options.max_bytes < 4096) {
    throw InputError("GifOptions.max_bytes: expected at least 4096 bytes, got " + std::to_string(options.max_bytes));
  }
  if (options.frame_delay_cs < 0 || options.frame_delay_cs > 65535) {
    throw InputError("GifOptions.frame_delay_cs: expected 0..65535 (1/100 s), got " +
                     std::to_string(options.frame_delay_cs));
  }
  if (options.last_frame_delay_cs < 0 || options.last_frame_delay_cs > 65535) {
    throw InputError("GifOptions.last_frame_delay_cs: expected 0..65535 (1/100 s), got " +
                     std::to_string(options.last_frame_delay_cs));
  }
}

namespace {

/// The GIF of `stages`, fitted under options.max_bytes (WriteStagesGif's rules).
void WriteFittedGif(StageFrames& stages, const std::filesystem::path& gif, const GifOptions& options) {
  std::vector<std::size_t> indices = EvenlySpacedIndices(stages.size(), stages.size());
  int side_px = stages.SidePx();
  const TempFileGuard temp{std::filesystem::path(gif).concat(".tmp")};
  for (;;) {
    const auto frame_at = [&](std::size_t i) {
      const bool last = i + 1 == indices.size();
      return GreyFrame{ShrinkToFit(stages.At(indices[i]), side_px),
                       last ? options.last_frame_delay_cs : options.frame_delay_cs};
    };
    const GifWriteOutcome written = WriteGreyGif(indices.size(), frame_at, temp.path, options.max_bytes);
    if (written.complete && written.bytes <= options.max_bytes) break;
    // The whole file's size, extrapolated from the frames written when writing gave up early.
    const double estimated_bytes = static_cast<double>(written.bytes) * static_cast<double>(indices.size()) /
                                   static_cast<double>(written.frames_written);
    const double ratio = kSafety * static_cast<double>(options.max_bytes) / estimated_bytes;
    const auto fewer = [&](std::size_t floor_count) {
      const auto wanted = static_cast<std::size_t>(std::floor(static_cast<double>(indices.size()) * ratio));
      indices = EvenlySpacedIndices(stages.size(), std::clamp(wanted, floor_count, indices.size() - 1));
    };
    const auto smaller = [&](int floor_px) {
      const int wanted = static_cast<int>(std::floor(side_px * std::sqrt(ratio)));
      side_px = std::clamp(wanted, floor_px, side_px - 1);
    };
    if (indices.size() > kComfortFrames) {
      fewer(kComfortFrames);
    } else if (side_px > kComfortSidePx) {
      smaller(kComfortSidePx);
    } else if (indices.size() > 2) {
      fewer(2);
    } else if (side_px > kMinSidePx) {
      smaller(kMinSidePx);
    } else {
      throw std::runtime_error("cannot fit the GIF " + gif.string() + " into " + std::to_string(options.max_bytes) +
                               " bytes");
    }
  }
  std::error_code error;
  // giflib creates its file for its owner alone; a report's files are for everyone who may read the folder.
  namespace fs = std::filesystem;
  fs::permissions(temp.path,
                  fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read,
                  error);
  std::filesystem::rename(temp.path, gif, error);
  if (error) throw std::runtime_error("cannot move the GIF into place at " + gif.string() + ": " + error.message());
}

}  // namespace

void WriteStagesGif(const std::vector<std::filesystem::path>& stage_images, const std::filesystem::path& gif,
                    const GifOptions& options) {
  ValidateGifOptions(options);
  if (stage_images.empty()) throw InputError(evaluator::Located(gif, 0, "no stage images to animate"));
  StageFileFrames stages(stage_images, options.max_side_px);
  WriteFittedGif(stages, gif, options);
}

void WriteStagesGifFromAnimation(const std::filesystem::path& animation, const std::filesystem::path& gif,
                                 const GifOptions& options) {
  ValidateGifOptions(options);
  AnimationFrames stages(animation, options.max_side_px);
  WriteFittedGif(stages, gif, options);
}

}  // namespace slamsweep::report::inline images
