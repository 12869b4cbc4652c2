#include "orchestrator/sweep/shared_run_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

namespace fs = std::filesystem;
using slamsweep::testing::TempDir;

void WriteText(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
}

std::string ReadText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(SharedRunFilesTest, RunsWithTheSameReferenceShareOneFile) {
  TempDir dir;
  const std::string intel = "# timestamp tx ty tz qx qy qz qw\n1 0 0 0 0 0 0 1\n";
  const std::string fr079 = "# timestamp tx ty tz qx qy qz qw\n1 5 0 0 0 0 0 1\n";
  WriteText(dir / "a/reference.tum", intel);
  WriteText(dir / "b/reference.tum", intel);
  WriteText(dir / "c/reference.tum", fr079);
  WriteText(dir / "d/reference.tum", intel);
  SharedRunFiles shared;
  for (const char* run : {"a", "b", "c", "d"}) shared.Share(dir / run / "reference.tum");
  EXPECT_TRUE(fs::equivalent(dir / "a/reference.tum", dir / "b/reference.tum"));
  EXPECT_TRUE(fs::equivalent(dir / "a/reference.tum", dir / "d/reference.tum"));
  EXPECT_EQ(fs::hard_link_count(dir / "a/reference.tum"), 3u);
  EXPECT_EQ(fs::hard_link_count(dir / "c/reference.tum"), 1u);
  EXPECT_EQ(ReadText(dir / "d/reference.tum"), intel);
  EXPECT_EQ(ReadText(dir / "c/reference.tum"), fr079);
  EXPECT_FALSE(fs::exists(dir / "d/reference.tum.shared"));
}

TEST(SharedRunFilesTest, AFirstFileThatIsGoneOrChangedIsNotLinkedTo) {
  TempDir dir;
  const std::string text = "1 0 0 0 0 0 0 1\n";
  WriteText(dir / "a/reference.tum", text);
  SharedRunFiles shared;
  shared.Share(dir / "a/reference.tum");
  fs::remove_all(dir / "a");  // the run is rerun: its folder is removed first
  WriteText(dir / "b/reference.tum", text);
  shared.Share(dir / "b/reference.tum");
  EXPECT_EQ(ReadText(dir / "b/reference.tum"), text);
  EXPECT_EQ(fs::hard_link_count(dir / "b/reference.tum"), 1u);
  // b is the first of its content now.
  WriteText(dir / "c/reference.tum", text);
  shared.Share(dir / "c/reference.tum");
  EXPECT_TRUE(fs::equivalent(dir / "b/reference.tum", dir / "c/reference.tum"));
  // A missing file is left alone.
  EXPECT_NO_THROW(shared.Share(dir / "none/reference.tum"));
  EXPECT_FALSE(fs::exists(dir / "none/reference.tum"));
}

}  // namespace
}  // namespace slamsweep::orchestrator
