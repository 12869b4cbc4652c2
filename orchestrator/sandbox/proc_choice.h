#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace slamsweep::orchestrator::inline sandbox {

/// Says how sandboxes get their /proc: "own" (a fresh /proc of their PID namespace) or "none" (no /proc
/// at all), optionally followed by ": why". Set by `slamsweep run` and `serve` for their workers after
/// one probe; a user may set "none" (never less isolated: nothing of /proc is shown).
inline constexpr const char* kSandboxProcVariable = "SLAMSWEEP_SANDBOX_PROC";

/// Whether a sandbox can have a /proc of its own here.
struct SandboxProcChoice {
  bool fresh_proc = true;
  /// Why not, when fresh_proc is false: bubblewrap's message, or that SLAMSWEEP_SANDBOX_PROC said so.
  std::string why;
};

/// Runs `bwrap` twice at most (a few milliseconds each): with its own user and PID namespaces and a fresh
/// /proc, then, when that fails, the same without /proc. Only when the second succeeds is the answer
/// "none": the kernel refuses a fresh /proc here (a container whose /proc has masked paths, as Docker's
/// has unless systempaths=unconfined). When both fail, namespaces are unavailable altogether: "own",
/// and every run fails to start with bubblewrap's message, as it would anyway.
SandboxProcChoice ProbeSandboxProc(const std::filesystem::path& bwrap);

/// The choice a value of SLAMSWEEP_SANDBOX_PROC says; std::invalid_argument for anything but "own" and "none[: why]".
SandboxProcChoice SandboxProcFromVariable(std::string_view value);

/// SLAMSWEEP_SANDBOX_PROC when set ("own" or "none..."; anything else throws std::invalid_argument),
/// else ProbeSandboxProc once per process.
const SandboxProcChoice& ChosenSandboxProc(const std::filesystem::path& bwrap);

/// For `run` and `serve`: decides once (ChosenSandboxProc) and sets SLAMSWEEP_SANDBOX_PROC for the
/// workers they start, so that no worker probes again. Call before any thread starts.
SandboxProcChoice DecideSandboxProcForWorkers(const std::filesystem::path& bwrap);

}  // namespace slamsweep::orchestrator::inline sandbox
