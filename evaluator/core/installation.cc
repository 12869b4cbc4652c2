#include "evaluator/core/installation.h"

#include <cstdlib>
#include <system_error>

namespace slamsweep::evaluator {
namespace fs = std::filesystem;

std::vector<fs::path> LibexecSearchDirs() {
  const char* configured = std::getenv("SLAMSWEEP_LIBEXEC_DIR");
  if (configured != nullptr && *configured != '\0') return {fs::path(configured)};
  std::vector<fs::path> dirs;
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    dirs.push_back(program.parent_path());
    dirs.push_back((program.parent_path() / ".." / "lib" / "slamsweep").lexically_normal());
  }
  // SLAMSWEEP_BUILD_LIBEXEC_DIR: set by CMake for this file only (evaluator/core/CMakeLists.txt).
  const fs::path build_dir(SLAMSWEEP_BUILD_LIBEXEC_DIR);
  bool listed = false;
  for (const fs::path& dir : dirs) listed = listed || dir == build_dir;
  if (!listed) dirs.push_back(build_dir);
  return dirs;
}

std::optional<fs::path> FindLibexecFile(std::string_view name) {
  for (const fs::path& dir : LibexecSearchDirs()) {
    std::error_code error;
    const fs::path candidate = dir / name;
    if (fs::is_regular_file(candidate, error)) return candidate;
  }
  return std::nullopt;
}

std::optional<fs::path> FindInstalledData(std::string_view relative) {
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (error) return std::nullopt;
  for (const char* up : {"..", "../.."}) {
    const fs::path candidate = (program.parent_path() / up / "share" / "slamsweep" / relative).lexically_normal();
    if (fs::exists(candidate, error)) return candidate;
  }
  return std::nullopt;
}

std::string DescribeLibexecSearch() {
  std::string text = "looked in ";
  const std::vector<fs::path> dirs = LibexecSearchDirs();
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    if (i > 0) text += i + 1 == dirs.size() ? " and " : ", ";
    text += dirs[i].string();
  }
  return text + " (set SLAMSWEEP_LIBEXEC_DIR to choose the folder)";
}

}  // namespace slamsweep::evaluator
