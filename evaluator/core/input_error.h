#pragma once

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

// Spelled the C++17 way: the ROS message library, which is C++17, includes this header.
namespace slamsweep::evaluator {
inline namespace core {

/// Thrown for bad input (files, options, data that cannot be scored). The message
/// always names where the problem is (file, line, field) and what was expected, so
/// the command line can print it as is and exit 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// "FILE:LINE: message" (LINE omitted when 0), the form compilers use, so editors
/// and Jenkins log parsers can jump to the place.
std::string Located(const std::filesystem::path& file, std::size_t line, std::string_view message);

}  // namespace core
}  // namespace slamsweep::evaluator
