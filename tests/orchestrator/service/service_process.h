#pragma once

// The real `slamsweep serve` as a child process of a test, and small HTTP helpers around it.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/support/child_process.h"
#include "tests/support/shared_data.h"

// Last: its <resolv.h> defines `_res`, which breaks Eigen headers included after it.
#include <httplib.h>

namespace slamsweep::service_testing {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

inline std::string ReadAll(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Runs PROGRAM ARGS... with stdout+stderr into `log`; returns its pid.
inline pid_t Spawn(const std::vector<std::string>& argv, const fs::path& log) {
  const pid_t pid = fork();
  if (pid == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    dup2(fd, 1);
    dup2(fd, 2);
    std::vector<char*> args;
    for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
    args.push_back(nullptr);
    execv(args[0], args.data());
    _exit(127);
  }
  return pid;
}

using testing::WaitExit;

/// Runs the command to its end; returns its exit code (-1 after `limit`).
inline int RunToEnd(const std::vector<std::string>& argv, const fs::path& log, std::chrono::seconds limit) {
  return WaitExit(Spawn(argv, log), limit);
}

/// `slamsweep serve --data DATA --listen 127.0.0.1:0 ...` started and listening.
class Server {
 public:
  Server(const fs::path& data, const std::vector<std::string>& extra_args, const fs::path& log) : log_(log) {
    const fs::path port_file = data.parent_path() / (data.filename().string() + ".port");
    fs::remove(port_file);
    std::vector<std::string> argv = {SLAMSWEEP_BINARY, "serve",       "--data",      data.string(),
                                     "--listen",       "127.0.0.1:0", "--port-file", port_file.string()};
    argv.insert(argv.end(), extra_args.begin(), extra_args.end());
    pid_ = Spawn(argv, log);
    const auto deadline = Clock::now() + std::chrono::seconds(60);
    while (Clock::now() < deadline && !fs::exists(port_file)) {
      int status = 0;
      if (waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    port_ = std::stoi(ReadAll(port_file));
  }
  ~Server() {
    if (pid_ > 0) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  bool listening() const { return pid_ > 0 && port_ > 0; }
  int port() const { return port_; }
  pid_t pid() const { return pid_; }
  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_); }
  httplib::Client Client() const {
    httplib::Client client("127.0.0.1", port_);
    client.set_read_timeout(60);
    return client;
  }
  /// Sends `signal` and returns the exit code (-1 when it did not end within `limit`).
  int Signal(int signal, std::chrono::seconds limit) {
    kill(pid_, signal);
    const int code = WaitExit(pid_, limit);
    pid_ = -1;
    return code;
  }
  /// Waits for the server to end by itself; its exit code (-1 after `limit`, then it is killed).
  int WaitForExit(std::chrono::seconds limit) {
    const int code = WaitExit(pid_, limit);
    pid_ = -1;
    return code;
  }
  std::string Log() const { return ReadAll(log_); }

 private:
  fs::path log_;
  pid_t pid_ = -1;
  int port_ = 0;
};

inline nlohmann::json GetJson(const Server& server, const std::string& path) {
  auto client = server.Client();
  auto result = client.Get(path);
  if (!result || result->status != 200) return nullptr;
  return nlohmann::json::parse(result->body);
}

/// Waits until the sweep's state is one of `states`; returns its last JSON.
inline nlohmann::json WaitForSweep(const Server& server, std::int64_t id, const std::vector<std::string>& states,
                                   std::chrono::seconds limit) {
  const auto deadline = Clock::now() + limit;
  nlohmann::json sweep;
  while (Clock::now() < deadline) {
    sweep = GetJson(server, "/api/sweeps/" + std::to_string(id));
    if (!sweep.is_null()) {
      for (const std::string& state : states) {
        if (sweep.value("state", "") == state && sweep.value("report", "") != "writing") return sweep;
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return sweep;
}

/// A sweep folder with a fake SLAM program (declared through the command adapter) that logs each
/// invocation's algorithm name in DIR/invocations.txt and waits while DIR/slow-<name> exists.
class FakeProgramSweep {
 public:
  /// The program lives in `dir`; its control files (slow-<algorithm>, which make it wait) in dir/control,
  /// the one folder besides its input it declares it reads. A SLAM program can write nowhere but its
  /// raw/ folder, so its invocations are counted from outside: a watcher notes every process running
  /// the script (each lives at least 0.2 s, 20 looks of the watcher).
  explicit FakeProgramSweep(const fs::path& dir) : dir_(dir) {
    fs::create_directories(dir / "control");
    program_ = testing::WriteFile(dir / "fake_slam.sh",
                                  "#!/bin/sh\n"
                                  "sleep 0.2\n"
                                  "while [ -e \"$3/slow-$4\" ]; do sleep 0.1; done\n"
                                  "cp \"$1\" \"$2/traj.tum\"\n");
    fs::permissions(program_, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                  fs::perms::others_read | fs::perms::others_exec);
    watcher_ = std::thread([this] {
      while (!stop_) {
        Look();
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
    });
  }
  ~FakeProgramSweep() {
    stop_ = true;
    watcher_.join();
  }
  FakeProgramSweep(const FakeProgramSweep&) = delete;
  FakeProgramSweep& operator=(const FakeProgramSweep&) = delete;

  /// The YAML of a sweep `name` with the given algorithms (each a name the fake program is started with).
  std::string Yaml(const std::string& name, const std::vector<std::string>& algorithms, int iterations) const {
    std::string text = "name: " + name + "\niterations: " + std::to_string(iterations) +
                       "\nseed: 1\nevaluation: {stages: 4}\nalgorithms:\n";
    for (const std::string& algorithm : algorithms) {
      text += "  - name: " + algorithm + "\n    adapter: command\n    timeout_s: 300\n    command:\n      argv: [" +
              program_.string() + ", \"{input}\", \"{output_dir}\", " + (dir_ / "control").string() + ", " + algorithm +
              "]\n      input_format: tum\n      trajectory: {path: traj.tum, format: tum}\n" + "      read_only: [" +
              (dir_ / "control").string() + "]\n";
    }
    return text + "sequences:\n  - {catalog: simulated-floor, name: floor, max_scans: 40}\n";
  }
  std::size_t Invocations(const std::string& algorithm) const {
    Look();
    const std::lock_guard<std::mutex> lock(mutex_);
    std::size_t count = 0;
    for (const auto& [process, name] : seen_) count += name == algorithm ? 1 : 0;
    return count;
  }
  void SetSlow(const std::string& algorithm, bool slow) const {
    if (slow) {
      testing::WriteFile(dir_ / "control" / ("slow-" + algorithm), "");
    } else {
      fs::remove(dir_ / "control" / ("slow-" + algorithm));
    }
  }

 private:
  /// Notes every shell running the script now: (pid, start time) -> its algorithm argument. A child the
  /// shell has forked shows the same command line until it execs (sleep, cp): one whose parent is such a
  /// shell is not another invocation.
  void Look() const {
    struct Found {
      std::string pid, parent, start_time, algorithm;
    };
    std::vector<Found> found;
    std::error_code error;
    for (fs::directory_iterator it("/proc", error), end; !error && it != end; it.increment(error)) {
      const std::string pid = it->path().filename().string();
      if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) continue;
      std::vector<std::string> argv;
      std::stringstream cmdline(ReadAll(it->path() / "cmdline"));
      for (std::string arg; std::getline(cmdline, arg, '\0');) argv.push_back(arg);
      // The shell that runs the script: [/bin/sh, SCRIPT, input, output, control, algorithm].
      if (argv.size() != 6 || argv[1] != program_.string() || !argv[0].ends_with("sh")) continue;
      std::string stat = ReadAll(it->path() / "stat");
      const auto close = stat.rfind(')');
      if (close == std::string::npos) continue;
      std::istringstream fields(stat.substr(close + 2));
      std::string field, parent, start_time;
      for (int index = 3; index <= 22 && fields >> field; ++index) {
        if (index == 4) parent = field;
        if (index == 22) start_time = field;
      }
      found.push_back({pid, parent, start_time, argv[5]});
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const Found& process : found) {
      const bool forked_by_script =
          std::any_of(found.begin(), found.end(), [&](const Found& other) { return other.pid == process.parent; });
      if (!forked_by_script) seen_.emplace(process.pid + "@" + process.start_time, process.algorithm);
    }
  }

  fs::path dir_;
  fs::path program_;
  mutable std::mutex mutex_;
  mutable std::map<std::string, std::string> seen_;
  std::atomic<bool> stop_{false};
  std::thread watcher_;
};

/// POST /api/sweeps with `yaml`; returns the status and the JSON body.
inline std::pair<int, nlohmann::json> PostSweep(const Server& server, const std::string& yaml,
                                                const std::string& query = "name=sweep.yaml",
                                                const httplib::Headers& headers = {}) {
  auto client = server.Client();
  auto result = client.Post("/api/sweeps?" + query, headers, yaml, "application/yaml");
  if (!result) return {-1, nullptr};
  nlohmann::json body;
  try {
    body = nlohmann::json::parse(result->body);
  } catch (const nlohmann::json::exception&) {
    body = result->body;
  }
  return {result->status, body};
}

}  // namespace slamsweep::service_testing
