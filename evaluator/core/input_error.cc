#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline core {

std::string Located(const std::filesystem::path& file, std::size_t line, std::string_view message) {
  std::string out = file.string();
  if (line > 0) {
    out += ':';
    out += std::to_string(line);
  }
  out += ": ";
  out += message;
  return out;
}

}  // namespace slamsweep::evaluator::inline core
