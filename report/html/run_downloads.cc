#include "report/html/run_downloads.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <optional>
#include <system_error>

#include "report/html/safe_name.h"
#include "report/html/site_files.h"

namespace slamsweep::report::inline html {
namespace {

namespace fs = std::filesystem;

// Files of a run folder (orchestrator/DESIGN.md) offered for download, in display order. Fixed
// names only: paths named inside result.json are not trusted to stay inside the run folder.
constexpr const char* kDownloads[] = {
    "map.png",    "map.pgm", "map.yaml",    "trajectory.tum", "reference.tum", "map.geojson",     "stages.png",
    "stages.gif", "log.txt", "command.txt", "run.json",       "result.json",   "rpe_segments.csv"};

bool IsSafeRelative(const std::string& text) {
  const fs::path path(text);
  if (text.empty() || path.is_absolute()) return false;
  for (const fs::path& part : path) {
    if (part == "..") return false;
  }
  return true;
}

// The run's stage animation (one animated PNG of every stage), when its folder has one.
std::optional<fs::path> StageAnimation(const RunRecord& run) {
  const std::string& name = run.outputs.stage_animation;
  if (name.empty() || !IsSafeRelative(name) || !IsRegularFileNoFollow(run.dir / name)) return std::nullopt;
  return run.dir / name;
}

}  // namespace

fs::path MapImage(const RunRecord& run) {
  return IsRegularFileNoFollow(run.dir / "map.png") ? run.dir / "map.png" : run.dir / "map.pgm";
}

std::vector<fs::path> StagePaths(const RunRecord& run) {
  std::vector<fs::path> stages;
  for (const std::string& stage : run.outputs.stages) {
    if (IsSafeRelative(stage) && IsRegularFileNoFollow(run.dir / stage)) stages.push_back(run.dir / stage);
  }
  if (!stages.empty() || !run.outputs.stages.empty()) return stages;
  std::error_code error;
  for (fs::directory_iterator it(run.dir / "stages", error), end; !error && it != end; it.increment(error)) {
    if (it->path().extension() == ".png" && IsRegularFileNoFollow(it->path())) stages.push_back(it->path());
  }
  std::sort(stages.begin(), stages.end());
  return stages;
}

void CopyDownloads(const RunRecord& run, const fs::path& run_out, RunArtifacts& artifacts) {
  for (const char* name : kDownloads) {
    if (!IsRegularFileNoFollow(run.dir / name)) continue;
    std::error_code error;
    LinkOrCopy(run.dir / name, run_out / name, error);
    if (error) {
      artifacts.notes.push_back(std::string(name) + " could not be copied: " + error.message());
    } else {
      artifacts.downloads.push_back(name);
    }
  }
  // The worker's stage animation is the page's animation as it is: no GIF to make.
  if (const std::optional<fs::path> animation = StageAnimation(run)) {
    std::error_code error;
    const fs::path shown = run_out / animation->filename();
    if (!IsRegularFileNoFollow(shown)) LinkOrCopy(*animation, shown, error);
    if (error) {
      artifacts.notes.push_back("Map-building animation not shown: " + error.message());
    } else {
      artifacts.animation = animation->filename().string();
    }
  }
}

void AddDownload(RunArtifacts& artifacts, const std::string& name) {
  auto rank = [](const std::string& file) {
    return std::find_if(std::begin(kDownloads), std::end(kDownloads), [&](const char* d) { return file == d; }) -
           std::begin(kDownloads);
  };
  const auto at = std::find_if(artifacts.downloads.begin(), artifacts.downloads.end(),
                               [&](const std::string& file) { return rank(file) > rank(name); });
  artifacts.downloads.insert(at, name);
}

LogTail ReadLogTail(const fs::path& log, std::size_t max_lines) {
  constexpr std::streamoff kMaxBytes = 64 * 1024;
  LogTail tail;
  std::ifstream in(log, std::ios::binary | std::ios::ate);
  if (!in) return tail;
  const std::streamoff size = in.tellg();
  const std::streamoff start = std::max<std::streamoff>(0, size - kMaxBytes);
  in.seekg(start);
  std::string content(static_cast<std::size_t>(size - start), '\0');
  in.read(content.data(), static_cast<std::streamsize>(content.size()));
  tail.truncated = start > 0;
  std::size_t lines = 0;
  std::size_t pos = content.size();
  if (pos > 0 && content[pos - 1] == '\n') --pos;
  while (pos > 0) {
    const std::size_t newline = content.rfind('\n', pos - 1);
    if (++lines > max_lines) {
      tail.truncated = true;
      break;
    }
    if (newline == std::string::npos) {
      pos = 0;
      break;
    }
    pos = newline;
  }
  tail.text = content.substr(pos == 0 ? 0 : pos + 1);
  return tail;
}

}  // namespace slamsweep::report::inline html
