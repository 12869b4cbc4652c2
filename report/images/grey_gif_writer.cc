#include "report/images/grey_gif_writer.h"

#include <gif_lib.h>

#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

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

/// A frame's own palette: the grey levels its rectangle draws, in ascending order, and after them the
/// transparent entry that pixels unchanged since the frame before get (they keep what is under them), so
/// that a map's unchanged cells cost next to nothing and a trinary map is coded on 2 bits, not 8. Padded to
/// a power of two (GIF's rule). Without room for a transparent entry (all 256 levels drawn), none.
struct FramePalette {
  std::array<GifPixelType, 256> index_of{};
  std::vector<GifColorType> colours;
  int entries = 0;
  int transparent = NO_TRANSPARENT_COLOR;
};

FramePalette PaletteOf(const cv::Mat& image, const FrameRect& rect, const cv::Mat* previous) {
  std::array<bool, 256> drawn{};
  for (int r = rect.top; r < rect.top + rect.height; ++r) {
    const uchar* row = image.ptr<uchar>(r) + rect.left;
    const uchar* before = previous != nullptr ? previous->ptr<uchar>(r) + rect.left : nullptr;
    for (int c = 0; c < rect.width; ++c) {
      if (before == nullptr || before[c] != row[c]) drawn[row[c]] = true;
    }
  }
  FramePalette palette;
  for (int level = 0; level < 256; ++level) {
    if (!drawn[static_cast<std::size_t>(level)]) continue;
    palette.index_of[static_cast<std::size_t>(level)] = static_cast<GifPixelType>(palette.colours.size());
    const auto grey = static_cast<GifByteType>(level);
    palette.colours.push_back(GifColorType{grey, grey, grey});
  }
  if (previous != nullptr && palette.colours.size() < 256) {
    palette.transparent = static_cast<int>(palette.colours.size());
    palette.colours.push_back(GifColorType{0, 0, 0});
  }
  // At least 2 entries (1 bit), a power of two.
  palette.entries = 2;
  while (palette.entries < static_cast<int>(palette.colours.size())) palette.entries *= 2;
  palette.colours.resize(static_cast<std::size_t>(palette.entries), GifColorType{0, 0, 0});
  return palette;
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

  // No global palette: each frame has its own (below), of the grey levels it draws.
  if (EGifPutScreenDesc(file.get(), size.width, size.height, 8, 0, nullptr) == GIF_ERROR) {
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

  std::vector<GifPixelType> indices;
  for (std::size_t i = 0; i < frame_count; ++i) {
    if (i > 0) {
      previous = std::move(current);
      current = frame_at(i);
    }
    ValidateFrame(current, i, size);
    const cv::Mat& image = current.image;
    const FrameRect rect = i == 0 ? FrameRect{0, 0, image.cols, image.rows} : ChangedRect(previous.image, image);
    const FramePalette palette = PaletteOf(image, rect, i == 0 ? nullptr : &previous.image);
    GraphicsControlBlock control{};
    control.DisposalMode = DISPOSE_DO_NOT;
    control.UserInputFlag = false;
    control.DelayTime = current.delay_cs;
    control.TransparentColor = palette.transparent;
    GifByteType control_bytes[4];
    const std::size_t control_size = EGifGCBToExtension(&control, control_bytes);
    if (EGifPutExtension(file.get(), GRAPHICS_EXT_FUNC_CODE, static_cast<int>(control_size), control_bytes) ==
        GIF_ERROR) {
      fail("graphics control block", file->Error);
    }
    const std::unique_ptr<ColorMapObject, decltype(&GifFreeMapObject)> colours(
        GifMakeMapObject(palette.entries, palette.colours.data()), &GifFreeMapObject);
    if (!colours) throw std::runtime_error("cannot write GIF " + name + ": out of memory for a palette");
    if (EGifPutImageDesc(file.get(), rect.left, rect.top, rect.width, rect.height, false, colours.get()) == GIF_ERROR) {
      fail("image descriptor", file->Error);
    }
    indices.resize(static_cast<std::size_t>(rect.width));
    for (int r = rect.top; r < rect.top + rect.height; ++r) {
      const uchar* row = image.ptr<uchar>(r) + rect.left;
      const uchar* before = i == 0 ? nullptr : previous.image.ptr<uchar>(r) + rect.left;
      for (int c = 0; c < rect.width; ++c) {
        indices[static_cast<std::size_t>(c)] = before != nullptr && palette.transparent >= 0 && before[c] == row[c]
                                                   ? static_cast<GifPixelType>(palette.transparent)
                                                   : palette.index_of[row[c]];
      }
      if (EGifPutLine(file.get(), indices.data(), rect.width) == GIF_ERROR) fail("pixels", file->Error);
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
