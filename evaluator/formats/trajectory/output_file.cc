#include "evaluator/formats/trajectory/output_file.h"

#include <fmt/format.h>

#include <fstream>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {

void WriteOutputFile(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw InputError(Located(path, 0, "cannot open for writing (does the folder exist and is it writable?)"));
  const auto remove_partial = [&] {
    out.close();
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
  };
  try {
    write(out);
  } catch (...) {
    // E.g. a planar-only format refusing a 3D pose: leave no empty or half file behind.
    remove_partial();
    throw;
  }
  out.flush();
  if (!out) {
    remove_partial();
    throw InputError(Located(path, 0, "write failed (disk full?); the partial file was removed"));
  }
}

std::string ShortestText(double value) { return fmt::format("{}", value); }

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
