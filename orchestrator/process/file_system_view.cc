#include "orchestrator/process/file_system_view.h"

#include <fcntl.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace slamsweep::orchestrator {
namespace fs = std::filesystem;
namespace {

bool Inside(const fs::path& path, const fs::path& folder) {
  const std::string p = path.string();
  const std::string f = folder.string();
  return p == f || (p.size() > f.size() && p.compare(0, f.size(), f) == 0 && p[f.size()] == '/');
}

fs::path Normalised(const fs::path& path) {
  if (!path.is_absolute()) throw std::invalid_argument("file system view: '" + path.string() + "' is not absolute");
  fs::path normal = path.lexically_normal();
  if (normal.has_filename() == false && normal != normal.root_path()) normal = normal.parent_path();
  return normal;
}

bool WriteWhole(const char* file, const std::string& text) {
  const int fd = ::open(file, O_WRONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  ::close(fd);
  return ok;
}

/// "/proc/self/fd/<fd>" into `buffer` (snprintf is not async-signal-safe).
void FdPath(int fd, char (&buffer)[32]) {
  char digits[12];
  int n = 0;
  do {
    digits[n++] = static_cast<char>('0' + fd % 10);
    fd /= 10;
  } while (fd > 0);
  const char prefix[] = "/proc/self/fd/";
  std::memcpy(buffer, prefix, sizeof(prefix) - 1);
  int at = sizeof(prefix) - 1;
  while (n > 0) buffer[at++] = digits[--n];
  buffer[at] = '\0';
}

std::string Probe() {
  std::error_code error;
  const fs::path scratch = fs::temp_directory_path(error) / ("slamsweep-view-probe-" + std::to_string(::getpid()));
  fs::create_directories(scratch / "kept", error);
  if (error) return "cannot create " + scratch.string() + ": " + error.message();
  FileSystemView view;
  view.hidden = {scratch};
  view.visible = {scratch / "kept"};
  const PreparedFileSystemView prepared = PrepareFileSystemView(view);
  int report[2];
  std::string reason;
  if (::pipe2(report, O_CLOEXEC) != 0) return std::string("pipe: ") + std::strerror(errno);
  const pid_t child = ::fork();
  if (child == 0) {
    const char* step = "";
    const int failure = ApplyFileSystemView(prepared, &step);
    // Only async-signal-safe calls here: the errno goes back as a number, the parent words it.
    if (failure != 0) {
      (void)!::write(report[1], &failure, sizeof(failure));
      (void)!::write(report[1], step, std::strlen(step));
    }
    ::_exit(failure == 0 ? 0 : 1);
  }
  ::close(report[1]);
  if (child < 0) {
    reason = std::string("fork: ") + std::strerror(errno);
  } else {
    std::string message;
    char buffer[256];
    ssize_t n = 0;
    while ((n = ::read(report[0], buffer, sizeof(buffer))) > 0) message.append(buffer, static_cast<std::size_t>(n));
    int status = 0;
    ::waitpid(child, &status, 0);
    if (message.size() >= sizeof(int)) {
      int failure = 0;
      std::memcpy(&failure, message.data(), sizeof(int));
      reason = message.substr(sizeof(int)) + ": " + std::strerror(failure);
    } else if (!(WIFEXITED(status) && WEXITSTATUS(status) == 0)) {
      reason = "the probe child failed";
    }
  }
  ::close(report[0]);
  fs::remove_all(scratch, error);
  return reason;
}

}  // namespace

PreparedFileSystemView PrepareFileSystemView(const FileSystemView& view) {
  PreparedFileSystemView prepared;
  std::vector<fs::path> hidden;
  for (const fs::path& path : view.hidden) {
    const fs::path normal = Normalised(path);
    if (normal == normal.root_path()) throw std::invalid_argument("file system view: cannot hide '/'");
    hidden.push_back(normal);
  }
  // Outermost first: a folder inside one already covered is gone with it.
  std::sort(hidden.begin(), hidden.end(), [](const fs::path& a, const fs::path& b) {
    return a.string().size() < b.string().size();
  });
  std::vector<fs::path> covers;
  for (const fs::path& folder : hidden) {
    if (std::none_of(covers.begin(), covers.end(), [&](const fs::path& c) { return Inside(folder, c); })) {
      covers.push_back(folder);
    }
  }
  for (const fs::path& cover : covers) prepared.hidden.push_back(cover.string());
  for (const fs::path& path : view.visible) {
    const fs::path normal = Normalised(path);
    const auto cover = std::find_if(covers.begin(), covers.end(), [&](const fs::path& c) { return Inside(normal, c); });
    if (cover == covers.end()) continue;  // never covered
    // The mount point and its parents, below the tmpfs.
    std::vector<std::string> chain;
    for (fs::path folder = normal; folder != *cover; folder = folder.parent_path()) chain.push_back(folder.string());
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      if (std::find(prepared.mkdirs.begin(), prepared.mkdirs.end(), *it) == prepared.mkdirs.end()) {
        prepared.mkdirs.push_back(*it);
      }
    }
    prepared.visible.push_back(normal.string());
  }
  prepared.user_namespace = ::geteuid() != 0;
  prepared.uid_map = std::to_string(::geteuid()) + " " + std::to_string(::geteuid()) + " 1\n";
  prepared.gid_map = std::to_string(::getegid()) + " " + std::to_string(::getegid()) + " 1\n";
  return prepared;
}

int ApplyFileSystemView(const PreparedFileSystemView& view, const char** step) noexcept {
  const auto fail = [step](const char* what) {
    *step = what;
    return errno != 0 ? errno : EINVAL;
  };
  constexpr std::size_t kMaxVisible = 16;
  int visible_fds[kMaxVisible];
  if (view.visible.size() > kMaxVisible) {
    errno = E2BIG;
    return fail("too many visible folders");
  }
  if (view.user_namespace) {
    if (::unshare(CLONE_NEWUSER | CLONE_NEWNS) != 0) return fail("unshare");
    if (!WriteWhole("/proc/self/setgroups", "deny")) return fail("write /proc/self/setgroups");
    if (!WriteWhole("/proc/self/uid_map", view.uid_map)) return fail("write /proc/self/uid_map");
    if (!WriteWhole("/proc/self/gid_map", view.gid_map)) return fail("write /proc/self/gid_map");
  } else if (::unshare(CLONE_NEWNS) != 0) {
    return fail("unshare");
  }
  // Nothing mounted here may reach the rest of the system.
  if (::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) return fail("make mounts private");
  // The folders to bind back, opened while still reachable, and in the new namespace: a bind mount
  // cannot take its source from another one.
  for (std::size_t i = 0; i < view.visible.size(); ++i) {
    visible_fds[i] = ::open(view.visible[i].c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC);
    if (visible_fds[i] < 0) return fail("open a visible folder");
  }
  for (const std::string& folder : view.hidden) {
    if (::mount("slamsweep-hidden", folder.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, "size=64k,mode=755") != 0) {
      return fail("mount tmpfs over a hidden folder");
    }
  }
  for (const std::string& folder : view.mkdirs) {
    if (::mkdir(folder.c_str(), 0755) != 0 && errno != EEXIST) return fail("make a mount point");
  }
  for (std::size_t i = 0; i < view.visible.size(); ++i) {
    char source[32];
    FdPath(visible_fds[i], source);
    if (::mount(source, view.visible[i].c_str(), nullptr, MS_BIND | MS_REC, nullptr) != 0) {
      return fail("bind a visible folder");
    }
    ::close(visible_fds[i]);
  }
  return 0;
}

const std::string& FileSystemViewUnavailableReason() {
  static const std::string reason = Probe();
  return reason;
}

}  // namespace slamsweep::orchestrator
