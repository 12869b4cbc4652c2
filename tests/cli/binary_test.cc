// The real executable, as Jenkins calls it: exit codes and stdout/stderr separation.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <filesystem>
#include <cstdio>
#include <string>

#include "tests/support/shared_data.h"

namespace slamsweep {
namespace {

struct ProcessResult {
  int exit_code = -1;
  std::string out;
};

/// Runs `PROGRAM ARGS` with `environment` ("NAME=value ..." or ""); stderr is kept when `with_stderr`.
ProcessResult RunProgram(const std::string& program, const std::string& args, const std::string& environment,
                         bool with_stderr) {
  const std::string command = environment + " " + program + " " + args + (with_stderr ? " 2>&1" : " 2>/dev/null");
  ProcessResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) result.out += buffer.data();
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

/// `slamsweep ARGS`, the build's core program.
ProcessResult RunBinary(const std::string& args, const std::string& environment = "", bool with_stderr = false) {
  return RunProgram(SLAMSWEEP_BINARY, args, environment, with_stderr);
}

TEST(BinaryTest, HelpExitsZeroAndListsCommands) {
  const ProcessResult result = RunBinary("--help");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_THAT(result.out, ::testing::HasSubstr("eval"));
  EXPECT_THAT(result.out, ::testing::HasSubstr("vectorize"));
}

TEST(BinaryTest, UsageErrorsExitTwoWithNothingOnStdout) {
  const ProcessResult unknown = RunBinary("frobnicate");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_EQ(unknown.out, "");
  EXPECT_EQ(RunBinary("").exit_code, 2);
  EXPECT_EQ(RunBinary("eval map /nonexistent/map.yaml").exit_code, 2);
}

TEST(BinaryTest, VersionPrintsTheRevision) {
  const ProcessResult result = RunBinary("--version");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_THAT(result.out, ::testing::StartsWith("slamsweep 0."));
}

TEST(BinaryTest, TheCoreLoadsNoHeavyLibrary) {
  // What the dynamic loader maps at start (ldd's way): the map, report, sweep and format libraries
  // belong to the helpers and modules (README "Programs and libraries").
  const ProcessResult result = RunBinary("--version", "LD_TRACE_LOADED_OBJECTS=1");
  EXPECT_THAT(result.out, ::testing::HasSubstr("libstdc++"));
  for (const char* heavy : {"opencv", "mrpt", "ros", "gdal", "assimp", "sqlite", "gif", "spdlog", "png"}) {
    EXPECT_THAT(result.out, ::testing::Not(::testing::HasSubstr(heavy))) << heavy;
  }
}

TEST(BinaryTest, TheCoreLoadsLibcryptoOnlyForADigest) {
  // libcrypto's relocations were two thirds of the core's start-up; it is loaded by the first SHA-256.
  const ProcessResult result = RunBinary("--version", "LD_TRACE_LOADED_OBJECTS=1");
  EXPECT_THAT(result.out, ::testing::HasSubstr("libstdc++"));
  EXPECT_THAT(result.out, ::testing::Not(::testing::HasSubstr("libcrypto")));
}

TEST(BinaryTest, TheWorkerLoadsNoImageCodecLibrary) {
  // Every run starts the sweep program as its worker: OpenCV's imgcodecs would bring GDAL and a hundred
  // more libraries, about 70 ms of loading per run. PNGs are read and written with libpng.
  const ProcessResult result = RunProgram(SLAMSWEEP_SWEEP_BINARY, "--version", "LD_TRACE_LOADED_OBJECTS=1", false);
  EXPECT_THAT(result.out, ::testing::HasSubstr("libpng"));
  for (const char* heavy : {"imgcodecs", "gdal", "mrpt", "ros", "assimp"}) {
    EXPECT_THAT(result.out, ::testing::Not(::testing::HasSubstr(heavy))) << heavy;
  }
}

TEST(BinaryTest, HelperCommandsAreListedAndGetTheirHelp) {
  const ProcessResult help = RunBinary("--help");
  for (const char* command : {"run", "merge", "report", "history", "data", "plan", "algorithms"}) {
    EXPECT_THAT(help.out, ::testing::HasSubstr(command));
  }
  const ProcessResult map_help = RunBinary("eval map --help");
  EXPECT_EQ(map_help.exit_code, 0);
  EXPECT_THAT(map_help.out, ::testing::HasSubstr("--unknown-value"));  // slamsweep-maps' own help
}

/// A stand-in for a helper that says where it was found and what it was given.
void WriteFakeHelper(const std::filesystem::path& path, const std::string& name) {
  std::filesystem::create_directories(path.parent_path());
  testing::WriteFile(path, "#!/bin/sh\necho \"" + name + " $*\"\n");
  std::filesystem::permissions(path, std::filesystem::perms::owner_all);
}

TEST(BinaryTest, HelpersAreFoundNextToTheProgramThenInItsInstalledLibFolder) {
  // A copy of the core in PREFIX/bin: a helper beside it wins, else PREFIX/lib/slamsweep's, both
  // before the build tree's.
  testing::TempDir prefix;
  const std::filesystem::path core = prefix / "bin" / "slamsweep";
  std::filesystem::create_directories(core.parent_path());
  std::filesystem::copy_file(SLAMSWEEP_BINARY, core);
  WriteFakeHelper(prefix / "lib" / "slamsweep" / "slamsweep-maps", "installed");
  EXPECT_EQ(RunProgram(core.string(), "eval map a.yaml --json", "", true).out, "installed eval map a.yaml --json\n");
  WriteFakeHelper(prefix / "bin" / "slamsweep-maps", "beside");
  EXPECT_EQ(RunProgram(core.string(), "vectorize m.pgm", "", true).out, "beside vectorize m.pgm\n");
}

TEST(BinaryTest, MapCommandsStartWithMallocOnHugePagesAndNothingElseDoes) {
  testing::TempDir prefix;
  const std::filesystem::path core = prefix / "bin" / "slamsweep";
  std::filesystem::create_directories(core.parent_path());
  std::filesystem::copy_file(SLAMSWEEP_BINARY, core);
  for (const char* helper : {"slamsweep-maps", "slamsweep-sweep"}) {
    const std::filesystem::path path = prefix / "bin" / helper;
    testing::WriteFile(path, "#!/bin/sh\necho \"tunables=$GLIBC_TUNABLES\"\n");
    std::filesystem::permissions(path, std::filesystem::perms::owner_all);
  }
  EXPECT_EQ(RunProgram(core.string(), "eval map m.yaml", "", true).out, "tunables=glibc.malloc.hugetlb=1\n");
  // Tunables already set are kept.
  EXPECT_EQ(RunProgram(core.string(), "vectorize m.pgm", "GLIBC_TUNABLES=glibc.malloc.check=0", true).out,
            "tunables=glibc.malloc.check=0:glibc.malloc.hugetlb=1\n");
  // The sweep helper starts SLAM programs, which must not inherit a tuning of slamsweep's.
  EXPECT_EQ(RunProgram(core.string(), "data info x.log", "", true).out, "tunables=\n");
}

TEST(BinaryTest, AMissingHelperIsNamedWithWhereItWasLookedFor) {
  const ProcessResult result = RunBinary("eval map map.yaml", "SLAMSWEEP_LIBEXEC_DIR=/nonexistent/libexec", true);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.out, ::testing::HasSubstr("slamsweep-maps"));
  EXPECT_THAT(result.out, ::testing::HasSubstr("/nonexistent/libexec"));
}

}  // namespace
}  // namespace slamsweep
