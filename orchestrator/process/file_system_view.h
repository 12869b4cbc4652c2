#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace slamsweep::orchestrator {

/// What a started program may see of the file system. Each `hidden` folder is covered, in the
/// program's own mount namespace only, by an empty tmpfs; each `visible` folder inside a hidden one
/// is then bound back at its own path. Nothing changes for any other process. A SLAM program gets
/// its input and output folders this way, while the sweep's results (other runs' reference.tum,
/// result.json, the reference-map cache, results.sqlite) and the dataset folders holding the
/// reference stay out of its reach, however it spells their paths.
struct FileSystemView {
  std::vector<std::filesystem::path> hidden;
  std::vector<std::filesystem::path> visible;

  bool empty() const { return hidden.empty(); }
};

/// Whether this process can start programs with a FileSystemView: "" when it can, else why not
/// (e.g. "unshare: Operation not permitted" in a container without user namespaces). Root needs a
/// mount namespace; other users also a user namespace mapping them to themselves. Probed once, by
/// starting a child that sets up a view of a scratch folder.
const std::string& FileSystemViewUnavailableReason();

/// The view's system calls, prepared before fork: the child may only make async-signal-safe calls.
struct PreparedFileSystemView {
  bool user_namespace = false;  ///< not root: a user namespace mapping uid and gid onto themselves
  std::string uid_map;
  std::string gid_map;
  std::vector<std::string> hidden;   ///< outermost first; none inside another
  std::vector<std::string> mkdirs;   ///< mount points of `visible` inside the tmpfs, parents first
  std::vector<std::string> visible;  ///< bound back after the tmpfs mounts
};

/// Absolute, normalised paths; hidden folders inside another hidden one dropped; a visible folder
/// outside every hidden one needs nothing. Throws std::invalid_argument for a relative path or for
/// hiding "/".
PreparedFileSystemView PrepareFileSystemView(const FileSystemView& view);

/// In the child, between fork and exec: enters new namespaces and mounts the view. Returns 0, or
/// the errno of the failed step with `*step` naming it. Async-signal-safe; not for a vfork child
/// (a user namespace needs a process of its own).
int ApplyFileSystemView(const PreparedFileSystemView& view, const char** step) noexcept;

}  // namespace slamsweep::orchestrator
