#include "report/images/grey_gif_writer.h"

#include <gif_lib.h>

#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>

namespace slamsweep::report::inline images {
namespace {

/// The part of a frame that is written: a rectangle of the canvas.
struct FrameRect {
  int left = 0;
  int top = 0;
  int width = 0;
  int height = 0;
};

/// The bounding box of the pixels where `current` differs from `previous`; a single pixel
/// when nothing changed, since a GIF frame cannot be empty.
FrameRect ChangedRect(const cv::Mat& previous, const cv::Mat& current) {
  int top = current.rows;
  int bottom = -1;
  int left = current.cols;
  int right = -1;
  for (int r = 0; r < current.rows; ++r) {
    const uchar* a = previous.ptr<uchar>(r);
    const uchar* b = current.ptr<uchar>(r);
    int first = 0;
    while (first < current.cols && a[first] == b[first]) ++first;
    if (first == current.cols) continue;
    int last = current.cols - 1;
    while (a[last] == b[last]) --last;
    top = std::min(top, r);
    bottom = r;
    left = std::min(left, first);
    right = std::max(right, last);
  }
  if (bottom < 0) return {0, 0, 1, 1};
  return {left, top, right - left + 1, bottom - top + 1};
}

std::string GifErrorText(int code) {
  const char* text = GifErrorString(code);
  return text != nullptr ? text : "giflib error " + std::to_string(code);
}

/// Closes the GIF file on every path out of WriteGreyGif.
struct GifCloser {
  void operator()(GifFileType* file) const {
    int ignored = 0;
    EGifCloseFile(file, &ignored);
  }
};

void ValidateFrame(const GreyFrame& frame, std::size_t index, const cv::Size& size) {
  if (frame.image.type() != CV_8UC1 || frame.image.size() != size) {
    throw std::invalid_argument("WriteGreyGif: frame " + std::to_string(index) +
                                " is not an 8-bit grey image of the first frame's size");
  }
  if (frame.delay_cs < 0 || frame.delay_cs > 65535) {
    throw std::invalid_argument("WriteGreyGif: frame " + std::to_string(index) + " delay must be 0..65535 cs");
  }
}

}  // namespace

GifWriteOutcome WriteGreyGif(const std::vector<GreyFrame>& frames, const std::filesystem::path& gif,
                             std::optional<std::size_t> give_up_above_bytes) {
  return WriteGreyGif(
      frames.size(), [&](std::size_t i) { return frames[i]; }, gif, give_up_above_bytes);
}

GifWriteOutcome WriteGreyGif(std::size_t frame_count, const std::function<GreyFrame(std::size_t)>& frame_at,
                             const std::filesystem::path& gif, std::optional<std::size_t> give_up_above_bytes) {
  if (frame_count == 0) throw std::invalid_argument("WriteGreyGif: no frames");
  GreyFrame previous;
  GreyFrame current = frame_at(0);
  const cv::Size size = current.image.size();
  if (size.width <= 0 || size.height <= 0 || size.width > 65535 || size.height > 65535) {
    throw std::invalid_argument("WriteGreyGif: frame size must be 1..65535 pixels a side");
  }
  const std::string name = gif.string();
  const auto fail = [&](const std::string& step, int code) {
    throw std::runtime_error("cannot write GIF " + name + " (" + step + "): " + GifErrorText(code));
  };

  int error = 0;
  std::unique_ptr<GifFileType, GifCloser> file(EGifOpenFileName(name.c_str(), false, &error));
  if (!file) fail("open", error);
  EGifSetGifVersion(file.get(), true);

  std::array<GifColorType, 256> greys{};
  for (int v = 0; v < 256; ++v) {
    greys[v] = GifColorType{static_cast<GifByteType>(v), static_cast<GifByteType>(v), static_cast<GifByteType>(v)};
  }
  const std::unique_ptr<ColorMapObject, decltype(&GifFreeMapObject)> palette(GifMakeMapObject(256, greys.data()),
                                                                             &GifFreeMapObject);
  if (!palette) throw std::runtime_error("cannot write GIF " + name + ": out of memory for the palette");

  if (EGifPutScreenDesc(file.get(), size.width, size.height, 8, 0, palette.get()) == GIF_ERROR) {
    fail("screen descriptor", file->Error);
  }
  // NETSCAPE2.0 application extension: sub-block {1, loop count 0 = forever (little endian)}.
  static const GifByteType kNetscape[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
  static const GifByteType kLoopForever[] = {1, 0, 0};
  if (EGifPutExtensionLeader(file.get(), APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
      EGifPutExtensionBlock(file.get(), sizeof kNetscape, kNetscape) == GIF_ERROR ||
      EGifPutExtensionBlock(file.get(), sizeof kLoopForever, kLoopForever) == GIF_ERROR ||
      EGifPutExtensionTrailer(file.get()) == GIF_ERROR) {
    fail("loop extension", file->Error);
  }

  for (std::size_t i = 0; i < frame_count; ++i) {
    if (i > 0) {
      previous = std::move(current);
      current = frame_at(i);
    }
    ValidateFrame(current, i, size);
    const cv::Mat& image = current.image;
    const FrameRect rect = i == 0 ? FrameRect{0, 0, image.cols, image.rows} : ChangedRect(previous.image, image);
    GraphicsControlBlock control{};
    control.DisposalMode = DISPOSE_DO_NOT;
    control.UserInputFlag = false;
    control.DelayTime = current.delay_cs;
    control.TransparentColor = NO_TRANSPARENT_COLOR;
    GifByteType control_bytes[4];
    const std::size_t control_size = EGifGCBToExtension(&control, control_bytes);
    if (EGifPutExtension(file.get(), GRAPHICS_EXT_FUNC_CODE, static_cast<int>(control_size), control_bytes) ==
        GIF_ERROR) {
      fail("graphics control block", file->Error);
    }
    if (EGifPutImageDesc(file.get(), rect.left, rect.top, rect.width, rect.height, false, nullptr) == GIF_ERROR) {
      fail("image descriptor", file->Error);
    }
    for (int r = rect.top; r < rect.top + rect.height; ++r) {
      // giflib takes a non-const pointer but does not write through it.
      auto* row = const_cast<GifPixelType*>(image.ptr<GifPixelType>(r) + rect.left);
      if (EGifPutLine(file.get(), row, rect.width) == GIF_ERROR) fail("pixels", file->Error);
    }
    if (give_up_above_bytes && i + 1 < frame_count) {
      // What stdio has flushed so far: at most one buffer short of the truth, enough for a cap.
      std::error_code size_error;
      const std::uintmax_t bytes = std::filesystem::file_size(gif, size_error);
      if (!size_error && bytes > *give_up_above_bytes) {
        return {.complete = false, .frames_written = i + 1, .bytes = static_cast<std::size_t>(bytes)};
      }
    }
  }
  GifFileType* raw = file.release();
  if (EGifCloseFile(raw, &error) == GIF_ERROR) fail("close", error);
  std::error_code size_error;
  const std::uintmax_t bytes = std::filesystem::file_size(gif, size_error);
  if (size_error) throw std::runtime_error("cannot read the size of GIF " + name + ": " + size_error.message());
  return {.complete = true, .frames_written = frame_count, .bytes = static_cast<std::size_t>(bytes)};
}

}  // namespace slamsweep::report::inline images
