#include "orchestrator/service/leftover_workers.h"

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <set>
#include <thread>

#include "orchestrator/slurm/slurm_command.h"

namespace slamsweep::orchestrator::service {
namespace {

namespace fs = std::filesystem;

bool IsUnder(const fs::path& path, const fs::path& root) {
  const std::string text = path.lexically_normal().string();
  const std::string prefix = root.lexically_normal().string();
  return text.size() > prefix.size() && text.compare(0, prefix.size(), prefix) == 0 && text[prefix.size()] == '/';
}

std::vector<std::string> CommandLine(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/cmdline", std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  std::vector<std::string> argv;
  std::string arg;
  for (const char c : bytes.str()) {
    if (c == '\0') {
      argv.push_back(arg);
      arg.clear();
    } else {
      arg += c;
    }
  }
  return argv;
}

/// Running, not a zombie that its new parent has yet to reap.
bool Alive(pid_t pid) {
  if (::kill(pid, 0) != 0) return false;
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat;
  std::getline(in, stat);
  const auto close = stat.rfind(')');
  return close == std::string::npos || close + 2 >= stat.size() || stat[close + 2] != 'Z';
}

}  // namespace

std::vector<pid_t> FindLeftoverProcesses(const fs::path& sweeps_root) {
  std::error_code error;
  const fs::path root = fs::weakly_canonical(fs::absolute(sweeps_root), error);
  std::vector<pid_t> found;
  for (const fs::directory_entry& entry : fs::directory_iterator("/proc", error)) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    const pid_t pid = static_cast<pid_t>(std::stol(name));
    if (pid == ::getpid()) continue;
    const std::vector<std::string> argv = CommandLine(pid);
    const bool worker = argv.size() == 3 && argv[1] == "worker" && IsUnder(argv[2], root);
    std::error_code cwd_error;
    const fs::path cwd = fs::read_symlink(entry.path() / "cwd", cwd_error);
    if (worker || (!cwd_error && IsUnder(cwd, root))) found.push_back(pid);
  }
  return found;
}

std::size_t EndLeftoverProcesses(const fs::path& sweeps_root, double grace_s) {
  const std::vector<pid_t> leftovers = FindLeftoverProcesses(sweeps_root);
  if (leftovers.empty()) return 0;
  for (const pid_t pid : leftovers) {
    const pid_t group = ::getpgid(pid);
    if (group > 0 && group == pid) ::kill(-group, SIGTERM);
    ::kill(pid, SIGTERM);
  }
  const auto give_up = [](double seconds) {
    return std::chrono::steady_clock::now() + std::chrono::milliseconds(static_cast<long>(seconds * 1000));
  };
  const auto wait_until = [&](std::chrono::steady_clock::time_point deadline) {
    while (std::chrono::steady_clock::now() < deadline) {
      bool any = false;
      for (const pid_t pid : leftovers) any = any || Alive(pid);
      if (!any) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
  };
  if (!wait_until(give_up(grace_s))) {
    for (const pid_t pid : leftovers) {
      const pid_t group = ::getpgid(pid);
      if (group > 0 && group == pid) ::kill(-group, SIGKILL);
      ::kill(pid, SIGKILL);
    }
    wait_until(give_up(5.0));
  }
  return leftovers.size();
}

namespace {

/// Array job ids of the queued or running jobs whose batch script lies in `state_dir`.
std::set<std::string> OurSlurmJobs(const fs::path& state_dir, bool& queried) {
  const CommandOutput listed = RunSlurmCommand({"squeue", "--noheader", "--format=%F|%o"});
  queried = listed.ok();
  std::set<std::string> jobs;
  const std::string prefix = fs::absolute(state_dir).lexically_normal().string() + "/";
  std::istringstream lines(listed.output);
  for (std::string line; std::getline(lines, line);) {
    const auto bar = line.find('|');
    if (bar == std::string::npos) continue;
    const std::string job = line.substr(0, bar), command = line.substr(bar + 1);
    if (!job.empty() && job.find_first_not_of("0123456789") == std::string::npos && command.rfind(prefix, 0) == 0) {
      jobs.insert(job);
    }
  }
  return jobs;
}

}  // namespace

std::vector<std::string> EndLeftoverSlurmJobs(const fs::path& state_dir, double wait_s) {
  bool queried = false;
  const std::set<std::string> jobs = OurSlurmJobs(state_dir, queried);
  for (const std::string& job : jobs) RunSlurmCommand({"scancel", job});
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(static_cast<long>(wait_s * 1000));
  while (!jobs.empty() && std::chrono::steady_clock::now() < deadline) {
    if (OurSlurmJobs(state_dir, queried).empty() && queried) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }
  return {jobs.begin(), jobs.end()};
}

}  // namespace slamsweep::orchestrator::service
