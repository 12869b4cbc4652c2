#include "orchestrator/sweep/worker_environment.h"

#include <cstdlib>

namespace slamsweep::orchestrator::inline sweep {

std::string WorkerGlibcTunables(const char* inherited) {
  const std::string ours = "glibc.malloc.hugetlb=1";
  if (inherited == nullptr || *inherited == '\0') return ours;
  // Ours first: glibc applies the tunables in order, so a user's own hugetlb setting wins.
  return ours + ":" + inherited;
}

std::vector<std::pair<std::string, std::string>> WorkerEnvironment() {
  return {{"GLIBC_TUNABLES", WorkerGlibcTunables(std::getenv("GLIBC_TUNABLES"))}};
}

}  // namespace slamsweep::orchestrator::inline sweep
