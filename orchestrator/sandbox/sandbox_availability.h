#pragma once

#include <filesystem>
#include <string>

namespace slamsweep::orchestrator::inline sandbox {

/// Where the sandbox's programs are on this machine: bubblewrap (bwrap in PATH, Debian's
/// `bubblewrap`) and slamsweep-sandbox-init (beside the slamsweep programs, evaluator/core/installation.h).
/// `missing` is empty when both were found, else it says which is missing and how to install it.
/// Whether the kernel lets bubblewrap make its namespaces shows only when a run starts (a container
/// whose seccomp profile refuses them): that run then fails to start with bubblewrap's message.
struct SandboxPrograms {
  std::filesystem::path bwrap;
  std::filesystem::path init;
  std::string missing;
};

/// Looked up once per process.
const SandboxPrograms& FindSandboxPrograms();

}  // namespace slamsweep::orchestrator::inline sandbox
