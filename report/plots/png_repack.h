#pragma once

#include <filesystem>

namespace slamsweep::report::inline plots {

/// Rewrites a drawn figure (gnuplot's RGB PNG) as a palette PNG when it has at most 256 colours and that is
/// smaller: the same pixels in a third to a half of the bytes. Leaves the file as it is otherwise, or when it
/// cannot be read or replaced (the figure stays correct, only larger).
void RepackAsPalettePng(const std::filesystem::path& png);

}  // namespace slamsweep::report::inline plots
