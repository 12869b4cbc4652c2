#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace slamsweep::evaluator::inline formats::inline trajectory {

/// Creates (or truncates) `path` and lets `write` fill it. A failure to open or to write is an
/// InputError naming the path, and the half-written file is removed so no one reads it as whole.
void WriteOutputFile(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);

/// The shortest decimal text that reads back as exactly `value` ("0.1", "1e-07"), so that
/// every writer in this folder round-trips doubles bit for bit.
std::string ShortestText(double value);

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
