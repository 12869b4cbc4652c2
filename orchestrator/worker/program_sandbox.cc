#include "orchestrator/worker/program_sandbox.h"

#include <pwd.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include <spdlog/spdlog.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/sandbox/bwrap_command.h"
#include "orchestrator/sandbox/proc_choice.h"

namespace slamsweep::orchestrator::inline worker {
namespace fs = std::filesystem;
namespace {

/// Absolute, with symbolic links resolved as far as the path exists: what bubblewrap will bind.
fs::path Resolved(const fs::path& path) {
  std::error_code error;
  const fs::path resolved = fs::weakly_canonical(fs::absolute(path), error);
  return error ? fs::absolute(path).lexically_normal() : resolved;
}

bool Inside(const fs::path& path, const fs::path& folder) {
  const fs::path relative = path.lexically_relative(folder);
  return !relative.empty() && *relative.begin() != "..";
}

/// The program file as exec will find it: a path with a '/' from the working folder, else the first
/// match in PATH.
fs::path ProgramFile(const std::string& program, const fs::path& working_dir) {
  if (program.find('/') != std::string::npos) return (working_dir / program).lexically_normal();
  std::istringstream path(std::getenv("PATH") != nullptr ? std::getenv("PATH") : "");
  std::string folder;
  while (std::getline(path, folder, ':')) {
    std::error_code error;
    const fs::path candidate = fs::path(folder.empty() ? "." : folder) / program;
    if (fs::is_regular_file(candidate, error)) return fs::absolute(candidate).lexically_normal();
  }
  return {};
}

struct Secret {
  fs::path path;
  std::string what;
};

std::vector<Secret> Secrets(const RunSpec& spec, const RunPaths& paths) {
  const fs::path run_dir = fs::absolute(paths.root).lexically_normal();
  // OUT/runs/<id>: all of OUT; a run folder elsewhere: that folder.
  const bool in_sweep = run_dir.parent_path().filename() == "runs";
  std::vector<Secret> secrets = {
      {Resolved(in_sweep ? run_dir.parent_path().parent_path() : run_dir), "the sweep's output folder"}};
  const auto& entry = spec.sequence.entry;
  // Their whole folders: a dataset's folder holds its other references too. A log is a reference
  // only when its poses are the ground truth (a corrected log).
  std::vector<std::string> truths = {entry.relations_path, entry.reference_map_path};
  if (entry.ground_truth != evaluator::GroundTruthKind::kNone) truths.push_back(entry.path);
  for (const std::string& truth : truths) {
    if (!truth.empty()) secrets.push_back({Resolved(truth).parent_path(), "a folder of the sequence's reference"});
  }
  if (const char* extra = std::getenv(kPrivateDirsVariable); extra != nullptr) {
    std::istringstream folders(extra);
    std::string folder;
    while (std::getline(folders, folder, ':')) {
      if (!folder.empty()) secrets.push_back({Resolved(folder), "a private folder (SLAMSWEEP_PRIVATE_DIRS)"});
    }
  }
  return secrets;
}

/// The user a sandbox started by root runs as: nobody, the account of no privilege every system has.
SandboxSpec::User Nobody() {
  if (const passwd* entry = ::getpwnam("nobody"); entry != nullptr) return {entry->pw_uid, entry->pw_gid};
  return {65534, 65534};
}

/// Gives `folder` and everything in it to `user` (not following links).
void HandOver(const fs::path& folder, const SandboxSpec::User& user) {
  std::error_code error;
  if (::lchown(folder.c_str(), user.uid, user.gid) != 0) {
    throw evaluator::InputError("cannot hand " + folder.string() + " to the sandbox's user: " + std::strerror(errno));
  }
  for (fs::recursive_directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    (void)::lchown(it->path().c_str(), user.uid, user.gid);
  }
}

}  // namespace

void AddPrivateDirs(const std::vector<fs::path>& folders) {
  const char* inherited = std::getenv(kPrivateDirsVariable);
  std::string value = inherited != nullptr ? inherited : "";
  for (const fs::path& folder : folders) {
    if (folder.empty()) continue;
    if (!value.empty()) value.push_back(':');
    value.append(fs::absolute(folder).lexically_normal().string());
  }
  ::setenv(kPrivateDirsVariable, value.c_str(), 1);
}

void DecideSandboxProcForWorkers() {
  const SandboxPrograms& programs = FindSandboxPrograms();
  if (!programs.missing.empty()) return;
  const SandboxProcChoice choice = orchestrator::DecideSandboxProcForWorkers(programs.bwrap);
  if (!choice.fresh_proc) spdlog::info("SLAM programs' sandboxes have no /proc here: {}", choice.why);
}

SandboxSpec ProgramSandbox(const RunSpec& spec, const RunPaths& paths, const std::vector<fs::path>& reads,
                           const std::string& program, const SandboxPrograms& programs,
                           const fs::path& pids_cgroup_procs, bool fresh_proc) {
  SandboxSpec sandbox;
  sandbox.fresh_proc = fresh_proc;
  sandbox.bwrap_program = programs.bwrap;
  sandbox.init_program = programs.init;
  sandbox.network = spec.algorithm.network;
  sandbox.process_limit = spec.algorithm.process_limit;
  sandbox.file_size_limit_bytes = spec.algorithm.disk_limit_mb << 20;
  sandbox.pids_cgroup_procs = pids_cgroup_procs;
  if (::geteuid() == 0 && pids_cgroup_procs.empty()) {
    // Root is exempt from RLIMIT_NPROC, even mapped into a user namespace: the sandbox runs as nobody,
    // who owns the run's raw/ (and input/, so that a strict umask cannot hide it).
    sandbox.user = Nobody();
    HandOver(paths.RawDir(), *sandbox.user);
    HandOver(paths.InputDir(), *sandbox.user);
  }
  const fs::path working_dir = fs::absolute(paths.ProgramWorkingDir()).lexically_normal();
  sandbox.writable = {working_dir};
  sandbox.read_only = {fs::absolute(paths.InputDir()).lexically_normal()};
  const std::vector<Secret> secrets = Secrets(spec, paths);
  std::vector<fs::path> system;
  for (const fs::path& path : SystemPaths()) system.push_back(Resolved(path));
  const auto in_system = [&](const fs::path& path) {
    return std::any_of(system.begin(), system.end(), [&](const fs::path& folder) { return Inside(path, folder); });
  };
  // The program's own file alone, wherever it is: a file shows nothing beside it.
  if (const fs::path file = ProgramFile(program, working_dir); !file.empty() && !in_system(Resolved(file))) {
    sandbox.read_only.push_back(file);
  }
  // A secret under /usr (a dataset installed by a package) is covered by an empty folder.
  for (const Secret& secret : secrets) {
    if (in_system(secret.path)) sandbox.hidden.push_back(secret.path);
  }
  std::error_code error;
  for (const fs::path& read : reads) {
    if (!fs::exists(read, error)) continue;
    const fs::path shown = Resolved(read);
    if (in_system(shown)) continue;  // visible anyway, with the secrets in it covered
    for (const Secret& secret : secrets) {
      if (Inside(secret.path, shown) || Inside(shown, secret.path)) {
        throw evaluator::InputError("the program's sandbox would show " + read.string() + ", which holds or lies in " +
                                    secret.what + " (" + secret.path.string() + "): the program may not read it");
      }
    }
    sandbox.read_only.push_back(fs::absolute(read).lexically_normal());
  }
  return sandbox;
}

}  // namespace slamsweep::orchestrator::inline worker
