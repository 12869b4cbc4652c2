#include "orchestrator/worker/program_view.h"

#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace slamsweep::orchestrator {
namespace fs = std::filesystem;
namespace {

bool Inside(const fs::path& path, const fs::path& folder) {
  const fs::path relative = path.lexically_relative(folder);
  return !relative.empty() && *relative.begin() != "..";
}

/// The program file as exec will find it (argv[0] with a '/', else the first match in PATH).
fs::path ProgramFile(const std::string& program) {
  if (program.find('/') != std::string::npos) return fs::absolute(program).lexically_normal();
  std::istringstream path(std::getenv("PATH") != nullptr ? std::getenv("PATH") : "");
  std::string folder;
  while (std::getline(path, folder, ':')) {
    std::error_code error;
    const fs::path candidate = fs::path(folder.empty() ? "." : folder) / program;
    if (fs::is_regular_file(candidate, error)) return fs::absolute(candidate).lexically_normal();
  }
  return {};
}

}  // namespace

FileSystemView ProgramFileSystemView(const RunSpec& spec, const RunPaths& paths, const std::string& program,
                                     std::vector<std::string>& warnings) {
  const fs::path run_dir = fs::absolute(paths.root).lexically_normal();
  // OUT/runs/<id>: all of OUT; a run folder elsewhere: that folder.
  std::vector<fs::path> candidates = {run_dir.parent_path().filename() == "runs" ? run_dir.parent_path().parent_path()
                                                                                 : run_dir};
  const auto& entry = spec.sequence.entry;
  for (const std::string& truth : {entry.path, entry.relations_path, entry.reference_map_path}) {
    if (!truth.empty()) candidates.push_back(fs::absolute(truth).lexically_normal().parent_path());
  }
  if (const char* extra = std::getenv(kPrivateDirsVariable); extra != nullptr) {
    std::istringstream folders(extra);
    std::string folder;
    while (std::getline(folders, folder, ':')) {
      if (!folder.empty()) candidates.push_back(fs::absolute(folder).lexically_normal());
    }
  }
  const fs::path program_file = ProgramFile(program);
  FileSystemView view;
  for (const fs::path& folder : candidates) {
    std::error_code error;
    if (folder == folder.root_path() || !fs::is_directory(folder, error)) continue;
    if (!program_file.empty() && Inside(program_file, folder)) {
      warnings.push_back("the program could see " + folder.string() + ": the program file " + program_file.string() +
                         " is in it");
      continue;
    }
    view.hidden.push_back(folder);
  }
  view.visible = {fs::absolute(paths.InputDir()).lexically_normal(), fs::absolute(paths.RawDir()).lexically_normal()};
  return view;
}

}  // namespace slamsweep::orchestrator
