#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "orchestrator/sandbox/sandbox_spec.h"

namespace slamsweep::orchestrator::inline sandbox {

/// The system paths every sandboxed program sees read-only, those of them that exist here: /usr,
/// the /bin, /sbin and /lib* links of a merged-/usr system (or the folders themselves), and the
/// files of /etc that the dynamic linker, the C library and the libraries in /usr read (ld.so.cache,
/// alternatives, time zone, user and host names). Nothing else of /etc, no /home, /root, /var, /run,
/// /srv, /opt or /mnt.
std::vector<std::filesystem::path> SystemPaths();

/// The bubblewrap command that runs `program_argv` in `spec`'s sandbox, in `working_dir` (which must
/// be visible in it), under slamsweep-sandbox-init writing its status lines to `status_fd` (an
/// inherited descriptor). Paths inside a folder already bound are not bound again. Throws
/// std::invalid_argument for a relative path or a missing init program.
std::vector<std::string> BwrapCommand(const SandboxSpec& spec, const std::vector<std::string>& program_argv,
                                      const std::filesystem::path& working_dir, int status_fd);

}  // namespace slamsweep::orchestrator::inline sandbox
