#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "evaluator/core/input_error.h"
#include "report/model/load_runs.h"
#include "report/model/mean_std.h"
#include "report/model/sweep_model.h"
#include "tests/report/fixture_sweep.h"
#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

using slamsweep::testing::TempDir;
using slamsweep::testing::WriteFile;

TEST(MeanStdTest, SampleStandardDeviationByHand) {
  // 2, 4, 4, 4, 5, 5, 7, 9: mean 5, squared deviations sum 32, sample variance 32 / 7.
  const std::vector<double> values = {2, 4, 4, 4, 5, 5, 7, 9};
  const MeanStd result = ComputeMeanStd(values);
  EXPECT_EQ(result.n, 8u);
  EXPECT_DOUBLE_EQ(result.mean, 5.0);
  ASSERT_TRUE(result.std.has_value());
  EXPECT_NEAR(*result.std, std::sqrt(32.0 / 7.0), 1e-12);
  EXPECT_EQ(result.min, 2.0);
  EXPECT_EQ(result.max, 9.0);
}

TEST(MeanStdTest, OneValueHasNoStd) {
  const std::vector<double> values = {0.5};
  const MeanStd result = ComputeMeanStd(values);
  EXPECT_EQ(result.n, 1u);
  EXPECT_EQ(result.mean, 0.5);
  EXPECT_FALSE(result.std.has_value());
}

TEST(MeanStdTest, NoValues) { EXPECT_EQ(ComputeMeanStd(std::vector<double>{}).n, 0u); }

TEST(LoadRunTest, MissingResultIsUnfinished) {
  TempDir dir;
  std::filesystem::create_directories(dir / "r1");
  WriteFile(dir / "r1/run.json", R"({"algorithm": {"name": "a"}, "sequence": {"name": "s"}, "iteration": 2})");
  const RunRecord run = LoadRun(dir / "r1");
  EXPECT_EQ(run.status, RunStatus::kUnfinished);
  EXPECT_EQ(run.algorithm, "a");
  EXPECT_EQ(run.iteration, 2);
}

TEST(LoadRunTest, CorruptResultIsUnreadableAndNamesTheFile) {
  TempDir dir;
  std::filesystem::create_directories(dir / "r1");
  WriteFile(dir / "r1/run.json", R"({"algorithm": {"name": "a"}, "sequence": {"name": "s"}})");
  WriteFile(dir / "r1/result.json", R"({"status": "ok", "wall_s": "slow"})");
  const RunRecord run = LoadRun(dir / "r1");
  EXPECT_EQ(run.status, RunStatus::kUnreadable);
  EXPECT_NE(run.reason.find("result.json"), std::string::npos) << run.reason;
  EXPECT_NE(run.reason.find("wall_s"), std::string::npos) << run.reason;
  EXPECT_NE(run.reason.find("expected a number"), std::string::npos) << run.reason;
}

TEST(LoadRunTest, NotJsonAndBadStatus) {
  TempDir dir;
  std::filesystem::create_directories(dir / "r1");
  WriteFile(dir / "r1/run.json", "{ not json");
  EXPECT_EQ(LoadRun(dir / "r1").status, RunStatus::kUnreadable);
  WriteFile(dir / "r1/run.json", R"({"algorithm": {"name": "a"}})");
  WriteFile(dir / "r1/result.json", R"({"status": "great"})");
  const RunRecord run = LoadRun(dir / "r1");
  EXPECT_EQ(run.status, RunStatus::kUnreadable);
  EXPECT_NE(run.reason.find("status"), std::string::npos) << run.reason;
  EXPECT_EQ(run.sequence, "?");
}

TEST(LoadRunsTest, MissingFoldersAreInputErrors) {
  TempDir dir;
  EXPECT_THROW(LoadRuns(dir / "nowhere"), evaluator::InputError);
  try {
    LoadRuns(dir.path());
    FAIL() << "expected InputError";
  } catch (const evaluator::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("runs"), std::string::npos) << error.what();
  }
}

class SweepModelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    testing::WriteFixtureSweep(dir_.path(), testing::StandardFixtureRuns());
    model_ = BuildSweepModel(LoadRuns(dir_.path()));
  }
  const SequenceModel& Sequence(const std::string& name) {
    for (const SequenceModel& sequence : model_.sequences) {
      if (sequence.name == name) return sequence;
    }
    throw std::runtime_error("no sequence " + name);
  }
  static const AlgorithmRow& Row(const SequenceModel& sequence, const std::string& algorithm) {
    for (const AlgorithmRow& row : sequence.rows) {
      if (row.algorithm == algorithm) return row;
    }
    throw std::runtime_error("no row " + algorithm);
  }
  static std::size_t Column(const std::vector<MetricColumn>& columns, const std::string& metric) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (columns[c].metric == metric) return c;
    }
    throw std::runtime_error("no column " + metric);
  }
  TempDir dir_;
  SweepModel model_;
};

TEST_F(SweepModelTest, CountsFailedRuns) {
  EXPECT_EQ(model_.counts.total, 10u);
  EXPECT_EQ(model_.counts.failed, 1u);
  const AlgorithmRow& hostile = Row(Sequence("intel"), "<script>alert(1)</script>");
  EXPECT_EQ(hostile.counts.total, 3u);
  EXPECT_EQ(hostile.counts.ok, 2u);
  EXPECT_EQ(hostile.counts.failed, 1u);
}

TEST_F(SweepModelTest, TableOneMeanStdAndBest) {
  const SequenceModel& intel = Sequence("intel");
  ASSERT_TRUE(intel.has_reference);
  const std::size_t ate = Column(intel.trajectory_columns, "ape_trans");
  EXPECT_EQ(intel.trajectory_columns[ate].spec, "alignment se2");
  EXPECT_EQ(intel.trajectory_columns[ate].unit, "m");
  const MetricCell& gmapping = Row(intel, "gmapping").trajectory_cells[ate];
  EXPECT_NEAR(gmapping.summary.mean, 0.11, 1e-12);  // 0.10 0.11 0.12
  EXPECT_NEAR(*gmapping.summary.std, 0.01, 1e-12);
  EXPECT_TRUE(gmapping.best);
  const MetricCell& hostile = Row(intel, "<script>alert(1)</script>").trajectory_cells[ate];
  EXPECT_EQ(hostile.summary.n, 2u);  // the failed run has no value
  EXPECT_NEAR(hostile.summary.mean, 0.25, 1e-12);
  EXPECT_NEAR(*hostile.summary.std, std::sqrt(0.005), 1e-12);  // (0.05^2 * 2) / 1
  EXPECT_FALSE(hostile.best);
  const MetricCell& single = Row(intel, "single").trajectory_cells[ate];
  EXPECT_EQ(single.summary.n, 1u);
  EXPECT_FALSE(single.summary.std.has_value());
  // The hostile algorithm has the lowest occupied ratio (0.04 < 0.05 < 0.06), but one of its three
  // runs failed, and six runs are too few for the validity study to support the metric: no best.
  const std::size_t occupied = Column(intel.map_columns, "occupied_to_free_unknown");
  EXPECT_FALSE(Row(intel, "<script>alert(1)</script>").map_cells[occupied].best);
  EXPECT_FALSE(Row(intel, "gmapping").map_cells[occupied].best);
  EXPECT_THAT(intel.map_columns[occupied].best_withheld, ::testing::HasSubstr("too few runs"));
}

TEST_F(SweepModelTest, MedianRunByAteOrByCornersWithoutReference) {
  const AlgorithmRow& gmapping = Row(Sequence("intel"), "gmapping");
  ASSERT_TRUE(gmapping.median_run);
  EXPECT_EQ(model_.runs[*gmapping.median_run].iteration, 1);  // 0.11 is the median of 0.10 0.11 0.12
  EXPECT_EQ(gmapping.median_by, "ATE translation RMSE");
  // Two successful runs (0.2, 0.3): the lower middle.
  const AlgorithmRow& hostile = Row(Sequence("intel"), "<script>alert(1)</script>");
  EXPECT_EQ(model_.runs[*hostile.median_run].iteration, 0);

  const SequenceModel& mit = Sequence("mit-no-ref");
  EXPECT_FALSE(mit.has_reference);
  EXPECT_TRUE(mit.trajectory_columns.empty());
  const AlgorithmRow& no_ref = Row(mit, "gmapping");
  EXPECT_EQ(no_ref.median_by, "corner count");
  EXPECT_EQ(model_.runs[*no_ref.median_run].iteration, 1);  // corners 30 29 28
}

TEST(MetricSpecLabelTest, DifferentAlignmentsGetDifferentColumns) {
  RunRecord a;
  a.status = RunStatus::kOk;
  a.algorithm = "x";
  a.sequence = "s";
  a.metrics = {{"ape_trans", "rmse", 1.0, "m"}};
  a.run_spec = {{"evaluation", {{"align", "se2"}}}};
  RunRecord b = a;
  b.run_id = "b";
  b.run_spec = {{"evaluation", {{"align", "sim2"}}}};
  const SweepModel model = BuildSweepModel({a, b});
  ASSERT_EQ(model.sequences.size(), 1u);
  ASSERT_EQ(model.sequences[0].trajectory_columns.size(), 2u);
  EXPECT_EQ(model.sequences[0].trajectory_columns[0].spec, "alignment se2");
  EXPECT_EQ(model.sequences[0].trajectory_columns[1].spec, "alignment sim2");
  EXPECT_EQ(model.sequences[0].rows[0].trajectory_cells[0].summary.n, 1u);
}

}  // namespace
}  // namespace slamsweep::report
