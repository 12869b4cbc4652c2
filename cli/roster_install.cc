#include "cli/roster_install.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "evaluator/core/input_error.h"
#include "evaluator/core/installation.h"
#include "orchestrator/adapters/roster.h"
#include "orchestrator/process/process_set.h"

namespace slamsweep::cli {

namespace fs = std::filesystem;
namespace orch = slamsweep::orchestrator;

namespace {

bool Installed(const orch::RosterAlgorithm& algorithm) {
  try {
    orch::RosterProgramFiles(algorithm);
    return true;
  } catch (const evaluator::InputError&) {
    return false;
  }
}

bool EnvironmentSet(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0';
}

// The build tree this program was built in, when it may build the roster there.
bool CanBuildHere() {
  if (EnvironmentSet("SLAMSWEEP_SLAM_PREFIX") || EnvironmentSet("SLAMSWEEP_SLAM_DRIVER_DIR")) return false;
  if (const char* off = std::getenv("SLAMSWEEP_NO_ROSTER_BUILD"); off != nullptr && std::string(off) == "1")
    return false;
  if (evaluator::FindInstalledData("slam")) return false;  // an installation: its roster comes with it
  return fs::is_regular_file(fs::path(SLAMSWEEP_SOURCE_DIR) / "scripts" / "install-slam.sh") &&
         fs::is_regular_file(fs::path(SLAMSWEEP_BUILD_TREE) / "CMakeCache.txt");
}

// What the user waits for, from the builds measured on 2 cores (docs/algorithms.md, "The paper's roster").
std::string Estimate(const std::string& upstream) {
  const std::string cached = "seconds when ~/.cache/slamsweep holds its build";
  if (upstream == "cartographer")
    return "its first build takes about 5 minutes on 2 cores (more on a busy machine); " + cached;
  return "a first build from source takes a few minutes at most; " + cached;
}

// Runs one step; its output goes to `log`, whose tail is the error when it fails.
void RunStep(const std::vector<std::string>& argv, const fs::path& log, const std::string& what) {
  orch::ProcessSpec spec;
  spec.argv = argv;
  spec.log_path = log;
  spec.timeout_s = 3 * 3600;
  const orch::ProcessOutcome outcome = orch::RunProcess(spec);
  if (outcome.ok()) return;
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  std::string tail = text.str();
  if (tail.size() > 3000) tail = "..." + tail.substr(tail.size() - 3000);
  throw evaluator::InputError(
      fmt::format("{} failed ({}); its output ({}):\n{}", what, fmt::join(argv, " "), log.string(), tail));
}

// Holds an exclusive lock on a file for its lifetime.
class FileLock {
 public:
  FileLock(const fs::path& file, std::ostream& progress)
      : fd_(::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
    if (fd_ < 0) throw evaluator::InputError(file.string() + ": cannot open the roster's install lock");
    if (::flock(fd_, LOCK_EX | LOCK_NB) == 0) return;
    progress << "slamsweep: another slamsweep is installing roster algorithms; waiting for it (" << file.string()
             << ")\n";
    progress.flush();
    if (::flock(fd_, LOCK_EX) != 0) throw evaluator::InputError(file.string() + ": cannot lock");
  }
  ~FileLock() { ::close(fd_); }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
};

}  // namespace

void InstallMissingRoster(const std::set<std::string>& adapters, std::ostream& progress) {
  std::vector<const orch::RosterAlgorithm*> wanted;
  for (const std::string& adapter : adapters) {
    if (const orch::RosterAlgorithm* algorithm = orch::FindRosterAlgorithm(adapter);
        algorithm && !Installed(*algorithm)) {
      wanted.push_back(algorithm);
    }
  }
  if (wanted.empty() || !CanBuildHere()) return;
  const fs::path prefix = orch::RosterPrefix();
  fs::create_directories(prefix);
  const FileLock lock(prefix / ".install.lock", progress);
  // Another process may have installed them while this one waited.
  std::map<std::string, std::vector<std::string>> missing;  // upstream -> algorithms
  for (const orch::RosterAlgorithm* algorithm : wanted) {
    if (!Installed(*algorithm)) missing[std::string(algorithm->upstream)].push_back(std::string(algorithm->name));
  }
  if (missing.empty()) return;
  const fs::path source(SLAMSWEEP_SOURCE_DIR);
  const fs::path build(SLAMSWEEP_BUILD_TREE);
  const fs::path log = build / "roster-install.log";
  std::vector<std::string> targets;
  for (const auto& [upstream, algorithms] : missing) {
    progress << fmt::format(
        "slamsweep: {} not installed: building {} now with scripts/install-slam.sh {} ({}); "
        "output in {}\n",
        fmt::join(algorithms, ", "), upstream, upstream, Estimate(upstream), log.string());
    progress.flush();
    const auto start = std::chrono::steady_clock::now();
    RunStep({(source / "scripts" / "install-slam.sh").string(), "--prefix", prefix.string(), upstream}, log,
            "scripts/install-slam.sh " + upstream);
    progress << fmt::format("slamsweep: {} installed in {:.0f} s\n", upstream,
                            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    for (const std::string& algorithm : algorithms) targets.push_back("slamsweep-slam-" + algorithm);
  }
  progress << fmt::format("slamsweep: building the driver(s) {} in {}\n", fmt::join(targets, ", "), build.string());
  progress.flush();
  // Reconfigure first: a driver is a target only once its upstream is installed.
  RunStep({"cmake", build.string()}, log, "reconfiguring " + build.string());
  std::vector<std::string> argv = {"cmake", "--build", build.string(), "--target"};
  argv.insert(argv.end(), targets.begin(), targets.end());
  RunStep(argv, log, "building the roster drivers");
}

}  // namespace slamsweep::cli
