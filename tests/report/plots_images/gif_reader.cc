#include "tests/report/plots_images/gif_reader.h"

#include <gif_lib.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

namespace slamsweep::report::gif_check {
namespace {

int ReadFromFile(GifFileType* gif, GifByteType* bytes, int count) {
  return static_cast<int>(std::fread(bytes, 1, static_cast<std::size_t>(count), static_cast<FILE*>(gif->UserData)));
}

}  // namespace

DecodedGif DecodeGif(const std::filesystem::path& path) {
  DecodedGif decoded;
  FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) {
    ADD_FAILURE() << "cannot open " << path;
    return decoded;
  }
  int error = 0;
  GifFileType* gif = DGifOpen(file, &ReadFromFile, &error);
  if (gif == nullptr) {
    std::fclose(file);
    ADD_FAILURE() << "not a GIF: " << path << ": " << GifErrorString(error);
    return decoded;
  }
  if (DGifSlurp(gif) != GIF_OK) {
    ADD_FAILURE() << "GIF does not decode: " << path << ": " << GifErrorString(gif->Error);
  }
  decoded.width = gif->SWidth;
  decoded.height = gif->SHeight;
  cv::Mat canvas(decoded.height, decoded.width, CV_8UC1, cv::Scalar(0));
  for (int i = 0; i < gif->ImageCount; ++i) {
    const SavedImage& image = gif->SavedImages[i];
    for (int e = 0; e < image.ExtensionBlockCount; ++e) {
      const ExtensionBlock& block = image.ExtensionBlocks[e];
      if (block.Function == APPLICATION_EXT_FUNC_CODE && block.ByteCount == 11 &&
          std::memcmp(block.Bytes, "NETSCAPE2.0", 11) == 0 && e + 1 < image.ExtensionBlockCount) {
        const ExtensionBlock& data = image.ExtensionBlocks[e + 1];
        decoded.loops_forever = data.ByteCount == 3 && data.Bytes[0] == 1 && data.Bytes[1] == 0 && data.Bytes[2] == 0;
      }
    }
    GraphicsControlBlock control{};
    control.TransparentColor = NO_TRANSPARENT_COLOR;
    decoded.delays_cs.push_back(DGifSavedExtensionToGCB(gif, i, &control) == GIF_OK ? control.DelayTime : -1);
    const GifImageDesc& desc = image.ImageDesc;
    // The frame's own palette, else the file's; every colour must be grey. Transparent pixels keep what is
    // under them (disposal "do not dispose" is the only one our GIFs use).
    const ColorMapObject* palette = desc.ColorMap != nullptr ? desc.ColorMap : gif->SColorMap;
    if (palette == nullptr) {
      ADD_FAILURE() << "frame " << i << " has no palette";
      break;
    }
    for (int v = 0; v < palette->ColorCount; ++v) {
      const GifColorType c = palette->Colors[v];
      if (v != control.TransparentColor && (c.Red != c.Green || c.Red != c.Blue)) {
        ADD_FAILURE() << "frame " << i << ": palette entry " << v << " is not grey";
        break;
      }
    }
    for (int r = 0; r < desc.Height; ++r) {
      for (int c = 0; c < desc.Width; ++c) {
        const int index = image.RasterBits[r * desc.Width + c];
        if (index == control.TransparentColor) continue;
        if (index >= palette->ColorCount) {
          ADD_FAILURE() << "frame " << i << ": index " << index << " past the palette";
          continue;
        }
        canvas.at<uchar>(desc.Top + r, desc.Left + c) = palette->Colors[index].Red;
      }
    }
    decoded.canvases.push_back(canvas.clone());
  }
  DGifCloseFile(gif, &error);
  std::fclose(file);
  return decoded;
}

}  // namespace slamsweep::report::gif_check
