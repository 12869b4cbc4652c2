// Bare map images (PGM P2/P5, PNG) read as maps (ReadMap: the image decoders, grey checks, cells): the input
// is written as map.png when it starts with the PNG signature, else as map.pgm.
#include <opencv2/core.hpp>

#include "evaluator/formats/map/map_file.h"
#include "evaluator/formats/map/png_image.h"
#include "evaluator/formats/map/pnm_image.h"
#include "tests/fuzz/fuzz_support.h"

namespace ev = slamsweep::evaluator;
namespace fuzz = slamsweep::fuzz;

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  cv::Mat grey(24, 32, CV_8UC1, cv::Scalar(254));
  grey.row(0).setTo(0);
  grey.col(5).setTo(0);
  grey(cv::Rect(10, 10, 6, 6)).setTo(205);
  seeds.Add("grey.pgm", ev::EncodePgm(grey, "seed"));
  seeds.Add("grey.png", ev::EncodePngBytes(grey));
  seeds.Add("palette.png", ev::EncodeGreyPalettePng(grey));
  cv::Mat colour(8, 8, CV_8UC3, cv::Scalar(10, 20, 30));
  seeds.Add("colour.png", ev::EncodePngBytes(colour));
  cv::Mat grey_rgba(8, 8, CV_8UC4, cv::Scalar(100, 100, 100, 255));
  seeds.Add("grey-rgba.png", ev::EncodePngBytes(grey_rgba));
  seeds.Add("ascii.pgm", "P2\n# a comment\n3 2\n15\n0 7 15\n15 7 0\n");
  seeds.Add("colour.ppm", "P6\n2 1\n255\n\x01\x02\x03\x04\x05\x06");
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes = fuzz::Bytes(data, size);
  const std::filesystem::path file = fuzz::WriteInput(ev::LooksLikePng(bytes) ? "map.png" : "map.pgm", bytes);
  ev::MapReadOptions options;
  options.unknown_value = 205;
  fuzz::ExpectReadOrInputError({file}, [&] { ev::ReadMap(file, options); });
  return 0;
}
