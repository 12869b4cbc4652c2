// slamsweep-hostile: a SLAM program that tries to cheat and to break out. Started by the worker
// through the command adapter exactly as a SLAM program is, it prints one line per attempt,
//   ATTEMPT <name>: refused (<why>)      or      ATTEMPT <name>: SUCCEEDED (<what it got>)
// (and NOTE lines for attempts the test judges from outside), and then behaves: it writes the odometry it was given as
// its trajectory, so the run is scored. Modes: "attempts" (everything but the limits), "fork" (a bounded fork storm
// that holds its processes), "disk" (one file larger than the run's disk limit). Arguments: --mode M --input
// ODOMETRY.tum --output-dir RAW --reference ABS --reference-dotdot REL
//            --decoy FILE --host-tmp FILE --port N --marker TEXT --storm N --disk-mb N
#include <arpa/inet.h>
#include <dirent.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <linux/capability.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/ptrace.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::map<std::string, std::string> g_args;

std::string Arg(const std::string& name) {
  const auto found = g_args.find(name);
  return found == g_args.end() ? std::string() : found->second;
}

void Report(const std::string& name, bool succeeded, const std::string& detail) {
  std::cout << "ATTEMPT " << name << ": " << (succeeded ? "SUCCEEDED" : "refused") << " (" << detail << ")"
            << std::endl;
}

std::string Error() { return std::strerror(errno); }

/// The first bytes of a file, or nullopt-like empty with `ok` false and errno set.
std::string ReadSome(const std::string& path, bool& ok, std::size_t limit = 4096) {
  ok = false;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return {};
  std::string content(limit, '\0');
  const ssize_t n = ::read(fd, content.data(), content.size());
  const int saved = errno;
  ::close(fd);
  errno = saved;
  if (n < 0) return {};
  content.resize(static_cast<std::size_t>(n));
  ok = true;
  return content;
}

void TryRead(const std::string& name, const std::string& path) {
  bool ok = false;
  const std::string content = ReadSome(path, ok);
  if (ok && !content.empty()) {
    Report(name, true, "read " + std::to_string(content.size()) + " bytes of " + path);
  } else {
    Report(name, false, path + ": " + (ok ? "empty" : Error()));
  }
}

void TryWrite(const std::string& name, const std::string& path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    Report(name, false, path + ": " + Error());
    return;
  }
  const bool wrote = ::write(fd, "hostile\n", 8) == 8;
  ::close(fd);
  Report(name, wrote, (wrote ? "wrote " : "opened but could not write ") + path);
}

/// The slamsweep worker running this run, found by its command line, or 0 when none is visible.
pid_t FindWorker(const std::string& run_dir) {
  DIR* proc = ::opendir("/proc");
  if (proc == nullptr) return 0;
  pid_t found = 0;
  while (const dirent* entry = ::readdir(proc)) {
    if (entry->d_name[0] < '1' || entry->d_name[0] > '9') continue;
    bool ok = false;
    std::string cmdline = ReadSome(std::string("/proc/") + entry->d_name + "/cmdline", ok, 65536);
    for (char& c : cmdline) c = c == '\0' ? ' ' : c;
    if (ok && cmdline.find(" worker ") != std::string::npos && cmdline.find(run_dir) != std::string::npos) {
      found = static_cast<pid_t>(std::stol(entry->d_name));
      break;
    }
  }
  ::closedir(proc);
  return found;
}

int CountProcesses() {
  DIR* proc = ::opendir("/proc");
  if (proc == nullptr) return 0;
  int count = 0;
  while (const dirent* entry = ::readdir(proc)) count += entry->d_name[0] >= '1' && entry->d_name[0] <= '9';
  ::closedir(proc);
  return count;
}

void Attempts(const std::string& raw_dir) {
  const std::string run_dir = raw_dir.substr(0, raw_dir.rfind('/'));
  TryRead("shared_reference_absolute", Arg("reference"));
  TryRead("shared_reference_dotdot", Arg("reference-dotdot"));
  TryRead("decoy_output_reference", Arg("decoy"));
  TryRead("own_run_json", run_dir + "/run.json");

  const pid_t parent = ::getppid();
  const pid_t worker = FindWorker(run_dir);
  const std::string target = std::to_string(worker != 0 ? worker : parent);
  Report("see_worker_process", worker != 0,
         worker != 0 ? "the worker is pid " + std::to_string(worker)
                     : "no worker among the " + std::to_string(CountProcesses()) + " processes in /proc");
  {
    bool ok = false;
    std::string environ = ReadSome("/proc/" + target + "/environ", ok, 1 << 20);
    const bool found = ok && environ.find(Arg("marker")) != std::string::npos;
    Report(
        "proc_ppid_environ", found,
        "/proc/" + target + "/environ: " + (ok ? (found ? "holds the worker's secret" : "no secret in it") : Error()));
  }
  {
    bool ok = false;
    std::string cmdline = ReadSome("/proc/" + target + "/cmdline", ok, 65536);
    for (char& c : cmdline) c = c == '\0' ? ' ' : c;
    const bool found = ok && cmdline.find(" worker ") != std::string::npos;
    Report("proc_ppid_cmdline", found,
           "/proc/" + target + "/cmdline: " +
               (ok ? (found ? cmdline.substr(0, 200) : "not the worker's: " + cmdline.substr(0, 80)) : Error()));
  }
  TryRead("proc_ppid_root", "/proc/" + target + "/root" + Arg("reference"));
  {
    const int fd = ::open(("/proc/" + target + "/mem").c_str(), O_RDONLY | O_CLOEXEC);
    char byte = 0;
    // Any mapped address will do: the page holding the auxiliary vector's first entry.
    bool ok = false;
    const std::string maps = ReadSome("/proc/" + target + "/maps", ok, 256);
    unsigned long address = 0;
    if (ok) address = std::stoul(maps.substr(0, maps.find('-')), nullptr, 16);
    const bool read = fd >= 0 && address != 0 && ::pread(fd, &byte, 1, static_cast<off_t>(address)) == 1;
    Report("proc_ppid_mem", read, "/proc/" + target + "/mem: " + (read ? "read its memory" : Error()));
    if (fd >= 0) ::close(fd);
  }
  TryRead("proc_1_environ", "/proc/1/environ");
  {
    const long attached = ::ptrace(PTRACE_ATTACH, parent, nullptr, nullptr);
    Report("ptrace_parent", attached == 0,
           "PTRACE_ATTACH " + std::to_string(parent) + ": " + (attached == 0 ? "attached" : Error()));
    if (attached == 0) ::ptrace(PTRACE_DETACH, parent, nullptr, nullptr);
  }
  if (worker != 0) {
    const pid_t group = ::getpgid(worker);
    const bool signalled = group > 0 && ::kill(-group, SIGCONT) == 0;
    Report("kill_worker_group", signalled,
           "SIGCONT to the worker's group " + std::to_string(group) + ": " + (signalled ? "delivered" : Error()));
  } else {
    Report("kill_worker_group", false, "the worker is not in this PID namespace: no pid to signal");
  }
  {
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(std::stoi(Arg("port"))));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    const bool connected = fd >= 0 && ::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0;
    Report("tcp_loopback_listener", connected, "127.0.0.1:" + Arg("port") + ": " + (connected ? "connected" : Error()));
    if (fd >= 0) ::close(fd);
  }
  // Beside its input/ and raw/: the run folder and the sweep's output folder above it must be read-only to it.
  TryWrite("write_run_folder", run_dir + "/hostile-was-here");
  {
    const std::string folder = run_dir + "/hostile-folder";
    const bool made = ::mkdir(folder.c_str(), 0755) == 0;
    Report("mkdir_run_folder", made, (made ? "made " : "") + folder + (made ? "" : ": " + Error()));
  }
  TryWrite("write_output_folder", run_dir.substr(0, run_dir.rfind("/runs/")) + "/hostile-was-here");
  TryWrite("write_input_folder", run_dir + "/input/hostile-was-here");
  TryWrite("write_decoy_output", Arg("decoy") + ".hostile");
  TryWrite("write_root", "/hostile-was-here");
  TryRead("read_host_tmp", Arg("host-tmp"));
  // Judged by the test: a sandbox's own /tmp takes the file, the host's must not.
  TryWrite("write_tmp", Arg("host-tmp") + ".hostile");
  {
    // From the kernel, not /proc (a sandbox may have none).
    __user_cap_header_struct header{_LINUX_CAPABILITY_VERSION_3, 0};
    __user_cap_data_struct data[2]{};
    const bool read = ::syscall(SYS_capget, &header, data) == 0;
    const bool holds =
        !read || data[0].effective != 0 || data[1].effective != 0 || data[0].permitted != 0 || data[1].permitted != 0;
    std::ostringstream caps;
    caps << std::hex << "effective " << data[1].effective << data[0].effective << ", permitted " << data[1].permitted
         << data[0].permitted;
    Report("hold_capabilities", holds, read ? caps.str() : "capget: " + Error());
    // Without no_new_privs a setuid program (mount, su, ping) would give its privilege back.
    const int no_new_privs = ::prctl(PR_GET_NO_NEW_PRIVS, 0, 0, 0, 0);
    Report("gain_privileges_by_exec", no_new_privs != 1, "PR_GET_NO_NEW_PRIVS " + std::to_string(no_new_privs));
  }
  {
    // A user namespace of its own would give it every capability over new namespaces (and the kernel's code
    // for them): then a fresh /proc, or mounts of its own over what it was given.
    const pid_t child = ::fork();
    if (child == 0) {
      if (::unshare(CLONE_NEWUSER | CLONE_NEWNS) != 0) _exit(10);
      ::mkdir("/tmp/hostile-proc", 0755);
      _exit(::mount("proc", "/tmp/hostile-proc", "proc", 0, nullptr) == 0 ? 0 : 11);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    Report("nested_user_namespace", code != 10,
           code == 10  ? "unshare(CLONE_NEWUSER) refused"
           : code == 0 ? "made one and mounted a proc in it"
                       : "made one");
    ::mkdir("/tmp/hostile-proc", 0755);
    const int mounted = ::mount("proc", "/tmp/hostile-proc", "proc", 0, nullptr);
    Report("mount_proc", mounted == 0, mounted == 0 ? "mounted a proc" : "mount proc: " + Error());
  }
  // Undo the file system the program was given: unmount what could cover or hold a secret, then
  // read again. "/" stays, so that the program can still write its result.
  const std::string out_dir = run_dir.substr(0, run_dir.rfind("/runs/"));
  int unmounted = 0;
  std::string umount_errors;
  for (const std::string& target :
       std::vector<std::string>{out_dir, run_dir + "/input", raw_dir, Arg("shared"), "/tmp", "/proc", "/dev", "/usr"}) {
    if (::umount2(target.c_str(), MNT_DETACH) == 0) {
      ++unmounted;
      umount_errors += target + " unmounted; ";
    } else {
      umount_errors += target + ": " + Error() + "; ";
    }
  }
  Report("umount", unmounted > 0, umount_errors);
  const int mounted = ::mount("none", "/tmp", "tmpfs", 0, nullptr);
  Report("mount", mounted == 0, mounted == 0 ? "mounted a tmpfs on /tmp" : "mount tmpfs /tmp: " + Error());
  TryRead("reference_after_umount", Arg("reference"));
  TryRead("decoy_after_umount", Arg("decoy"));
  {
    const int created = ::symlink(Arg("reference").c_str(), (raw_dir + "/stolen-reference.tum").c_str());
    // Judged by the test: the worker must remove the link before it reads raw/.
    std::cout << "NOTE symlink_out_of_raw: " << (created == 0 ? "made raw/stolen-reference.tum" : "symlink: " + Error())
              << std::endl;
  }
  // Left behind on purpose: the run must end it when the program exits (the test looks for it).
  if (::fork() == 0) {
    ::setsid();
    if (::fork() == 0) {
      for (int i = 0; i < 120; ++i) ::sleep(1);
      ::_exit(0);
    }
    ::_exit(0);
  }
  std::cout << "NOTE setsid_daemon: started; the test checks that it did not outlive the run" << std::endl;
}

void ForkStorm() {
  const int wanted = std::stoi(Arg("storm"));
  std::vector<pid_t> children;
  std::string error;
  for (int i = 0; i < wanted; ++i) {
    const pid_t child = ::fork();
    if (child == 0) {
      ::sleep(30);
      ::_exit(0);
    }
    if (child < 0) {
      error = Error();
      break;
    }
    children.push_back(child);
  }
  Report("fork_storm", static_cast<int>(children.size()) == wanted,
         "started " + std::to_string(children.size()) + " of " + std::to_string(wanted) + " processes" +
             (error.empty() ? "" : ": " + error));
  ::sleep(5);  // holding them, as a fork bomb would
  for (const pid_t child : children) ::kill(child, SIGKILL);
  while (::wait(nullptr) > 0) {
  }
}

void BigFile(const std::string& raw_dir) {
  const long long bytes = (std::stoll(Arg("disk-mb")) + 1) << 20;
  const int fd = ::open((raw_dir + "/big.bin").c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  std::vector<char> block(1 << 20, 'x');
  long long written = 0;
  while (fd >= 0 && written < bytes) {
    const ssize_t n = ::write(fd, block.data(), block.size());
    if (n <= 0) break;
    written += n;
  }
  Report("big_file", written >= bytes,
         "wrote " + std::to_string(written >> 20) + " of " + std::to_string(bytes >> 20) + " MB");
  if (fd >= 0) ::close(fd);
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string name = argv[i];
    if (name.rfind("--", 0) == 0) g_args[name.substr(2)] = argv[i + 1];
  }
  const std::string raw_dir = Arg("output-dir");
  const std::string mode = Arg("mode");
  if (mode == "attempts") Attempts(raw_dir);
  if (mode == "fork") ForkStorm();
  if (mode == "disk") BigFile(raw_dir);
  // The scored part: the odometry it was given, as its trajectory.
  std::ifstream in(Arg("input"), std::ios::binary);
  std::ofstream out(raw_dir + "/trajectory.tum", std::ios::binary);
  out << in.rdbuf();
  return out ? 0 : 1;
}
