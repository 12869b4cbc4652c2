#include "orchestrator/store/merge.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <set>

#include "evaluator/core/input_error.h"
#include "orchestrator/store/results_store.h"
#include "tests/orchestrator/store/store_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using ::testing::HasSubstr;
using testing::MakeOkResult;
using testing::MakeSpec;

std::string ReadText(const fs::path& file) {
  std::ifstream in(file);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// An output directory as a sweep leaves it: results.sqlite plus runs/<id>/ with result.json and a log.
void AddRun(const fs::path& out, ResultsStore& store, std::int64_t sweep, const json& result) {
  const std::string id = result.at("run_id");
  fs::create_directories(out / "runs" / id / "raw");
  slamsweep::testing::WriteFile(out / "runs" / id / "result.json", result.dump());
  slamsweep::testing::WriteFile(out / "runs" / id / "raw" / "log.txt", "log of " + id);
  store.RecordRun(sweep, MakeSpec(id), result, "runs/" + id);
}

struct Shards {
  slamsweep::testing::TempDir dir;
  fs::path a = dir / "a";
  fs::path b = dir / "b";
};

// Shard a: r1, r2 (finished 05:00:03). Shard b: r1 identical, r2 re-run with another result (finished
// 06:00:00, so newer), r3.
void MakeShards(Shards& shards) {
  for (const fs::path& p : {shards.a, shards.b}) fs::create_directories(p);
  ResultsStore a = ResultsStore::Open(shards.a / "results.sqlite");
  SweepInfo info;
  info.name = "shard-a";
  info.started_at = "2026-11-22T04:00:00Z";
  const std::int64_t sa = a.BeginSweep(info);
  AddRun(shards.a, a, sa, MakeOkResult("r1"));
  AddRun(shards.a, a, sa, MakeOkResult("r2", 3.0, 0.12, "2026-11-22T05:00:03Z"));
  a.FinishSweep(sa, SweepStatus::kOk, 2);
  ResultsStore b = ResultsStore::Open(shards.b / "results.sqlite");
  info.name = "shard-b";
  const std::int64_t sb = b.BeginSweep(info);
  AddRun(shards.b, b, sb, MakeOkResult("r1"));
  AddRun(shards.b, b, sb, MakeOkResult("r2", 5.0, 0.99, "2026-11-22T06:00:00Z"));
  AddRun(shards.b, b, sb, MakeOkResult("r3"));
  b.FinishSweep(sb, SweepStatus::kOk, 3);
}

TEST(MergeTest, CombinesShardsKeepsDuplicatesOnceAndTheNewerConflict) {
  Shards shards;
  MakeShards(shards);
  const fs::path out = shards.dir / "out";
  const MergeReport report = MergeResultDirs({shards.a, shards.b}, out);
  EXPECT_EQ(report.runs_added, 3u);
  EXPECT_EQ(report.duplicates, 1u);
  ASSERT_EQ(report.conflicts.size(), 1u);
  EXPECT_THAT(report.conflicts[0], HasSubstr("run r2"));
  EXPECT_THAT(report.conflicts[0], HasSubstr("kept the newer one from " + shards.b.string()));
  EXPECT_TRUE(report.warnings.empty());

  ResultsStore merged = ResultsStore::OpenExisting(out / "results.sqlite");
  const auto runs = merged.Runs();
  ASSERT_EQ(runs.size(), 3u);
  const auto r2 = merged.FindRun("r2");
  EXPECT_EQ(r2->wall_s, 5.0);
  EXPECT_EQ(r2->metrics.at(0).value, 0.99);
  // The folder follows the row: out/runs/r2 is shard b's.
  EXPECT_EQ(json::parse(ReadText(out / "runs" / "r2" / "result.json")).at("wall_s"), 5.0);
  EXPECT_EQ(ReadText(out / "runs" / "r3" / "raw" / "log.txt"), "log of r3");
  EXPECT_EQ(ReadText(out / "runs" / "r1" / "raw" / "log.txt"), "log of r1");
  EXPECT_FALSE(fs::exists(out / "runs" / ".r2.merging"));
  // Runs point at their own shard's sweep, re-numbered in the merged store.
  const auto sweeps = merged.Sweeps();
  ASSERT_EQ(sweeps.size(), 2u);
  EXPECT_EQ(sweeps[1].info.name, "shard-b");
  EXPECT_EQ(merged.FindRun("r3")->sweep_id, sweeps[1].id);
  EXPECT_EQ(merged.FindRun("r1")->sweep_id, sweeps[0].id);

  const json summary = json::parse(ReadText(out / "summary.json"));
  EXPECT_EQ(summary.at("counts").at("total"), 3);
  EXPECT_THAT(ReadText(out / "junit.xml"), HasSubstr("i0 (r3)\""));
}

// Two shards of one comparison group whose programs were built apart (other digests): the merge keeps
// them as two groups, each marked, and says so; it never averages them together.
TEST(MergeTest, ResultsOfDifferentBuildsAreKeptApartAsMarkedGroups) {
  Shards shards;
  const auto shard = [](const fs::path& out, const std::string& id, const std::string& digest, double ape,
                        const std::string& program = "/usr/bin/icp-slam") {
    fs::create_directories(out);
    ResultsStore store = ResultsStore::Open(out / "results.sqlite");
    const std::int64_t sweep = store.BeginSweep(SweepInfo{});
    json spec = MakeSpec(id, "icp-slam", "intel", id == "r1" ? 0 : 1);
    spec["build"] = {{"slamsweep_revision", "0.1+abc"}, {"program_files", {{program, digest}}}};
    const json result = MakeOkResult(id, 3.0, ape);
    fs::create_directories(out / "runs" / id);
    slamsweep::testing::WriteFile(out / "runs" / id / "result.json", result.dump());
    store.RecordRun(sweep, spec, result, "runs/" + id);
  };
  shard(shards.a, "r1", std::string(64, 'a'), 0.10);
  shard(shards.b, "r2", std::string(64, 'b'), 0.30);
  const fs::path out = shards.dir / "merged";
  const MergeReport report = MergeResultDirs({shards.a, shards.b}, out);
  ASSERT_EQ(report.warnings.size(), 1u) << ::testing::PrintToString(report.warnings);
  EXPECT_THAT(report.warnings[0], HasSubstr("kept apart as separate groups"));
  EXPECT_THAT(report.warnings[0], HasSubstr("icp-slam [ICP.maxIterations=80] on intel (clean)"));
  const json summary = json::parse(ReadText(out / "summary.json"));
  ASSERT_EQ(summary.at("groups").size(), 2u) << summary.at("groups").dump(1);
  std::set<double> means;
  std::set<std::string> builds;
  for (const json& group : summary.at("groups")) {
    EXPECT_TRUE(group.at("build_split").get<bool>());
    EXPECT_EQ(group.at("n_runs"), 1);
    builds.insert(group.at("build").get<std::string>());
    means.insert(group.at("metrics").at("ape_trans").at("rmse").at("mean").get<double>());
    EXPECT_THAT(group.at("build_description").get<std::string>(), HasSubstr("slamsweep 0.1+abc; icp-slam "));
  }
  EXPECT_EQ(builds.size(), 2u);
  EXPECT_EQ(means, (std::set<double>{0.10, 0.30}));  // never their average 0.2
  EXPECT_THAT(ReadText(out / "summary.csv"), HasSubstr(*builds.begin()));

  // The same binaries unpacked at another path are the same build: one group, unmarked.
  Shards same;
  shard(same.a, "r1", std::string(64, 'a'), 0.10);
  shard(same.b, "r2", std::string(64, 'a'), 0.30, "/var/tmp/elsewhere/icp-slam");
  const MergeReport pooled = MergeResultDirs({same.a, same.b}, same.dir / "merged");
  EXPECT_TRUE(pooled.warnings.empty()) << ::testing::PrintToString(pooled.warnings);
  EXPECT_EQ(json::parse(ReadText(same.dir / "merged" / "summary.json")).at("groups").size(), 1u);
}

TEST(MergeTest, OlderConflictingResultDoesNotReplaceANewerOne) {
  Shards shards;
  MakeShards(shards);
  const fs::path out = shards.dir / "out";
  const MergeReport report = MergeResultDirs({shards.b, shards.a}, out);
  EXPECT_EQ(report.runs_added, 3u);
  EXPECT_EQ(report.duplicates, 1u);
  ASSERT_EQ(report.conflicts.size(), 1u);
  EXPECT_THAT(report.conflicts[0], HasSubstr("kept the newer one from " + shards.b.string()));
  EXPECT_EQ(ResultsStore::OpenExisting(out / "results.sqlite").FindRun("r2")->wall_s, 5.0);
  EXPECT_EQ(json::parse(ReadText(out / "runs" / "r2" / "result.json")).at("wall_s"), 5.0);
}

TEST(MergeTest, MergingAgainChangesNothing) {
  Shards shards;
  MakeShards(shards);
  const fs::path out = shards.dir / "out";
  MergeResultDirs({shards.a, shards.b}, out);
  const MergeReport again = MergeResultDirs({shards.a, shards.b}, out);
  EXPECT_EQ(again.runs_added, 0u);
  // r1 twice, r2 and r3 from b; a's older r2 is still a conflict, and still loses.
  EXPECT_EQ(again.duplicates, 4u);
  EXPECT_EQ(again.conflicts.size(), 1u);
  ResultsStore merged = ResultsStore::OpenExisting(out / "results.sqlite");
  EXPECT_EQ(merged.Runs().size(), 3u);
  EXPECT_EQ(merged.Sweeps().size(), 2u);
  EXPECT_EQ(merged.FindRun("r2")->wall_s, 5.0);
}

TEST(MergeTest, MissingRunFolderIsAWarning) {
  Shards shards;
  MakeShards(shards);
  fs::remove_all(shards.b / "runs" / "r3");
  const MergeReport report = MergeResultDirs({shards.b}, shards.dir / "out");
  EXPECT_EQ(report.runs_added, 3u);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_THAT(report.warnings[0], HasSubstr("run r3: folder"));
  EXPECT_THAT(report.warnings[0], HasSubstr("missing"));
}

TEST(MergeTest, InputWithoutStoreIsAnErrorAndOutIsUntouched) {
  Shards shards;
  MakeShards(shards);
  const fs::path empty = shards.dir / "empty";
  fs::create_directories(empty);
  const fs::path out = shards.dir / "out";
  try {
    MergeResultDirs({shards.a, empty}, out);
    FAIL() << "expected InputError";
  } catch (const evaluator::InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr((empty / "results.sqlite").string()));
    EXPECT_THAT(e.what(), HasSubstr("slamsweep output directory"));
  }
  EXPECT_FALSE(fs::exists(out));
}

TEST(MergeTest, OutputCannotBeAnInput) {
  Shards shards;
  MakeShards(shards);
  EXPECT_THROW(MergeResultDirs({shards.b, shards.a}, shards.a), evaluator::InputError);
}

TEST(MergeTest, CorruptInputStoreNamesIt) {
  Shards shards;
  MakeShards(shards);
  fs::remove(shards.b / "results.sqlite-wal");
  fs::remove(shards.b / "results.sqlite-shm");
  slamsweep::testing::WriteFile(shards.b / "results.sqlite", std::string(4096, 'z'));
  try {
    MergeResultDirs({shards.a, shards.b}, shards.dir / "out");
    FAIL() << "expected InputError";
  } catch (const evaluator::InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr((shards.b / "results.sqlite").string()));
  }
}

}  // namespace
}  // namespace slamsweep::orchestrator
