#pragma once

#include <string>
#include <string_view>

namespace slamsweep::report::inline plots {

/// `text` as a gnuplot string expression that evaluates to exactly `text`, for any command that
/// takes a string (`set title`, `set output`, xtics labels, `print`). Built from single-quoted
/// literals, in which gnuplot expands nothing (no backslash escapes, no `command` substitution,
/// which it DOES do inside double quotes, no @macros). A single quote itself is not written as
/// gnuplot's doubled '' (gnuplot 5.4 misreads it at the start of a string or twice in a row) but
/// joined in as sprintf('%c', 39): "it's" -> 'it' . sprintf('%c', 39) . 's'. Control characters
/// (newline, tab, ...) would end the command and become spaces. Callers must also draw the text
/// `noenhanced`, or ^ _ { } @ & would still be read as markup.
std::string GnuplotQuoted(std::string_view text);

}  // namespace slamsweep::report::inline plots
