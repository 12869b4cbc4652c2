#include "orchestrator/matrix/shard.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <string>

#include "evaluator/core/input_error.h"
#include "orchestrator/matrix/run_id.h"

namespace slamsweep::orchestrator::inline matrix {
namespace {

bool ParseCount(std::string_view text, std::size_t& value) {
  if (text.empty()) return false;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}

}  // namespace

Shard ParseShard(std::string_view text, std::string_view option) {
  const std::size_t slash = text.find('/');
  Shard shard;
  if (slash == std::string_view::npos || !ParseCount(text.substr(0, slash), shard.index) ||
      !ParseCount(text.substr(slash + 1), shard.count)) {
    throw evaluator::InputError(fmt::format(
        "{}: expected I/N with whole numbers, e.g. 2/4 for the second of four shares, got '{}'", option, text));
  }
  if (shard.count == 0 || shard.index == 0 || shard.index > shard.count) {
    throw evaluator::InputError(fmt::format("{}: expected 1 <= I <= N in I/N, got '{}'", option, text));
  }
  return shard;
}

std::vector<RunSpec> SelectShard(std::vector<RunSpec> runs, std::size_t index, std::size_t count) {
  if (count == 0 || index == 0 || index > count) {
    throw evaluator::InputError(fmt::format("shard {}/{}: expected 1 <= I <= N", index, count));
  }
  std::erase_if(runs, [&](const RunSpec& run) { return Fnv1a64(run.run_id) % count + 1 != index; });
  return runs;
}

}  // namespace slamsweep::orchestrator::inline matrix
