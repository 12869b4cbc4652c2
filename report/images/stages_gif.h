#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

namespace slamsweep::report::inline images {

struct GifOptions {
  /// Longest side of the animation, pixels (maps are only ever shrunk, never enlarged).
  int max_side_px = 480;
  /// Largest file size; frames are dropped and/or the animation shrunk until it fits.
  std::size_t max_bytes = 2 << 20;
  /// Delay of every frame but the last, and of the last (the finished map), in 1/100 s.
  int frame_delay_cs = 15;
  int last_frame_delay_cs = 150;
};

/// Throws evaluator::InputError naming the field when max_side_px < 8, max_bytes < 4096 or a
/// delay is outside 0..65535.
void ValidateGifOptions(const GifOptions& options);

/// Writes the stage maps (8-bit grey images in build order, as the worker writes them: 0
/// occupied, 254 free, 205 unknown) as a looping animated GIF of the map being built:
/// - every stage is read as grey; stages of different sizes are centred on a canvas of the
///   largest width and height, filled with map_saver's unknown grey 205 (a stage image carries
///   no origin, so centring is the best guess for a map that grows in all directions); stages that
///   all have one size are cropped to the union of their known pixels plus 2 (the canvas rule of
///   the map metrics), so padding a program adds around its map does not shrink the animation;
/// - the canvas is shrunk (area interpolation) so its longest side is at most max_side_px;
/// - 8-bit grey palette, LZW by giflib, NETSCAPE2.0 loop, a graphics control block per frame;
/// - when the file exceeds max_bytes: frames are dropped evenly (the first and last are kept)
///   down to 8, then the animation is shrunk down to 120 px, then frames are dropped down to 2,
///   then it is shrunk further, until it fits.
/// Stages are read when first needed: a long list cut down by the cap is never decoded whole
/// (a stage whose header cannot be read is decoded at once to size the canvas).
/// The GIF is written beside `gif` under a temporary name and renamed, so a reader never sees
/// a half-written file. Throws InputError naming the file for an empty list or an unreadable
/// stage image, and for bad options; std::runtime_error when the GIF cannot be written.
void WriteStagesGif(const std::vector<std::filesystem::path>& stage_images, const std::filesystem::path& gif,
                    const GifOptions& options);

/// The same GIF from a stage animation (the worker's stages.png: an animated PNG whose frames are the stage maps on
/// one canvas, as evaluator/formats/map/animated_png_reader.h reads it): every frame cropped to the union of the
/// known cells, shrunk and fitted under max_bytes by the rules above. Throws InputError naming the file when it
/// cannot be read or is not a grey animated PNG, and for bad options.
void WriteStagesGifFromAnimation(const std::filesystem::path& animation, const std::filesystem::path& gif,
                                 const GifOptions& options);

}  // namespace slamsweep::report::inline images
