#include "orchestrator/process/group_memory.h"

#include <dirent.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <string>

namespace slamsweep::orchestrator::inline process {
namespace {

template <typename Int>
bool ParseInt(std::string_view text, Int& value) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}

std::optional<std::string> ReadSmallFile(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  std::array<char, 1024> buffer;
  std::string content;
  for (;;) {
    const ssize_t n = ::read(fd, buffer.data(), buffer.size());
    if (n <= 0) break;
    content.append(buffer.data(), static_cast<std::size_t>(n));
  }
  ::close(fd);
  return content;
}

}  // namespace

std::optional<ProcStat> ParseProcStat(std::string_view content) {
  const std::size_t open = content.find('(');
  const std::size_t close = content.rfind(')');
  if (open == std::string_view::npos || close == std::string_view::npos || close < open) return std::nullopt;
  ProcStat stat;
  std::string_view pid_text = content.substr(0, open);
  while (!pid_text.empty() && pid_text.back() == ' ') pid_text.remove_suffix(1);
  if (!ParseInt(pid_text, stat.pid)) return std::nullopt;
  // After ')': field 3 (state) is token 0, so field N is token N - 3.
  std::string_view rest = content.substr(close + 1);
  constexpr int kParentToken = 4 - 3;
  constexpr int kGroupToken = 5 - 3;
  constexpr int kThreadsToken = 20 - 3;
  constexpr int kRssToken = 24 - 3;
  int token = 0;
  bool have_parent = false, have_group = false, have_threads = false, have_rss = false;
  while (!rest.empty() && token <= kRssToken) {
    const std::size_t start = rest.find_first_not_of(" \n");
    if (start == std::string_view::npos) break;
    rest.remove_prefix(start);
    const std::size_t end = std::min(rest.find_first_of(" \n"), rest.size());
    const std::string_view field = rest.substr(0, end);
    if (token == kParentToken) have_parent = ParseInt(field, stat.parent);
    if (token == kGroupToken) have_group = ParseInt(field, stat.process_group);
    if (token == kThreadsToken) have_threads = ParseInt(field, stat.threads);
    if (token == kRssToken) have_rss = ParseInt(field, stat.rss_pages);
    rest.remove_prefix(end);
    ++token;
  }
  if (!have_parent || !have_group || !have_threads || !have_rss) return std::nullopt;
  return stat;
}

std::map<pid_t, GroupUsage> GroupUsageOf(const std::vector<pid_t>& leaders, const std::vector<ProcStat>& processes,
                                         std::int64_t page_kb) {
  std::map<pid_t, GroupUsage> usage;
  for (const pid_t leader : leaders) usage[leader] = {};
  std::map<pid_t, const ProcStat*> by_pid;
  for (const ProcStat& process : processes) by_pid[process.pid] = &process;
  // The leader a process counts for: its group's, else the nearest leader among its ancestors.
  std::map<pid_t, pid_t> owner;  // memo: pid -> leader, 0 for none
  const auto owner_of = [&](pid_t pid) {
    std::vector<pid_t> chain;
    pid_t found = 0;
    for (pid_t at = pid; at > 0 && chain.size() < by_pid.size() + 1;) {
      if (const auto known = owner.find(at); known != owner.end()) {
        found = known->second;
        break;
      }
      chain.push_back(at);
      if (usage.contains(at)) {
        found = at;
        break;
      }
      const auto record = by_pid.find(at);
      if (record == by_pid.end()) break;
      if (usage.contains(record->second->process_group)) {
        found = record->second->process_group;
        break;
      }
      at = record->second->parent;
    }
    for (const pid_t visited : chain) owner[visited] = found;
    return found;
  };
  for (const ProcStat& process : processes) {
    const pid_t leader = owner_of(process.pid);
    if (leader == 0) continue;
    usage[leader].rss_kb += process.rss_pages * page_kb;
    usage[leader].tasks += process.threads;
  }
  return usage;
}

std::map<pid_t, GroupUsage> GroupUsageOf(const std::vector<pid_t>& leaders) {
  if (leaders.empty()) return {};
  std::vector<ProcStat> processes;
  DIR* proc = ::opendir("/proc");
  if (proc != nullptr) {
    while (const dirent* entry = ::readdir(proc)) {
      if (entry->d_name[0] < '1' || entry->d_name[0] > '9') continue;
      // Processes vanish between readdir and read: a missing file is normal, not an error.
      const auto content = ReadSmallFile(std::string("/proc/") + entry->d_name + "/stat");
      if (!content) continue;
      if (const auto stat = ParseProcStat(*content)) processes.push_back(*stat);
    }
    ::closedir(proc);
  }
  return GroupUsageOf(leaders, processes, ::sysconf(_SC_PAGESIZE) / 1024);
}

}  // namespace slamsweep::orchestrator::inline process
