#include "orchestrator/store/group_summary.h"

#include <gtest/gtest.h>

#include <functional>
#include <map>

#include "orchestrator/store/csv_tables.h"
#include "orchestrator/store/results_store.h"
#include "tests/orchestrator/store/store_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

using nlohmann::json;
using testing::MakeOkResult;
using testing::MakeSpec;

/// An ok result whose segment RPE was computed at `lengths_m`, with a mean drift of `drift_pct` at each.
json WithSegments(json result, const std::vector<double>& lengths_m, double drift_pct) {
  json lengths = json::array();
  for (const double length : lengths_m) {
    const std::string name = "segment_drift_" + std::to_string(static_cast<int>(length)) + "m";
    result["metrics"].push_back({{"metric", name}, {"statistic", "mean"}, {"value", drift_pct}, {"unit", "%"}});
    lengths.push_back({{"length_m", length}, {"n", 3}});
  }
  result["metric_details"]["segment_rpe"] = {{"specification", {{"lengths_m", lengths_m}}}, {"lengths", lengths}};
  return result;
}

/// Each group's mean ATE RMSE, by the name `key` gives its summary.json object; every group holds one run.
std::map<std::string, double> AteByGroup(const std::vector<GroupSummary>& groups,
                                         const std::function<std::string(const json&)>& key) {
  std::map<std::string, double> ate;
  for (const GroupSummary& group : groups) {
    EXPECT_EQ(group.runs, 1u);
    const json out = ToJson(group);
    ate[key(out)] = out.at("metrics").at("ape_trans").at("rmse").at("mean");
  }
  return ate;
}

TEST(GroupSummaryTest, AGroupRecordsItsSegmentLengthsAndWhetherItsRunsAgree) {
  slamsweep::testing::TempDir dir;
  ResultsStore store = ResultsStore::Open(dir / "results.sqlite");
  store.RecordRun(1, MakeSpec("a0", "icp-slam", "intel", 0), WithSegments(MakeOkResult("a0"), {10, 20}, 2.0),
                  "runs/a0");
  store.RecordRun(1, MakeSpec("a1", "icp-slam", "intel", 1), WithSegments(MakeOkResult("a1"), {10, 20}, 4.0),
                  "runs/a1");
  store.RecordRun(1, MakeSpec("b0", "icp-slam", "fr079", 0), WithSegments(MakeOkResult("b0"), {10, 20}, 1.0),
                  "runs/b0");
  // Scored at other lengths (a --reuse-stale rerun): never pooled into the 10 m aggregate of the others.
  store.RecordRun(1, MakeSpec("b1", "icp-slam", "fr079", 1), WithSegments(MakeOkResult("b1"), {15}, 9.0), "runs/b1");
  const std::vector<GroupSummary> groups = SummarizeGroups(store.Runs());
  ASSERT_EQ(groups.size(), 2u);
  const GroupSummary& fr079 = groups[0];
  const GroupSummary& intel = groups[1];
  EXPECT_EQ(intel.segment_lengths_m, (std::vector<double>{10, 20}));
  EXPECT_TRUE(intel.segment_lengths_consistent);
  EXPECT_EQ(fr079.segment_lengths_m, (std::vector<double>{10, 15, 20}));
  EXPECT_FALSE(fr079.segment_lengths_consistent);
  const json out = ToJson(fr079);
  EXPECT_EQ(out.at("rpe_segments_m"), json::array({10.0, 15.0, 20.0}));
  EXPECT_EQ(out.at("rpe_segments_consistent"), false);
  EXPECT_EQ(out.at("metrics").at("segment_drift_10m").at("mean").at("n"), 1);
  EXPECT_EQ(out.at("metrics").at("segment_drift_15m").at("mean").at("mean"), 9.0);
  EXPECT_EQ(ToJson(intel).at("metrics").at("segment_drift_10m").at("mean").at("mean"), 3.0);
  // summary.csv's headline of the segment RPE is its mean, as for the relations metric.
  EXPECT_TRUE(IsHeadlineStatistic("segment_drift_10m", "mean"));
  EXPECT_FALSE(IsHeadlineStatistic("segment_drift_10m", "median"));
  EXPECT_NE(GroupsCsv(groups).find("segment_drift_10m.mean.mean"), std::string::npos);
}

TEST(GroupSummaryTest, RunsOfAnotherNoiseSettingOrParameterValueAreNeverPooled) {
  slamsweep::testing::TempDir dir;
  ResultsStore store = ResultsStore::Open(dir / "results.sqlite");
  json noisy = MakeSpec("n0", "icp-slam", "intel", 0);
  noisy["noise"]["name"] = "noisy";
  json other_parameters = MakeSpec("p0", "icp-slam", "intel", 0);
  other_parameters["algorithm"]["parameters"]["ICP.maxIterations"] = 40;
  store.RecordRun(1, MakeSpec("c0", "icp-slam", "intel", 0), MakeOkResult("c0", 3.0, 0.1), "runs/c0");
  store.RecordRun(1, noisy, MakeOkResult("n0", 3.0, 0.5), "runs/n0");
  store.RecordRun(1, other_parameters, MakeOkResult("p0", 3.0, 0.9), "runs/p0");
  const std::vector<GroupSummary> groups = SummarizeGroups(store.Runs());
  ASSERT_EQ(groups.size(), 3u);
  const std::map<std::string, double> ate = AteByGroup(groups, [](const json& group) {
    return group.at("noise").get<std::string>() + " " + group.at("parameters").get<std::string>();
  });
  EXPECT_EQ(ate.at("clean ICP.maxIterations=80"), 0.1);
  EXPECT_EQ(ate.at("noisy ICP.maxIterations=80"), 0.5);
  EXPECT_EQ(ate.at("clean ICP.maxIterations=40"), 0.9);
}

// One algorithm on one log, fed the robot's recorded odometry in one sweep and the reference in
// another: two groups, each named by its mode, in summary.json's and summary.csv's rows.
TEST(GroupSummaryTest, RunsOnRecordedAndOnReferenceOdometryAreNeverPooled) {
  slamsweep::testing::TempDir dir;
  ResultsStore store = ResultsStore::Open(dir / "results.sqlite");
  json recorded = MakeSpec("r0", "icp-slam", "intel", 0);
  recorded["group"] = {{"sequence", "intel"},
                       {"algorithm", "icp-slam"},
                       {"parameters", "ICP.maxIterations=80"},
                       {"noise", "clean"},
                       {"odometry", "recorded"}};
  json reference = MakeSpec("f0", "icp-slam", "intel", 0);
  reference["group"] = recorded["group"];
  reference["group"]["odometry"] = "reference";
  store.RecordRun(1, recorded, MakeOkResult("r0", 3.0, 0.7), "runs/r0");
  store.RecordRun(1, reference, MakeOkResult("f0", 3.0, 0.1), "runs/f0");
  const std::vector<GroupSummary> groups = SummarizeGroups(store.Runs());
  ASSERT_EQ(groups.size(), 2u);
  const std::map<std::string, double> ate =
      AteByGroup(groups, [](const json& group) { return group.at("odometry").get<std::string>(); });
  EXPECT_EQ(ate.at("recorded"), 0.7);
  EXPECT_EQ(ate.at("reference"), 0.1);
  const std::string csv = GroupsCsv(groups);
  EXPECT_NE(csv.find("intel,icp-slam,ICP.maxIterations=80,clean,recorded,1,1,0,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("intel,icp-slam,ICP.maxIterations=80,clean,reference,1,1,0,"), std::string::npos) << csv;
}

}  // namespace
}  // namespace slamsweep::orchestrator
