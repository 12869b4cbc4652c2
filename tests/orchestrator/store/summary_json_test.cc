#include "orchestrator/store/summary_json.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "orchestrator/store/results_store.h"
#include "orchestrator/store/validity_table.h"
#include "tests/orchestrator/store/store_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

using nlohmann::json;
using testing::MakeFailedResult;
using testing::MakeOkResult;
using testing::MakeSpec;

json ReadJson(const std::filesystem::path& file) {
  std::ifstream in(file);
  return json::parse(std::string(std::istreambuf_iterator<char>(in), {}));
}

TEST(SummaryJsonTest, ListsEveryRunWithFlatMetricsUnitsAndCounts) {
  slamsweep::testing::TempDir dir;
  ResultsStore store = ResultsStore::Open(dir / "results.sqlite");
  store.RecordRun(1, MakeSpec("ok-run", "icp-slam", "intel", 3), MakeOkResult("ok-run", 4.25, 0.3), "runs/ok-run");
  store.RecordRun(1, MakeSpec("bad-run", "rbpf", "intel"), MakeFailedResult("bad-run"), "runs/bad-run");
  const auto file = dir / "summary.json";
  WriteSummaryJson(store.Runs(), ValidityStudyOf(store.Runs()), file);
  const json summary = ReadJson(file);

  EXPECT_TRUE(summary.at("generated_at").get<std::string>().ends_with("Z"));
  EXPECT_EQ(summary.at("counts"), (json{{"total", 2}, {"ok", 1}, {"failed", 1}}));
  const json& runs = summary.at("runs");
  ASSERT_EQ(runs.size(), 2u);
  // Same sequence: ordered by algorithm (icp-slam < rbpf).
  const json& ok = runs[0];
  EXPECT_EQ(ok.at("run_id"), "ok-run");
  EXPECT_EQ(ok.at("algorithm"), "icp-slam");
  EXPECT_EQ(ok.at("adapter"), "mrpt-icp-slam");
  EXPECT_EQ(ok.at("parameters"), (json{{"ICP.maxIterations", 80}}));
  EXPECT_EQ(ok.at("sequence"), "intel");
  EXPECT_EQ(ok.at("noise"), "clean");
  EXPECT_EQ(ok.at("iteration"), 3);
  EXPECT_EQ(ok.at("seed"), 123456789);
  EXPECT_EQ(ok.at("status"), "ok");
  EXPECT_TRUE(ok.at("failure_kind").is_null());
  EXPECT_EQ(ok.at("exit_code"), 0);
  EXPECT_EQ(ok.at("wall_s"), 4.25);
  EXPECT_EQ(ok.at("cpu_s"), 2.5);
  EXPECT_EQ(ok.at("peak_rss_kb"), 81234);
  EXPECT_EQ(ok.at("run_dir"), "runs/ok-run");
  EXPECT_EQ(ok.at("ground_truth"), "relations");
  EXPECT_EQ(ok.at("metrics"), (json{{"ape_trans", {{"rmse", 0.3}, {"mean", 0.1}}}, {"corners", {{"value", 17}}}}));
  EXPECT_EQ(ok.at("units"), (json{{"ape_trans", "m"}, {"corners", "count"}}));
  EXPECT_EQ(ok.at("outputs").at("trajectory"), "trajectory.tum");

  const json& bad = runs[1];
  EXPECT_EQ(bad.at("status"), "failed");
  EXPECT_EQ(bad.at("failure_kind"), "signal");
  EXPECT_EQ(bad.at("reason"), "killed by SIGSEGV");
  EXPECT_EQ(bad.at("signal"), 11);
  EXPECT_TRUE(bad.at("exit_code").is_null());
  EXPECT_EQ(bad.at("metrics"), json::object());

  // Written compact: the file is its own content without any whitespace between tokens.
  std::ifstream in(file);
  const std::string text(std::istreambuf_iterator<char>(in), {});
  EXPECT_EQ(text, summary.dump() + "\n");

  // Atomic write: nothing but the file itself is left beside it.
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    files += entry.path().filename().string().starts_with("summary.json") ? 1 : 0;
  }
  EXPECT_EQ(files, 1u);
}

TEST(SummaryJsonTest, AMeasuredReferenceSaysWhereItWasRecorded) {
  slamsweep::testing::TempDir dir;
  ResultsStore store = ResultsStore::Open(dir / "results.sqlite");
  json spec = MakeSpec("bag-run", "icp-slam", "run1");
  spec["sequence"] = {
      {"name", "run1"}, {"format", "rosbag2"}, {"ground_truth", "measured"}, {"reference_topic", "/ground_truth"}};
  store.RecordRun(1, spec, MakeOkResult("bag-run"), "runs/bag-run");
  const auto file = dir / "summary.json";
  WriteSummaryJson(store.Runs(), ValidityStudyOf(store.Runs()), file);
  const json summary = ReadJson(file);
  const json& run = summary.at("runs").at(0);
  EXPECT_EQ(run.at("ground_truth"), "measured");
  EXPECT_EQ(run.at("reference"),
            "measured: a reference recorded with the data (topic /ground_truth); ATE and RPE are agreement with it, "
            "as good as the system that measured it");
}

TEST(SummaryJsonTest, EmptyStoreAndGarbledTextStillGiveValidJson) {
  slamsweep::testing::TempDir dir;
  WriteSummaryJson({}, {}, dir / "summary.json");
  EXPECT_EQ(ReadJson(dir / "summary.json").at("counts").at("total"), 0);

  RunRecord run;
  run.run_id = "r";
  run.status = RunStatus::kFailed;
  run.result = {{"reason", std::string("bad byte \xff here")}};
  WriteSummaryJson({run}, ValidityStudyOf({run}), dir / "summary.json");
  const json back = ReadJson(dir / "summary.json");
  EXPECT_EQ(back.at("runs")[0].at("reason"), "bad byte \xEF\xBF\xBD here");
  // Missing spec fields come out as nulls, not as a crash.
  EXPECT_TRUE(back.at("runs")[0].at("ground_truth").is_null());
  EXPECT_EQ(back.at("counts").at("failed"), 1);
}

TEST(SummaryJsonTest, UnwritableFolderNamesTheFile) {
  slamsweep::testing::TempDir dir;
  const auto file = dir / "missing-folder" / "summary.json";
  try {
    WriteSummaryJson({}, {}, file);
    FAIL() << "expected InputError";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("missing-folder/summary.json"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace slamsweep::orchestrator
