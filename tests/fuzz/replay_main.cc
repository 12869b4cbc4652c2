// The plain main of a fuzz target in the normal build: writes the target's seeds (--write-seeds=DIR) and
// feeds every file of the folders and files named on the command line to LLVMFuzzerTestOneInput, once
// each, in name order. ctest runs it on the seeds and on corpus/<target>/ (the findings kept as
// regressions). A finding aborts; a path that does not exist, or nothing to replay, is an error (exit 2).
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "tests/fuzz/fuzz_support.h"

namespace {

std::vector<std::filesystem::path> InputsOf(const std::filesystem::path& path) {
  std::vector<std::filesystem::path> inputs;
  if (std::filesystem::is_directory(path)) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(path)) {
      if (entry.is_regular_file()) inputs.push_back(entry.path());
    }
    std::sort(inputs.begin(), inputs.end());
  } else {
    inputs.push_back(path);
  }
  return inputs;
}

}  // namespace

int main(int argc, char** argv) {
  slamsweep::fuzz::SetShowRejections(true);
  std::vector<std::filesystem::path> paths;
  for (int i = 1; i < argc; ++i) {
    const std::string_view argument = argv[i];
    constexpr std::string_view kWriteSeeds = "--write-seeds=";
    if (argument.starts_with(kWriteSeeds)) {
      if (const int status = slamsweep::fuzz::WriteSeeds(std::string(argument.substr(kWriteSeeds.size())));
          status != 0) {
        return status;
      }
    } else {
      paths.emplace_back(argument);
    }
  }
  std::size_t replayed = 0;
  for (const std::filesystem::path& path : paths) {
    if (!std::filesystem::exists(path)) {
      std::cerr << "replay: " << path.string() << " does not exist\n";
      return 2;
    }
    std::size_t here = 0;
    for (const std::filesystem::path& input : InputsOf(path)) {
      std::ifstream in(input, std::ios::binary);
      const std::string bytes(std::istreambuf_iterator<char>(in), {});
      std::cout << "replaying " << input.string() << " (" << bytes.size() << " bytes)" << std::endl;
      LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
      ++here;
    }
    std::cout << "replayed " << here << " inputs from " << path.string() << "\n";
    replayed += here;
  }
  if (replayed == 0) {
    std::cerr << "replay: nothing to replay (usage: " << argv[0] << " [--write-seeds=DIR] PATH...)\n";
    return 2;
  }
  std::cout << "replayed " << replayed << " inputs: no finding\n";
  return 0;
}
