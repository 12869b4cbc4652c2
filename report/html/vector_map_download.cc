#include "report/html/vector_map_download.h"

#include <fstream>

#include "evaluator/borders/vector_map.h"
#include "evaluator/borders/vector_map_export.h"
#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/map_file.h"

namespace slamsweep::report::inline html {

namespace ev = slamsweep::evaluator;

void WriteVectorMapDownload(const std::filesystem::path& map_yaml, const std::filesystem::path& out) {
  const ev::VectorMap vector_map = ev::Vectorize(ev::ReadMap(map_yaml), ev::VectorizeOptions{});
  std::ofstream file(out, std::ios::binary | std::ios::trunc);
  if (!file) throw ev::InputError(out.string() + ": cannot open for writing");
  ev::WriteGeoJson(vector_map, file);
  file.close();
  if (!file) throw ev::InputError(out.string() + ": write failed");
}

}  // namespace slamsweep::report::inline html
