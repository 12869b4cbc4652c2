#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "cli/command.h"
#include "evaluator/core/input_error.h"
#include "tests/report/fake_artwork.h"
#include "tests/report/fixture_sweep.h"
#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

namespace fs = std::filesystem;
using slamsweep::testing::TempDir;

// Parses like RunCommandLine does for this one command.
void RunReportCommand(std::vector<std::string> args, std::ostream& out) {
  std::ostringstream err;
  const cli::Streams streams{out, err};
  CLI::App app{"slamsweep", "slamsweep"};
  app.require_subcommand(1);
  cli::RegisterReportCommand(app, streams);
  std::vector<const char*> argv = {"slamsweep", "report"};
  for (const std::string& arg : args) argv.push_back(arg.c_str());
  app.parse(static_cast<int>(argv.size()), argv.data());
}

TEST(ReportCommandTest, WritesIntoResultDirByDefault) {
  TempDir dir;
  testing::WriteFixtureSweep(dir.path(), testing::StandardFixtureRuns());
  std::ostringstream out;
  RunReportCommand({dir.path().string(), "--no-images"}, out);
  EXPECT_TRUE(fs::is_regular_file(dir / "report/index.html"));
  EXPECT_NE(out.str().find("10 runs"), std::string::npos) << out.str();
}

TEST(ReportCommandTest, OutputOptionAndBadInput) {
  TempDir dir;
  testing::WriteFixtureSweep(dir / "sweep", testing::StandardFixtureRuns());
  std::ostringstream out;
  RunReportCommand({(dir / "sweep").string(), "-o", (dir / "site").string(), "--no-images", "-j", "1"}, out);
  EXPECT_TRUE(fs::is_regular_file(dir / "site/index.html"));
  EXPECT_THROW(RunReportCommand({(dir / "missing").string(), "--no-images"}, out), evaluator::InputError);
  EXPECT_THROW(RunReportCommand({(dir / "sweep").string(), "--thumbnail-px", "2"}, out), CLI::ValidationError);
}

}  // namespace
}  // namespace slamsweep::report
