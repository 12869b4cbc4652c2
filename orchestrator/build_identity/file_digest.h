#pragma once

#include <filesystem>
#include <string>

namespace slamsweep::orchestrator::inline build_identity {

/// SHA-256 of a file's bytes as 64 lowercase hex digits (OpenSSL). Throws InputError naming the
/// file when it cannot be read.
std::string Sha256OfFile(const std::filesystem::path& file);

/// SHA-256 of `bytes`, as Sha256OfFile.
std::string Sha256OfBytes(std::string_view bytes);

}  // namespace slamsweep::orchestrator::inline build_identity
