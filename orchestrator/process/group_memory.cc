#include "orchestrator/process/group_memory.h"

#include <dirent.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <string>

namespace slamsweep::orchestrator {
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
  constexpr int kGroupToken = 5 - 3;
  constexpr int kRssToken = 24 - 3;
  int token = 0;
  bool have_group = false, have_rss = false;
  while (!rest.empty() && token <= kRssToken) {
    const std::size_t start = rest.find_first_not_of(" \n");
    if (start == std::string_view::npos) break;
    rest.remove_prefix(start);
    const std::size_t end = std::min(rest.find_first_of(" \n"), rest.size());
    const std::string_view field = rest.substr(0, end);
    if (token == kGroupToken) have_group = ParseInt(field, stat.process_group);
    if (token == kRssToken) have_rss = ParseInt(field, stat.rss_pages);
    rest.remove_prefix(end);
    ++token;
  }
  if (!have_group || !have_rss) return std::nullopt;
  return stat;
}

std::map<pid_t, std::int64_t> GroupRssKb(const std::vector<pid_t>& process_groups) {
  std::map<pid_t, std::int64_t> rss_kb;
  for (const pid_t group : process_groups) rss_kb[group] = 0;
  if (process_groups.empty()) return rss_kb;
  const std::int64_t page_kb = ::sysconf(_SC_PAGESIZE) / 1024;
  DIR* proc = ::opendir("/proc");
  if (proc == nullptr) return rss_kb;
  while (const dirent* entry = ::readdir(proc)) {
    if (entry->d_name[0] < '1' || entry->d_name[0] > '9') continue;
    // Processes vanish between readdir and read: a missing file is normal, not an error.
    const auto content = ReadSmallFile(std::string("/proc/") + entry->d_name + "/stat");
    if (!content) continue;
    const auto stat = ParseProcStat(*content);
    if (!stat) continue;
    const auto found = rss_kb.find(stat->process_group);
    if (found != rss_kb.end()) found->second += stat->rss_pages * page_kb;
  }
  ::closedir(proc);
  return rss_kb;
}

}  // namespace slamsweep::orchestrator
