#include "orchestrator/config/program_path.h"

#include <unistd.h>

#include <cstdlib>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator::inline config {
namespace {

bool IsExecutableFile(const std::filesystem::path& path) {
  std::error_code error;
  return std::filesystem::is_regular_file(path, error) && ::access(path.c_str(), X_OK) == 0;
}

}  // namespace

std::filesystem::path ResolveProgram(std::string_view program, const std::filesystem::path& base_dir) {
  const std::string name(program);
  if (name.find('/') == std::string::npos) {
    const char* path_variable = std::getenv("PATH");
    const std::string folders = path_variable != nullptr ? path_variable : "";
    std::size_t start = 0;
    while (start <= folders.size()) {
      std::size_t end = folders.find(':', start);
      if (end == std::string::npos) end = folders.size();
      // An empty PATH entry means the current folder, as for execvp.
      const std::filesystem::path folder = end == start ? std::string(".") : folders.substr(start, end - start);
      const std::filesystem::path candidate = folder / name;
      if (IsExecutableFile(candidate)) return std::filesystem::absolute(candidate).lexically_normal();
      start = end + 1;
    }
    throw evaluator::InputError("program '" + name + "' not found in PATH (" + folders +
                                "); give its full path or install it");
  }
  std::filesystem::path path = name;
  if (path.is_relative()) path = base_dir / path;
  path = std::filesystem::absolute(path).lexically_normal();
  std::error_code error;
  if (!std::filesystem::exists(path, error)) throw evaluator::InputError("program " + path.string() + ": no such file");
  if (!std::filesystem::is_regular_file(path, error)) {
    throw evaluator::InputError("program " + path.string() + ": not a regular file");
  }
  if (::access(path.c_str(), X_OK) != 0) {
    throw evaluator::InputError("program " + path.string() + ": not executable (chmod +x it)");
  }
  return path;
}

}  // namespace slamsweep::orchestrator::inline config
