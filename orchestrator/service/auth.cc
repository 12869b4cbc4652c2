#include "orchestrator/service/auth.h"

#include <arpa/inet.h>
#include <openssl/crypto.h>
#include <openssl/sha.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator::service {
namespace {

std::string Sha256(std::string_view text) {
  unsigned char digest[SHA256_DIGEST_LENGTH];
  SHA256(reinterpret_cast<const unsigned char*>(text.data()), text.size(), digest);
  return std::string(reinterpret_cast<const char*>(digest), sizeof digest);
}

std::string_view Trimmed(std::string_view text) {
  const auto begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string_view::npos) return {};
  const auto end = text.find_last_not_of(" \t\r\n");
  return text.substr(begin, end - begin + 1);
}

}  // namespace

std::string ReadTokenFile(const std::filesystem::path& file) {
  struct stat info = {};
  if (::stat(file.c_str(), &info) != 0)
    throw evaluator::InputError(fmt::format("--token-file {}: no such file", file.string()));
  if (!S_ISREG(info.st_mode))
    throw evaluator::InputError(fmt::format("--token-file {}: not a regular file", file.string()));
  if ((info.st_mode & 077) != 0) {
    throw evaluator::InputError(
        fmt::format("--token-file {}: mode {:04o} lets other users read the token; expected 0600 (chmod 600 {})",
                    file.string(), info.st_mode & 07777, file.string()));
  }
  if (info.st_uid != ::geteuid()) {
    throw evaluator::InputError(fmt::format("--token-file {}: owned by uid {}, expected the server's user (uid {})",
                                            file.string(), info.st_uid, ::geteuid()));
  }
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  const std::string token(Trimmed(text.str()));
  if (token.empty())
    throw evaluator::InputError(fmt::format("--token-file {}: empty; expected a token", file.string()));
  if (token.find_first_of(" \t\r\n") != std::string::npos) {
    throw evaluator::InputError(fmt::format("--token-file {}: expected one token without white space", file.string()));
  }
  return token;
}

BearerAuth::BearerAuth(std::optional<std::string> token) {
  if (token) digest_ = Sha256(*token);
}

BearerAuth::Verdict BearerAuth::Check(const std::optional<std::string_view>& authorization) const {
  if (!digest_) return Verdict::kAllowed;
  constexpr std::string_view kScheme = "Bearer ";
  if (!authorization || authorization->size() <= kScheme.size() ||
      authorization->substr(0, kScheme.size()) != kScheme) {
    return Verdict::kMissing;
  }
  const std::string given = Sha256(Trimmed(authorization->substr(kScheme.size())));
  return CRYPTO_memcmp(given.data(), digest_->data(), given.size()) == 0 ? Verdict::kAllowed : Verdict::kWrong;
}

bool IsLoopbackAddress(std::string_view host) {
  if (host == "localhost") return true;
  const std::string text(host);
  in_addr v4 = {};
  if (::inet_pton(AF_INET, text.c_str(), &v4) == 1) return (ntohl(v4.s_addr) >> 24) == 127;
  in6_addr v6 = {};
  if (::inet_pton(AF_INET6, text.c_str(), &v6) == 1) return IN6_IS_ADDR_LOOPBACK(&v6);
  return false;
}

}  // namespace slamsweep::orchestrator::service
