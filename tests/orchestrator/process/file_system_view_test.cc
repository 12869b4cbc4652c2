// FileSystemView: which folders the prepared view covers and binds back, and, in a real child, that a
// hidden file cannot be read by any path while a visible folder inside it can, and that nothing
// changes for the parent.
#include "orchestrator/process/file_system_view.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

namespace fs = std::filesystem;

TEST(FileSystemViewTest, NestedHiddenFoldersAreCoveredOnceAndVisibleFoldersGetTheirMountPoints) {
  FileSystemView view;
  view.hidden = {"/data/out/runs", "/data/out", "/sets/intel/"};
  view.visible = {"/data/out/runs/r1/input", "/data/out/runs/r1/raw", "/elsewhere/tools"};
  const PreparedFileSystemView prepared = PrepareFileSystemView(view);
  EXPECT_EQ(prepared.hidden, (std::vector<std::string>{"/data/out", "/sets/intel"}));
  EXPECT_EQ(prepared.mkdirs, (std::vector<std::string>{"/data/out/runs", "/data/out/runs/r1", "/data/out/runs/r1/input",
                                                       "/data/out/runs/r1/raw"}));
  // A visible folder under no hidden one needs no binding.
  EXPECT_EQ(prepared.visible, (std::vector<std::string>{"/data/out/runs/r1/input", "/data/out/runs/r1/raw"}));
}

TEST(FileSystemViewTest, RelativePathsAndTheRootAreRefused) {
  FileSystemView relative;
  relative.hidden = {"out"};
  EXPECT_THROW(PrepareFileSystemView(relative), std::invalid_argument);
  FileSystemView root;
  root.hidden = {"/"};
  EXPECT_THROW(PrepareFileSystemView(root), std::invalid_argument);
}

TEST(FileSystemViewTest, AChildCannotReadAHiddenFileByAnyPathButKeepsItsVisibleFolder) {
  if (const std::string& reason = FileSystemViewUnavailableReason(); !reason.empty()) {
    if (testing::RunningInCi()) FAIL() << "no private mount namespace under CI: " << reason;
    GTEST_SKIP() << "no private mount namespace here: " << reason;
  }
  testing::TempDir dir;
  fs::create_directories(dir / "out" / "runs" / "r1" / "raw");
  fs::create_directories(dir / "out" / "runs" / "r0");
  std::ofstream(dir / "out" / "runs" / "r0" / "reference.tum") << "truth\n";
  std::ofstream(dir / "out" / "runs" / "r1" / "run.json") << "{}\n";
  std::ofstream(dir / "out" / "runs" / "r1" / "raw" / "mine.txt") << "mine\n";
  FileSystemView view;
  view.hidden = {dir / "out"};
  view.visible = {dir / "out" / "runs" / "r1" / "raw"};
  const PreparedFileSystemView prepared = PrepareFileSystemView(view);
  const std::string raw = (dir / "out" / "runs" / "r1" / "raw").string();
  const std::string hidden_paths[] = {(dir / "out" / "runs" / "r0" / "reference.tum").string(),
                                      (dir / "out" / "runs" / "r1" / "run.json").string(),
                                      raw + "/../../r0/reference.tum", raw + "/../run.json"};
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const char* step = "";
    if (ApplyFileSystemView(prepared, &step) != 0) ::_exit(10);
    // Exit code bits: 1 = a hidden file was readable, 2 = the visible file was not; writes 4 = failed.
    int code = 0;
    for (const std::string& path : hidden_paths) code |= ::access(path.c_str(), F_OK) == 0 ? 1 : 0;
    if (::access((raw + "/mine.txt").c_str(), R_OK) != 0) code |= 2;
    if (::chdir(raw.c_str()) != 0 || ::access("../../r0/reference.tum", F_OK) == 0) code |= 1;
    std::FILE* out = std::fopen("written.txt", "w");
    if (out == nullptr || std::fputs("by the child\n", out) < 0 || std::fclose(out) != 0) code |= 4;
    ::_exit(code);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  const int code = WEXITSTATUS(status);
  EXPECT_NE(code, 10) << "the view could not be applied although the probe succeeded";
  EXPECT_EQ(code & 1, 0) << "a hidden file was reachable from the child";
  EXPECT_EQ(code & 2, 0) << "the visible folder's file was not readable";
  EXPECT_EQ(code & 4, 0) << "the child could not write into its visible folder";
  // The child's writes land in the real folder, and the parent still sees everything.
  EXPECT_TRUE(fs::exists(dir / "out" / "runs" / "r1" / "raw" / "written.txt"));
  EXPECT_TRUE(fs::exists(dir / "out" / "runs" / "r0" / "reference.tum"));
}

TEST(FileSystemViewTest, AFailedStepIsNamedWithItsErrno) {
  if (const std::string& reason = FileSystemViewUnavailableReason(); !reason.empty()) {
    if (testing::RunningInCi()) FAIL() << "no private mount namespace under CI: " << reason;
    GTEST_SKIP() << "no private mount namespace here: " << reason;
  }
  testing::TempDir dir;
  FileSystemView view;
  view.hidden = {dir / "no-such-folder"};
  const PreparedFileSystemView prepared = PrepareFileSystemView(view);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const char* step = "";
    const int failure = ApplyFileSystemView(prepared, &step);
    ::_exit(failure == ENOENT && std::strcmp(step, "mount tmpfs over a hidden folder") == 0 ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "expected ENOENT from the tmpfs step";
}

}  // namespace
}  // namespace slamsweep::orchestrator
