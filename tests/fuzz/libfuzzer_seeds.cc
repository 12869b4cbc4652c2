// In a fuzz build, where libFuzzer owns main: `fuzz_<target> --write-seeds=DIR` writes the target's seeds
// and exits before any fuzzing (jobs/fuzz-check.sh starts each target's corpus this way).
#include <cstdlib>
#include <string>
#include <string_view>

#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  constexpr std::string_view kWriteSeeds = "--write-seeds=";
  for (int i = 1; i < *argc; ++i) {
    const std::string_view argument = (*argv)[i];
    if (argument.starts_with(kWriteSeeds)) {
      std::exit(slamsweep::fuzz::WriteSeeds(std::string(argument.substr(kWriteSeeds.size()))));
    }
  }
  return 0;
}
