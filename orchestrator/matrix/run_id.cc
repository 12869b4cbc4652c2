#include "orchestrator/matrix/run_id.h"
#include "orchestrator/run/run_json.h"

#include <fmt/format.h>

namespace slamsweep::orchestrator::inline matrix {

std::string SanitizeIdPart(std::string_view text) {
  constexpr std::size_t kMaxChars = 32;
  std::string part;
  for (const char c : text) {
    if (part.size() == kMaxChars) break;
    if (part.empty() && c == '.') continue;
    const bool allowed =
        (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.' || c == '-';
    part += allowed ? c : '_';
  }
  return part.empty() ? "_" : part;
}

std::string MakeRunId(const RunSpec& spec) {
  // dump() of an nlohmann::json object lists keys sorted, so the text (and the hash) is canonical.
  const std::uint64_t hash = Fnv1a64(RunIdentity(spec).dump());
  return fmt::format("{}-{}-{}-i{}-{:08x}", SanitizeIdPart(spec.algorithm.name),
                     SanitizeIdPart(spec.sequence.entry.name), SanitizeIdPart(spec.noise.name), spec.iteration,
                     static_cast<std::uint32_t>(hash >> 32));
}

}  // namespace slamsweep::orchestrator::inline matrix
