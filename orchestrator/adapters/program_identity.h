#pragma once
// What a run's result depends on besides its inputs, per adapter: the program files and whether the
// seed reaches the program. Kept apart from the adapters' run-time code (adapter.h) so that planning a
// sweep needs none of the map and image libraries that running one does.
#include <filesystem>
#include <string_view>
#include <vector>

#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline adapters {

/// The files a run of `algorithm` executes or reads as its program's configuration (binary,
/// wrapper script, configuration template), found as the worker will find them: their digests
/// are the run's build identity. A program that cannot be found is an InputError saying so, and
/// so is an unknown adapter (UnknownAdapter).
std::vector<std::filesystem::path> ProgramFilesOf(const AlgorithmSpec& algorithm);

/// Whether a run of `algorithm` can be reproduced from its seed.
Seeding SeedingOf(const AlgorithmSpec& algorithm);

/// The InputError for an adapter name no adapter has, listing the known ones.
[[noreturn]] void ThrowUnknownAdapter(std::string_view name);

}  // namespace slamsweep::orchestrator::inline adapters
