#pragma once

#include <string>
#include <utility>
#include <vector>

namespace slamsweep::orchestrator::inline sweep {

/// Environment variables set for every worker process, by every executor (on top of the
/// orchestrator's own environment).
///
/// GLIBC_TUNABLES gains glibc.malloc.hugetlb=1: malloc then asks for transparent huge pages
/// for its large blocks. A worker scores one map in a fresh process, so every buffer of the
/// map metrics and of the mapper is fresh memory, and its first touch costs a page fault per
/// 4 KiB page; with 2 MiB pages the paper metrics of a 2000 x 2000 map fault 1,200 times
/// instead of 14,000 (map_metrics_bench --peak_rss). Tunables the user set are kept and come
/// after ours, so that theirs win on a clash (glibc applies them left to right); glibc older
/// than 2.35 and kernels with transparent huge pages off ignore it.
std::vector<std::pair<std::string, std::string>> WorkerEnvironment();

/// GLIBC_TUNABLES for a worker given the orchestrator's value (null when unset).
std::string WorkerGlibcTunables(const char* inherited);

/// The orchestrator's environment with WorkerEnvironment() set in it, as NAME=VALUE strings for posix_spawn.
std::vector<std::string> WorkerEnvironmentBlock();

}  // namespace slamsweep::orchestrator::inline sweep
