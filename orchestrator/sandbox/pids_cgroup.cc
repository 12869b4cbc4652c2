#include "orchestrator/sandbox/pids_cgroup.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

namespace slamsweep::orchestrator::inline sandbox {
namespace fs = std::filesystem;
namespace {

std::string ReadText(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

bool WriteText(const fs::path& file, const std::string& text) {
  std::ofstream out(file);
  out << text;
  out.flush();
  return static_cast<bool>(out);
}

/// Whether the comma-separated `list` holds `item`.
bool Lists(const std::string& list, const std::string& item) {
  std::istringstream items(list);
  for (std::string one; std::getline(items, one, ',');) {
    if (one == item) return true;
  }
  return false;
}

/// This process's cgroup in the pids hierarchy: the v1 `pids` mount, else the v2 mount when its
/// controllers hold `pids`. Empty when there is neither.
fs::path OwnPidsCgroup() {
  std::istringstream mounts(ReadText("/proc/self/mountinfo"));
  fs::path v1, v2;
  for (std::string line; std::getline(mounts, line);) {
    // "... MOUNT_POINT OPTIONS - FSTYPE SOURCE SUPER_OPTIONS"
    const auto dash = line.find(" - ");
    if (dash == std::string::npos) continue;
    std::istringstream before(line.substr(0, dash)), after(line.substr(dash + 3));
    std::string field, mount_point, type, source, options;
    for (int i = 0; i < 5 && before >> field; ++i) mount_point = field;
    after >> type >> source >> options;
    if (type == "cgroup" && Lists(options, "pids")) v1 = mount_point;
    if (type == "cgroup2") v2 = mount_point;
  }
  std::istringstream groups(ReadText("/proc/self/cgroup"));
  for (std::string line; std::getline(groups, line);) {
    // "ID:CONTROLLERS:PATH"
    const auto first = line.find(':');
    const auto second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1);
    const fs::path path = fs::path(line.substr(second + 1)).relative_path();
    if (!v1.empty() && Lists(controllers, "pids")) return v1 / path;
    if (v1.empty() && !v2.empty() && controllers.empty() &&
        ReadText(v2 / path / "cgroup.controllers").find("pids") != std::string::npos) {
      return v2 / path;
    }
  }
  return {};
}

}  // namespace

std::unique_ptr<PidsCgroup> PidsCgroup::Create(std::uint64_t limit, std::string& why) {
  const fs::path parent = OwnPidsCgroup();
  if (parent.empty()) {
    why = "no pids cgroup controller is mounted";
    return nullptr;
  }
  // cgroup v2: the pids controller must be enabled for children (refused where processes live beside them).
  if (fs::exists(parent / "cgroup.subtree_control") &&
      ReadText(parent / "cgroup.subtree_control").find("pids") == std::string::npos &&
      !WriteText(parent / "cgroup.subtree_control", "+pids")) {
    why = "cannot enable the pids controller in " + parent.string();
    return nullptr;
  }
  static std::atomic<int> counter{0};
  std::string name = "slamsweep-sandbox-";
  name.append(std::to_string(::getpid())).append("-").append(std::to_string(counter++));
  const fs::path folder = parent / name;
  std::error_code error;
  if (!fs::create_directory(folder, error)) {
    why = "cannot make " + folder.string();
    why.append(": ").append(error ? error.message() : std::string("it exists"));
    return nullptr;
  }
  std::unique_ptr<PidsCgroup> cgroup(new PidsCgroup(folder));
  if (!WriteText(folder / "pids.max", std::to_string(limit))) {
    why = "cannot write " + (folder / "pids.max").string();
    return nullptr;
  }
  return cgroup;
}

PidsCgroup::~PidsCgroup() {
  // A sandbox ended by SIGKILL may still be leaving: rmdir succeeds once the cgroup is empty.
  for (int attempt = 0; attempt < 50; ++attempt) {
    if (::rmdir(folder_.c_str()) == 0 || errno == ENOENT) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

std::uint64_t PidsCgroup::Refusals() const {
  std::istringstream events(ReadText(folder_ / "pids.events"));
  std::string key;
  std::uint64_t value = 0;
  while (events >> key >> value) {
    if (key == "max") return value;
  }
  return 0;
}

}  // namespace slamsweep::orchestrator::inline sandbox
