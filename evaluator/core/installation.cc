#include "evaluator/core/installation.h"

#include <sys/auxv.h>

#include <cstdlib>
#include <system_error>

namespace slamsweep::evaluator::inline core {
namespace fs = std::filesystem;
namespace {

/// The working folder when this program started, before main can change it: AT_EXECFN may be relative to it.
const fs::path g_start_dir = [] {
  std::error_code error;
  return fs::current_path(error);
}();

}  // namespace

fs::path RunningProgram() {
  std::error_code error;
  if (fs::path program = fs::read_symlink("/proc/self/exe", error); !error) return program;
  const auto* started_as = reinterpret_cast<const char*>(::getauxval(AT_EXECFN));
  if (started_as == nullptr || *started_as == '\0') return {};
  const fs::path program = fs::path(started_as).is_absolute() ? fs::path(started_as) : g_start_dir / started_as;
  const fs::path resolved = fs::canonical(program, error);
  return error ? fs::path() : resolved;
}

std::vector<fs::path> LibexecSearchDirs() {
  const char* configured = std::getenv("SLAMSWEEP_LIBEXEC_DIR");
  if (configured != nullptr && *configured != '\0') return {fs::path(configured)};
  std::vector<fs::path> dirs;
  if (const fs::path program = RunningProgram(); !program.empty()) {
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
  const fs::path program = RunningProgram();
  if (program.empty()) return std::nullopt;
  std::error_code error;
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

}  // namespace slamsweep::evaluator::inline core
