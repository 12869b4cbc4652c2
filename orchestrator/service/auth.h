#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace slamsweep::orchestrator::service {

/// The bearer token of `--token-file`: the file must be a regular file owned by the server's user
/// and readable by nobody else (mode 0600 or 0400), since anyone who can read it can run sweeps.
/// Throws InputError naming the file and what is wrong (mode, owner, empty). Surrounding white space
/// (a trailing newline) is not part of the token.
std::string ReadTokenFile(const std::filesystem::path& file);

/// Checks an Authorization header against the token in constant time: the time taken does not depend
/// on how many leading characters are right (both sides are hashed with SHA-256 and the digests
/// compared with OpenSSL's CRYPTO_memcmp).
class BearerAuth {
 public:
  /// nullopt: no token configured; every request is allowed.
  explicit BearerAuth(std::optional<std::string> token);

  enum class Verdict { kAllowed, kMissing, kWrong };
  /// `authorization`: the header's value, or nullopt when the request has none.
  Verdict Check(const std::optional<std::string_view>& authorization) const;
  bool enabled() const { return digest_.has_value(); }

 private:
  std::optional<std::string> digest_;
};

/// True for addresses that only this machine can reach: 127.0.0.0/8, ::1, "localhost".
bool IsLoopbackAddress(std::string_view host);

}  // namespace slamsweep::orchestrator::service
