#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string_view>
#include <vector>

#include <sys/types.h>

namespace slamsweep::orchestrator::inline process {

/// The fields of /proc/PID/stat the resource limits need.
struct ProcStat {
  pid_t pid = 0;
  pid_t parent = 0;
  pid_t process_group = 0;
  std::int64_t threads = 0;
  std::int64_t rss_pages = 0;
};

/// Parses the content of /proc/PID/stat (proc(5)); nullopt when it is not in that form. The command
/// name may itself hold spaces and parentheses, so fields are counted from the LAST ')'.
std::optional<ProcStat> ParseProcStat(std::string_view content);

/// What a started child and everything it started hold now.
struct GroupUsage {
  std::int64_t rss_kb = 0;
  /// Processes and threads.
  std::int64_t tasks = 0;
};

/// The usage of each of `leaders` with every live process in its process group or descending from
/// it (a process that left the group with setsid still counts, as does a sandbox's PID namespace,
/// whose orphans its process 1 adopts), from one scan of /proc. A leader with nothing left maps to
/// zeros. Limiting the group, not the child alone, catches a SLAM program whose memory lives in a
/// helper process it started.
std::map<pid_t, GroupUsage> GroupUsageOf(const std::vector<pid_t>& leaders);

/// The same usage from given /proc/PID/stat records (GroupUsageOf reads them).
std::map<pid_t, GroupUsage> GroupUsageOf(const std::vector<pid_t>& leaders, const std::vector<ProcStat>& processes,
                                         std::int64_t page_kb);

}  // namespace slamsweep::orchestrator::inline process
