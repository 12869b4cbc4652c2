#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace slamsweep::testing {

/// Root of the read-only shared data (spec, datasets, reference values): $SLAMSWEEP_SHARED
/// if set, else the folder configured at build time (../shared beside the repository).
std::filesystem::path SharedRoot();

/// Why a shared file is unavailable, or empty when it is there.
std::string MissingSharedFile(const std::filesystem::path& relative);

/// True under CI (CI=true): there a missing shared file fails the test instead of skipping it,
/// so a broken checkout cannot pass as green.
bool RunningInCi();

/// A temporary directory removed when the object goes out of scope.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

/// Writes `content` to `path` and returns the path.
std::filesystem::path WriteFile(const std::filesystem::path& path, const std::string& content);

}  // namespace slamsweep::testing

/// Skips the test with `why` (a stream expression naming what is missing and how to install it), or
/// fails it under CI=true: there everything a test needs is installed by the project's scripts, so a
/// missing piece is a broken setup, never a pass.
#define SLAMSWEEP_SKIP_OR_FAIL_IN_CI(why)                                        \
  do {                                                                           \
    if (::slamsweep::testing::RunningInCi()) FAIL() << "under CI=true: " << why; \
    GTEST_SKIP() << why;                                                         \
  } while (false)

/// Declares `var` as the absolute path of a file under the shared folder. When it is
/// missing the test is skipped (failed under CI) with a message naming what is missing.
#define SLAMSWEEP_REQUIRE_SHARED(var, relative)                                                  \
  const std::filesystem::path var = ::slamsweep::testing::SharedRoot() / (relative);             \
  if (const std::string why = ::slamsweep::testing::MissingSharedFile(relative); !why.empty()) { \
    if (::slamsweep::testing::RunningInCi()) FAIL() << why;                                      \
    GTEST_SKIP() << why;                                                                         \
  }
