#include "orchestrator/config/placeholders.h"

#include <fmt/format.h>

#include <algorithm>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator::inline config {

std::vector<TemplatePiece> ParseTemplate(std::string_view text) {
  std::vector<TemplatePiece> pieces;
  std::string literal;
  const std::string quoted = fmt::format("'{}'", text);
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const bool doubled = i + 1 < text.size() && text[i + 1] == c;
    if ((c == '{' || c == '}') && doubled) {
      literal += c;
      ++i;
      continue;
    }
    if (c == '}') throw evaluator::InputError("a lone '}' in " + quoted + " (write '}}' for a literal brace)");
    if (c != '{') {
      literal += c;
      continue;
    }
    const std::size_t close = text.find_first_of("{}", i + 1);
    if (close == std::string_view::npos || text[close] == '{') {
      throw evaluator::InputError("'{' without its closing '}' in " + quoted + " (write '{{' for a literal brace)");
    }
    if (close == i + 1) throw evaluator::InputError("an empty placeholder '{}' in " + quoted);
    if (!literal.empty()) pieces.push_back({false, std::move(literal)});
    literal.clear();
    pieces.push_back({true, std::string(text.substr(i + 1, close - i - 1))});
    i = close;
  }
  if (!literal.empty()) pieces.push_back({false, std::move(literal)});
  return pieces;
}

std::string AcceptedPlaceholders() {
  std::string accepted;
  for (std::string_view name : kPlaceholderNames) accepted += fmt::format("{{{}}}, ", name);
  return accepted + "{param:NAME}, {{, }}";
}

void CheckPlaceholderName(std::string_view name, std::span<const std::string> parameters) {
  if (name.starts_with(kParameterPlaceholderPrefix)) {
    const std::string_view parameter = name.substr(kParameterPlaceholderPrefix.size());
    if (std::find(parameters.begin(), parameters.end(), parameter) != parameters.end()) return;
    std::string declared;
    for (const std::string& known : parameters) declared += (declared.empty() ? "" : ", ") + known;
    throw evaluator::InputError(fmt::format("{{param:{}}} names no parameter of the algorithm (declared: {})",
                                            parameter, declared.empty() ? "none" : declared));
  }
  if (std::find(std::begin(kPlaceholderNames), std::end(kPlaceholderNames), name) != std::end(kPlaceholderNames)) {
    return;
  }
  throw evaluator::InputError(fmt::format("unknown placeholder {{{}}}; accepted: {}", name, AcceptedPlaceholders()));
}

}  // namespace slamsweep::orchestrator::inline config
