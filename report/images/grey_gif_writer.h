#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <vector>

namespace slamsweep::report::inline images {

/// One frame of an animation: an 8-bit grey image (CV_8UC1) and how long it stays, in
/// hundredths of a second (the GIF unit).
struct GreyFrame {
  cv::Mat image;
  int delay_cs = 10;
};

/// Writes `frames` (all of one size) as a looping GIF89a with giflib: the NETSCAPE2.0 loop-forever
/// extension and a graphics control block per frame for its delay. Each frame after the first
/// stores only the rectangle that differs from the previous one (disposal "do not dispose"), with
/// a palette of its own: the grey levels it draws (exactly, no quantisation) and a transparent
/// entry for the pixels of the rectangle that did not change. A map being built changes little
/// between stages and has three grey levels: this keeps the file small.
/// With `give_up_above_bytes`, writing stops as soon as the file has grown past that size (checked
/// after each frame), leaving an incomplete file: a caller fitting a size cap learns early, from the
/// frames written so far, how far off it is, instead of encoding hundreds of frames in vain.
/// Throws std::invalid_argument for no frames, frames that are not CV_8UC1 or differ in size,
/// or a delay outside 0..65535; std::runtime_error naming the file and giflib's message when
/// writing fails.
struct GifWriteOutcome {
  /// False when writing stopped early (give_up_above_bytes).
  bool complete = true;
  std::size_t frames_written = 0;
  /// The file's size when writing ended (complete or not).
  std::size_t bytes = 0;
};
GifWriteOutcome WriteGreyGif(const std::vector<GreyFrame>& frames, const std::filesystem::path& gif,
                             std::optional<std::size_t> give_up_above_bytes = std::nullopt);

/// The same, with frames made on demand (`frame_at(i)` for i = 0 .. frame_count - 1, in order), so
/// that frames after an early give-up are never made, and only two are held at a time.
GifWriteOutcome WriteGreyGif(std::size_t frame_count, const std::function<GreyFrame(std::size_t)>& frame_at,
                             const std::filesystem::path& gif,
                             std::optional<std::size_t> give_up_above_bytes = std::nullopt);

}  // namespace slamsweep::report::inline images
