#pragma once

// Headless Chromium for the tests that load pages slamsweep serves or writes (the report, the
// service's pages): a child process in its own process group, and the Content-Security-Policy
// violations it logs.
#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace slamsweep::testing {

inline constexpr const char* kChromium = "/usr/bin/chromium";

/// A child process (no shell), stdin /dev/null, stdout and stderr to files, in its own process
/// group so that helpers it starts (Chromium's renderers) end with it; killed when destroyed.
class ChildProcess {
 public:
  ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& stdout_file,
               const std::filesystem::path& stderr_file);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  bool started() const { return pid_ > 0; }
  /// Waits up to `timeout`; true when the process ended by itself.
  bool Wait(std::chrono::seconds timeout);
  /// SIGTERM to the group, SIGKILL after 5 s.
  void Stop();

 private:
  pid_t pid_ = -1;
  bool exited_ = false;
};

struct ChromiumPage {
  bool finished = false;  ///< Chromium ended by itself within its time
  std::string dom;        ///< the DOM after load (when no screenshot was asked for)
  std::string log;        ///< its stderr: console messages and CSP reports
};

/// Loads `url` once: with an empty `screenshot` it dumps the DOM, otherwise it saves a PNG of a
/// 1280 x `window_height_px` window. Files go to `work` under `name`.
ChromiumPage LoadInHeadlessChromium(const std::string& url, const std::filesystem::path& work, const std::string& name,
                                    const std::filesystem::path& screenshot = {}, int window_height_px = 2000);

/// The lines of a Chromium log that report a Content-Security-Policy violation.
std::vector<std::string> CspViolations(const std::string& log);

}  // namespace slamsweep::testing
