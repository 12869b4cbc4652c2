#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace slamsweep::orchestrator::inline config {

/// The placeholders of a command declaration's argv and output paths (besides {param:NAME}):
/// {input} the program's input file, {input_dir} the folder holding it, {output_dir} the program's
/// output folder (also its working directory), {seed} the run's 64-bit seed, {seed32} Seed32 of it,
/// {iteration}. There is deliberately no placeholder for the run folder: it holds the run's record.
inline constexpr std::string_view kPlaceholderNames[] = {"input", "input_dir", "output_dir",
                                                         "seed",  "seed32",    "iteration"};
inline constexpr std::string_view kParameterPlaceholderPrefix = "param:";

/// One piece of a template: literal text, or the name inside a {placeholder}.
struct TemplatePiece {
  bool is_placeholder = false;
  std::string text;
};

/// Splits `text` into literal pieces and {name} placeholders. "{{" and "}}" are literal braces, so
/// "{{input}}" is the literal text "{input}". Throws InputError (the message names no file: callers
/// add where the text came from) for a lone '}', a '{' without its '}', an empty "{}" or a '{' inside
/// a placeholder. The names are not checked: see CheckPlaceholderName.
std::vector<TemplatePiece> ParseTemplate(std::string_view text);

/// Throws InputError unless `name` is one of kPlaceholderNames or "param:P" with P in `parameters`;
/// the message lists what is accepted.
void CheckPlaceholderName(std::string_view name, std::span<const std::string> parameters);

/// "{input}, {input_dir}, ..., {param:NAME}, {{, }}": what a template accepts, for messages.
std::string AcceptedPlaceholders();

}  // namespace slamsweep::orchestrator::inline config
