#include "orchestrator/store/record_run_folder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "evaluator/core/input_error.h"
#include "tests/orchestrator/store/store_test_util.h"
#include "tests/support/shared_data.h"
#include "tests/support/input_error_text.h"

namespace slamsweep::orchestrator {
namespace {

using ::testing::HasSubstr;
using testing::MakeOkResult;
using testing::MakeSpec;

using slamsweep::testing::ErrorOf;

TEST(RunFolderTest, RecordsRunJsonAndResultJson) {
  slamsweep::testing::TempDir dir;
  std::filesystem::create_directories(dir / "runs" / "r1");
  slamsweep::testing::WriteFile(dir / "runs" / "r1" / "run.json", MakeSpec("r1").dump(2));
  slamsweep::testing::WriteFile(dir / "runs" / "r1" / "result.json", MakeOkResult("r1").dump(2));
  ResultsStore store = ResultsStore::Open(dir / "results.sqlite");
  RecordRunFolder(store, 1, dir.path(), "runs/r1");
  const auto run = store.FindRun("r1");
  ASSERT_TRUE(run.has_value());
  EXPECT_EQ(run->run_dir, "runs/r1");
  EXPECT_EQ(run->run_spec, MakeSpec("r1"));
  EXPECT_EQ(run->result.at("status"), "ok");
  EXPECT_EQ(run->result.at("wall_s"), 3.0);
  EXPECT_EQ(run->result.at("outputs"), MakeOkResult("r1").at("outputs"));
  EXPECT_EQ(run->metrics.size(), 3u);
}

TEST(RunFolderTest, MissingOrBrokenFilesNameTheFile) {
  slamsweep::testing::TempDir dir;
  std::filesystem::create_directories(dir / "runs" / "r1");
  ResultsStore store = ResultsStore::Open(dir / "results.sqlite");
  const auto folder = dir / "runs" / "r1";
  EXPECT_THAT(ErrorOf([&] { RecordRunFolder(store, 1, dir.path(), "runs/r1"); }),
              HasSubstr((folder / "run.json").string() + ": cannot read"));
  slamsweep::testing::WriteFile(folder / "run.json", MakeSpec("r1").dump());
  slamsweep::testing::WriteFile(folder / "result.json", "{\"status\": \"ok\",");
  EXPECT_THAT(ErrorOf([&] { RecordRunFolder(store, 1, dir.path(), "runs/r1"); }),
              HasSubstr((folder / "result.json").string() + ": not valid JSON"));
  slamsweep::testing::WriteFile(folder / "result.json", "{\"status\": \"maybe\"}");
  const std::string error = ErrorOf([&] { RecordRunFolder(store, 1, dir.path(), "runs/r1"); });
  EXPECT_THAT(error, HasSubstr(folder.string()));
  EXPECT_THAT(error, HasSubstr("status: expected \"ok\" or \"failed\""));
  EXPECT_FALSE(store.StatusOf("r1").has_value());
}

TEST(ResultsStoreOpenTest, MissingFolderSaysWhatToCheck) {
  slamsweep::testing::TempDir dir;
  const auto file = dir / "no" / "such" / "results.sqlite";
  const std::string error = ErrorOf([&] { ResultsStore::Open(file); });
  EXPECT_THAT(error, HasSubstr(file.string()));
  EXPECT_THAT(error, HasSubstr("check that the folder exists"));
}

}  // namespace
}  // namespace slamsweep::orchestrator
