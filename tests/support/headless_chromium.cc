#include "tests/support/headless_chromium.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <fstream>
#include <sstream>
#include <thread>

extern char** environ;

namespace slamsweep::testing {
namespace {

std::string FileText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& stdout_file,
                           const std::filesystem::path& stderr_file) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, stdout_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, stderr_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  std::vector<char*> args;
  for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
  args.push_back(nullptr);
  if (posix_spawn(&pid_, argv[0].c_str(), &actions, &attributes, args.data(), environ) != 0) pid_ = -1;
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
}

ChildProcess::~ChildProcess() {
  if (pid_ > 0 && !exited_) {
    kill(-pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
}

bool ChildProcess::Wait(std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      exited_ = true;
      return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

void ChildProcess::Stop() {
  if (pid_ <= 0 || exited_) return;
  kill(-pid_, SIGTERM);
  if (!Wait(std::chrono::seconds(5))) kill(-pid_, SIGKILL);
  waitpid(pid_, nullptr, 0);
  exited_ = true;
}

ChromiumPage LoadInHeadlessChromium(const std::string& url, const std::filesystem::path& work, const std::string& name,
                                    const std::filesystem::path& screenshot, int window_height_px) {
  // Without the background-networking flags Chromium keeps trying hosts this closed network refuses.
  std::vector<std::string> argv = {kChromium,
                                   "--headless=new",
                                   "--no-sandbox",
                                   "--disable-gpu",
                                   "--no-first-run",
                                   "--disable-background-networking",
                                   "--disable-component-update",
                                   "--disable-sync",
                                   "--enable-logging=stderr",
                                   "--v=0",
                                   "--user-data-dir=" + (work / ("profile-" + name)).string(),
                                   "--window-size=1280," + std::to_string(window_height_px)};
  argv.push_back(screenshot.empty() ? std::string("--dump-dom") : "--screenshot=" + screenshot.string());
  argv.push_back(url);
  const std::filesystem::path out = work / (name + ".out"), err = work / (name + ".err");
  ChildProcess chromium(argv, out, err);
  ChromiumPage page;
  if (!chromium.started()) return page;
  page.finished = chromium.Wait(std::chrono::seconds(40));
  chromium.Stop();
  page.dom = FileText(out);
  page.log = FileText(err);
  return page;
}

std::vector<std::string> CspViolations(const std::string& log) {
  std::vector<std::string> lines;
  std::istringstream in(log);
  for (std::string line; std::getline(in, line);) {
    if (line.find("Refused to") != std::string::npos || line.find("Content Security Policy") != std::string::npos) {
      lines.push_back(line);
    }
  }
  return lines;
}

}  // namespace slamsweep::testing
