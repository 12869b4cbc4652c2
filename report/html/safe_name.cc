#include "report/html/safe_name.h"

#include <cstdint>
#include <cstdio>

namespace slamsweep::report::inline html {

namespace {

std::uint64_t Fnv1a64(std::string_view text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}

bool Allowed(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.' || c == '-';
}

}  // namespace

std::string SafeFileName(std::string_view text) {
  constexpr std::size_t kMaxReadable = 64 - 9;  // room for "-" + 8 hex digits
  std::string out;
  for (char c : text) out += Allowed(c) ? c : '_';
  const std::size_t first = out.find_first_not_of('.');
  out.erase(0, first == std::string::npos ? out.size() : first);
  if (out == std::string(text) && !out.empty() && out.size() <= 64) return out;
  if (out.size() > kMaxReadable) out.resize(kMaxReadable);
  char suffix[16];
  std::snprintf(suffix, sizeof suffix, "-%08x", static_cast<unsigned>(Fnv1a64(text) >> 32));
  return out + suffix;
}

bool IsRegularFileNoFollow(const std::filesystem::path& path) {
  std::error_code error;
  return std::filesystem::symlink_status(path, error).type() == std::filesystem::file_type::regular;
}

}  // namespace slamsweep::report::inline html
