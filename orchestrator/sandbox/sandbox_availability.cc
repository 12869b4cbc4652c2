#include "orchestrator/sandbox/sandbox_availability.h"

#include <unistd.h>

#include <cstdlib>
#include <sstream>

#include "evaluator/core/installation.h"

namespace slamsweep::orchestrator::inline sandbox {
namespace fs = std::filesystem;
namespace {

fs::path InPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::istringstream folders(path != nullptr ? path : "/usr/bin:/bin");
  std::string folder;
  while (std::getline(folders, folder, ':')) {
    if (folder.empty()) continue;
    const fs::path candidate = fs::path(folder) / program;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return {};
}

SandboxPrograms Find() {
  SandboxPrograms programs;
  programs.bwrap = InPath("bwrap");
  if (const auto init = evaluator::FindLibexecFile("slamsweep-sandbox-init")) programs.init = fs::absolute(*init);
  if (programs.bwrap.empty()) {
    programs.missing = "bubblewrap (bwrap) is not installed: scripts/install-deps.sh installs it";
  } else if (programs.init.empty()) {
    programs.missing = "slamsweep-sandbox-init is missing: " + evaluator::DescribeLibexecSearch();
  }
  return programs;
}

}  // namespace

const SandboxPrograms& FindSandboxPrograms() {
  static const SandboxPrograms programs = Find();
  return programs;
}

}  // namespace slamsweep::orchestrator::inline sandbox
