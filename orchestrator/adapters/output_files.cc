#include "orchestrator/adapters/output_files.h"

#include <fnmatch.h>

#include <algorithm>
#include <cctype>
#include <utility>
#include <system_error>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/map_file.h"
#include "orchestrator/run/run_failure.h"

namespace slamsweep::orchestrator::inline adapters {

namespace ev = slamsweep::evaluator;
namespace fs = std::filesystem;

std::string RunRelative(const RunPaths& paths, const fs::path& file) {
  const fs::path relative = file.lexically_relative(paths.root);
  if (relative.empty() || relative.begin()->string() == "..") return file.string();
  return relative.string();
}

void RequireOutputFile(const RunPaths& paths, const fs::path& file, std::string_view what) {
  std::error_code error;
  if (!fs::is_regular_file(file, error)) {
    throw RunFailure(FailureKind::kMissingOutput,
                     "no " + std::string(what) + ": " + RunRelative(paths, file) + " missing");
  }
}

namespace {

/// The reader's message names the absolute path; the run-relative one is shorter and stable.
std::string Shortened(const RunPaths& paths, std::string message) {
  const std::string root = paths.root.string() + "/";
  for (std::size_t at = message.find(root); at != std::string::npos; at = message.find(root, at)) {
    message.erase(at, root.size());
  }
  return message;
}

}  // namespace

ev::OccupancyGrid ReadMapOutput(const RunPaths& paths, const fs::path& file, std::string_view what,
                                const ev::MapReadOptions& options) {
  RequireOutputFile(paths, file, what);
  try {
    return ev::ReadMap(file, options);
  } catch (const ev::InputError& error) {
    throw RunFailure(FailureKind::kCorruptOutput,
                     "corrupt " + std::string(what) + ": " + Shortened(paths, error.what()));
  }
}

ev::Trajectory ReadTrajectoryOutput(const RunPaths& paths, const fs::path& file, ev::TrajectoryFormat format,
                                    const ev::TrajectoryReadOptions& options, std::vector<std::string>& warnings) {
  RequireOutputFile(paths, file, "trajectory");
  try {
    ev::TrajectoryFile read = ev::ReadTrajectoryFile(file, format, options);
    for (std::string& warning : read.warnings) warnings.push_back(Shortened(paths, std::move(warning)));
    if (read.trajectory.empty()) {
      throw RunFailure(FailureKind::kCorruptOutput,
                       "corrupt trajectory: " + RunRelative(paths, file) + " holds no pose");
    }
    return std::move(read.trajectory);
  } catch (const ev::InputError& error) {
    throw RunFailure(FailureKind::kCorruptOutput, "corrupt trajectory: " + Shortened(paths, error.what()));
  }
}

std::vector<fs::path> GlobFiles(const fs::path& dir, const std::string& pattern) {
  std::vector<std::pair<std::string, fs::path>> matches;
  std::error_code error;
  if (!fs::is_directory(dir, error)) return {};
  for (fs::recursive_directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
    if (!it->is_regular_file(error)) continue;
    const std::string relative = it->path().lexically_relative(dir).string();
    if (::fnmatch(pattern.c_str(), relative.c_str(), FNM_PATHNAME) == 0) matches.emplace_back(relative, it->path());
  }
  std::sort(matches.begin(), matches.end());
  std::vector<fs::path> files;
  files.reserve(matches.size());
  for (auto& [relative, path] : matches) files.push_back(std::move(path));
  return files;
}

std::string SafeFileStem(std::string_view name) {
  std::string stem;
  for (const char c : name) {
    const bool safe = std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.' || c == '-';
    if (stem.empty() && c == '.') continue;
    stem += safe ? c : '_';
  }
  return stem.empty() ? "sequence" : stem;
}

std::vector<double> ScanStamps(std::span<const ev::LaserScan> scans) {
  std::vector<double> stamps;
  stamps.reserve(scans.size());
  for (const ev::LaserScan& scan : scans) stamps.push_back(scan.stamp_s);
  return stamps;
}

}  // namespace slamsweep::orchestrator::inline adapters
