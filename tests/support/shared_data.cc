#include "tests/support/shared_data.h"

#include <fstream>
#include <random>

namespace slamsweep::testing {

std::filesystem::path SharedRoot() {
  if (const char* env = std::getenv("SLAMSWEEP_SHARED"); env != nullptr && *env != '\0') return env;
  return SLAMSWEEP_SHARED_DIR;
}

std::string MissingSharedFile(const std::filesystem::path& relative) {
  const std::filesystem::path full = SharedRoot() / relative;
  if (std::filesystem::exists(full)) return {};
  return "shared test data missing: " + full.string() +
         " (expected the read-only shared/ folder beside the repository, or set SLAMSWEEP_SHARED)";
}

bool RunningInCi() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::string(ci) == "true";
}

TempDir::TempDir() {
  std::random_device device;
  const std::string name = "slamsweep-test-" + std::to_string(device()) + std::to_string(device());
  path_ = std::filesystem::temp_directory_path() / name;
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

std::filesystem::path WriteFile(const std::filesystem::path& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary);
  out << content;
  return path;
}

}  // namespace slamsweep::testing
