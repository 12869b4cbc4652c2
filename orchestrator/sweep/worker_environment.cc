#include "orchestrator/sweep/worker_environment.h"

#include <cstdlib>
#include <map>

extern char** environ;

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

std::vector<std::string> WorkerEnvironmentBlock() {
  std::map<std::string, std::string> variables;
  for (char** entry = environ; entry != nullptr && *entry != nullptr; ++entry) {
    const std::string text(*entry);
    const std::size_t equals = text.find('=');
    if (equals != std::string::npos) variables[text.substr(0, equals)] = text.substr(equals + 1);
  }
  for (const auto& [name, value] : WorkerEnvironment()) variables[name] = value;
  std::vector<std::string> block;
  for (const auto& [name, value] : variables) block.push_back(name + "=" + value);
  return block;
}

}  // namespace slamsweep::orchestrator::inline sweep
