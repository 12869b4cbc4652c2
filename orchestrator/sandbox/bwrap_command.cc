#include "orchestrator/sandbox/bwrap_command.h"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <system_error>

namespace slamsweep::orchestrator::inline sandbox {
namespace fs = std::filesystem;
namespace {

// The top-level links (or folders) of the C library's and programs' paths on a merged-/usr system.
constexpr const char* kSystemRoots[] = {"/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"};
// What the dynamic linker, the C library and libraries in /usr read from /etc; nothing that is a secret
// (no shadow, ssh, ssl keys, machine-id) or names this machine's services.
constexpr const char* kSystemEtc[] = {
    "/etc/ld.so.cache", "/etc/ld.so.conf", "/etc/ld.so.conf.d", "/etc/alternatives",   "/etc/localtime",
    "/etc/timezone",    "/etc/passwd",     "/etc/group",        "/etc/nsswitch.conf",  "/etc/hosts",
    "/etc/host.conf",   "/etc/gai.conf",   "/etc/os-release",   "/etc/debian_version", "/etc/fonts"};

// POSIX shared memory, as much as a container gets by default.
constexpr std::uint64_t kDevShmBytes = 64 << 20;
// The sandbox's own writable tmpfs folders: bubblewrap would make a bound path's missing parents there, writable.
constexpr const char* kScratchFolders[] = {"/tmp", "/dev/shm"};

bool Inside(const fs::path& path, const fs::path& folder) {
  const std::string p = path.string();
  const std::string f = folder.string();
  return p == f || (p.size() > f.size() && p.compare(0, f.size(), f) == 0 && (f.back() == '/' || p[f.size()] == '/'));
}

fs::path Checked(const fs::path& path) {
  if (!path.is_absolute()) throw std::invalid_argument("sandbox: '" + path.string() + "' is not an absolute path");
  fs::path normal = path.lexically_normal();
  if (!normal.has_filename() && normal != normal.root_path()) normal = normal.parent_path();
  return normal;
}

void Append(std::vector<std::string>& argv, std::initializer_list<std::string> items) {
  argv.insert(argv.end(), items.begin(), items.end());
}

/// The stands in the sandbox's scratch folders: for each path mounted two or more levels below /tmp or /dev/shm
/// (/tmp/a/out/runs/r0/raw), the folder right below it (/tmp/a), unless that is mounted itself. bubblewrap makes a
/// mount point's missing parents as plain folders of the file system beneath, here the writable private tmpfs: the
/// program could write beside its raw/ and input/, into a copy of its run folder that never reaches the host. An
/// empty tmpfs on the stand holds those parents and is remounted read-only once everything is bound in it
/// (--remount-ro needs a mount point, which a folder made by --dir is not; binding a parent from the host would show
/// its other files).
std::vector<fs::path> Stands(const std::vector<fs::path>& mounted) {
  std::vector<fs::path> stands;
  for (const fs::path& path : mounted) {
    for (const fs::path scratch : kScratchFolders) {
      const fs::path relative = path.lexically_relative(scratch);
      if (relative.empty() || *relative.begin() == ".." || std::distance(relative.begin(), relative.end()) < 2) {
        continue;
      }
      const fs::path stand = scratch / *relative.begin();
      if (std::find(mounted.begin(), mounted.end(), stand) == mounted.end() &&
          std::find(stands.begin(), stands.end(), stand) == stands.end()) {
        stands.push_back(stand);
      }
    }
  }
  return stands;
}

}  // namespace

std::vector<fs::path> SystemPaths() {
  std::vector<fs::path> paths;
  std::error_code error;
  for (const char* root : kSystemRoots) {
    if (fs::exists(fs::symlink_status(root, error))) paths.emplace_back(root);
  }
  for (const char* file : kSystemEtc) {
    if (fs::exists(file, error)) paths.emplace_back(file);
  }
  return paths;
}

std::vector<std::string> BwrapCommand(const SandboxSpec& spec, const std::vector<std::string>& program_argv,
                                      const fs::path& working_dir, int status_fd) {
  if (spec.init_program.empty()) throw std::invalid_argument("sandbox: no slamsweep-sandbox-init program");
  const fs::path init = Checked(spec.init_program);
  std::vector<std::string> argv = {spec.bwrap_program.string(),
                                   "--unshare-user",
                                   "--unshare-pid",
                                   "--unshare-ipc",
                                   "--unshare-uts",
                                   "--unshare-cgroup-try",
                                   "--die-with-parent",
                                   "--new-session",
                                   "--as-pid-1",
                                   "--cap-drop",
                                   "ALL",
                                   "--hostname",
                                   "sandbox"};
  if (!spec.network) argv.push_back("--unshare-net");
  // No nested user namespace: bubblewrap forbids them through the sandbox's /proc; without one, process 1's
  // seccomp filter does (--no-user-namespaces below).
  if (spec.fresh_proc) argv.push_back("--disable-userns");

  // Memory-backed folders, each bounded: the program cannot fill the machine's memory through them.
  const std::string tmpfs_size = std::to_string(spec.file_size_limit_bytes);
  if (spec.fresh_proc) Append(argv, {"--proc", "/proc"});
  Append(argv,
         {"--dev", "/dev", "--size", std::to_string(kDevShmBytes), "--tmpfs", "/dev/shm", "--remount-ro", "/dev"});
  if (spec.file_size_limit_bytes > 0) Append(argv, {"--size", tmpfs_size});
  Append(argv, {"--tmpfs", "/tmp"});
  // System folders, then the run's own paths with parents before children, so that a writable folder
  // inside a read-only one is bound on top of it (and a run folder under /tmp on a stand in the private one).
  std::vector<fs::path> bound;
  std::error_code error;
  for (const fs::path& path : SystemPaths()) {
    const auto status = fs::symlink_status(path, error);
    // A merged-/usr system's /bin, /lib... are links into /usr: links in the sandbox too.
    if (fs::is_symlink(status) && path.parent_path() == "/") {
      Append(argv, {"--symlink", fs::read_symlink(path, error).string(), path.string()});
    } else {
      Append(argv, {"--ro-bind", path.string(), path.string()});
      bound.push_back(path);
    }
  }
  struct Bind {
    fs::path path;
    bool writable;
  };
  std::vector<Bind> binds;
  for (const fs::path& path : spec.read_only) binds.push_back({Checked(path), false});
  for (const fs::path& path : spec.writable) binds.push_back({Checked(path), true});
  binds.push_back({init, false});
  std::stable_sort(binds.begin(), binds.end(), [](const Bind& a, const Bind& b) { return a.path < b.path; });
  // Empty tmpfs folders, read-only at the end: a secret's folder under the system paths, covered, and the
  // stands under /tmp and /dev/shm that hold the parents of what is bound there.
  std::vector<fs::path> masks;
  for (const fs::path& path : spec.hidden) masks.push_back(Checked(path));
  std::vector<fs::path> mounted = masks;
  for (const Bind& bind : binds) mounted.push_back(bind.path);
  for (const fs::path& stand : Stands(mounted)) masks.push_back(stand);
  std::sort(masks.begin(), masks.end());
  for (const fs::path& mask : masks) Append(argv, {"--tmpfs", mask.string()});
  for (const Bind& bind : binds) {
    const bool covered =
        std::any_of(bound.begin(), bound.end(), [&](const fs::path& folder) { return Inside(bind.path, folder); });
    if (covered && !bind.writable) continue;
    Append(argv, {bind.writable ? "--bind" : "--ro-bind", bind.path.string(), bind.path.string()});
    if (!bind.writable) bound.push_back(bind.path);
  }

  // Read-only once everything is bound in them: nothing can be written there, nor memory filled.
  for (auto mask = masks.rbegin(); mask != masks.rend(); ++mask) Append(argv, {"--remount-ro", mask->string()});
  Append(argv, {"--remount-ro", "/"});
  Append(argv, {"--setenv", "TMPDIR", "/tmp", "--chdir", Checked(working_dir).string(), "--"});

  Append(argv, {init.string(), "--status-fd", std::to_string(status_fd)});
  if (spec.process_limit > 0) Append(argv, {"--process-limit", std::to_string(spec.process_limit)});
  if (spec.file_size_limit_bytes > 0) Append(argv, {"--file-size-limit", tmpfs_size});
  if (!spec.fresh_proc) argv.push_back("--no-user-namespaces");
  argv.push_back("--");
  argv.insert(argv.end(), program_argv.begin(), program_argv.end());
  return argv;
}

}  // namespace slamsweep::orchestrator::inline sandbox
