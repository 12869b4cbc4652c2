#pragma once

#include <signal.h>
#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "orchestrator/process/process_spec.h"

namespace slamsweep::orchestrator::testing {

/// `/bin/sh -c SCRIPT` logging into `log_path`.
inline ProcessSpec Sh(const std::string& script, const std::filesystem::path& log_path = {}) {
  ProcessSpec spec;
  spec.argv = {"/bin/sh", "-c", script};
  spec.log_path = log_path;
  return spec;
}

inline std::string ReadAll(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

/// Gone = no such process, or a zombie waiting for a reaper that is not us (PID 1 of a container
/// may not reap promptly). Waits up to `patience` for it to go.
inline bool ProcessGone(pid_t pid, std::chrono::milliseconds patience = std::chrono::milliseconds(2000)) {
  const auto until = std::chrono::steady_clock::now() + patience;
  for (;;) {
    if (::kill(pid, 0) != 0) return true;
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    std::getline(stat, line);
    const auto close = line.rfind(')');
    if (close != std::string::npos && close + 2 < line.size() && line[close + 2] == 'Z') return true;
    if (std::chrono::steady_clock::now() > until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

/// Waits until `path` holds a line (a pid a child script wrote) and returns it as a number.
inline pid_t ReadPidFile(const std::filesystem::path& path) {
  for (int i = 0; i < 250; ++i) {
    const std::string text = ReadAll(path);
    if (!text.empty() && text.back() == '\n') return static_cast<pid_t>(std::stol(text));
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return -1;
}

}  // namespace slamsweep::orchestrator::testing
