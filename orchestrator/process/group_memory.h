#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string_view>
#include <vector>

#include <sys/types.h>

namespace slamsweep::orchestrator {

/// The fields of /proc/PID/stat the memory limit needs.
struct ProcStat {
  pid_t pid = 0;
  pid_t process_group = 0;
  std::int64_t rss_pages = 0;
};

/// Parses the content of /proc/PID/stat (proc(5)); nullopt when it is not in that form. The command
/// name may itself hold spaces and parentheses, so fields are counted from the LAST ')'.
std::optional<ProcStat> ParseProcStat(std::string_view content);

/// Summed resident memory (kB) of every live process in each of `process_groups`, from one scan of
/// /proc. A group with no process left maps to 0. Limiting the group, not the child alone, catches a
/// SLAM program whose memory lives in a helper process it started.
std::map<pid_t, std::int64_t> GroupRssKb(const std::vector<pid_t>& process_groups);

}  // namespace slamsweep::orchestrator
