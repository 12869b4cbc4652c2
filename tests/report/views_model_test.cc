// The models behind the segment-length and parameter pages: boxes, drift per row and length, and
// which rows of a parameter sweep are compared with which.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "report/model/box_summary.h"
#include "report/model/load_runs.h"
#include "report/model/parameter_model.h"
#include "report/model/segment_model.h"
#include "tests/report/fixture_sweep.h"
#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

using slamsweep::testing::TempDir;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(BoxSummaryTest, QuartilesInterpolateBetweenOrderStatistics) {
  // 1..9: h = 8p, so the quartiles fall on 3, 5 and 7; nothing beyond 1.5 IQR.
  const auto box = SummarizeBox({9, 1, 8, 2, 7, 3, 6, 4, 5});
  ASSERT_TRUE(box);
  EXPECT_EQ(box->n, 9u);
  EXPECT_DOUBLE_EQ(box->q1, 3);
  EXPECT_DOUBLE_EQ(box->median, 5);
  EXPECT_DOUBLE_EQ(box->q3, 7);
  EXPECT_DOUBLE_EQ(box->whisker_low, 1);
  EXPECT_DOUBLE_EQ(box->whisker_high, 9);
  EXPECT_DOUBLE_EQ(box->mean, 5);
  EXPECT_EQ(box->outliers, 0u);
}

TEST(BoxSummaryTest, WhiskersStopAtOneAndAHalfInterquartileRanges) {
  // 1..9 and 100: h = 9p -> q1 = 3.25, median 5.5, q3 = 7.75 (numpy's default); the upper fence
  // 7.75 + 1.5 * 4.5 = 14.5 leaves 100 out.
  const auto box = SummarizeBox({1, 2, 3, 4, 5, 6, 7, 8, 9, 100});
  ASSERT_TRUE(box);
  EXPECT_DOUBLE_EQ(box->q1, 3.25);
  EXPECT_DOUBLE_EQ(box->median, 5.5);
  EXPECT_DOUBLE_EQ(box->q3, 7.75);
  EXPECT_DOUBLE_EQ(box->whisker_high, 9);
  EXPECT_EQ(box->outliers, 1u);
  EXPECT_DOUBLE_EQ(box->mean, 14.5);
  EXPECT_FALSE(SummarizeBox({}));
  EXPECT_FALSE(SummarizeBox({std::nan("")}));
  EXPECT_EQ(SummarizeBox({4.0})->whisker_low, 4.0);
}

class ViewsModelTest : public ::testing::Test {
 protected:
  SweepModel Load(const std::vector<testing::FixtureRun>& runs) {
    testing::WriteFixtureSweep(dir_ / "sweep", runs);
    return BuildSweepModel(LoadRuns(dir_ / "sweep"));
  }
  static const SequenceModel& Table(const SweepModel& model, const std::string& name) {
    for (const SequenceModel& sequence : model.sequences) {
      if (sequence.name == name) return sequence;
    }
    throw std::runtime_error("no table " + name);
  }
  static std::size_t RowOf(const SequenceModel& sequence, const std::string& label) {
    for (std::size_t r = 0; r < sequence.rows.size(); ++r) {
      if (sequence.rows[r].algorithm == label) return r;
    }
    throw std::runtime_error("no row " + label);
  }
  TempDir dir_;
};

TEST_F(ViewsModelTest, SegmentTablePoolsEverySegmentAndAveragesEachRunsDrift) {
  const SweepModel model = Load(testing::ViewsFixtureRuns());
  const SequenceModel& intel = Table(model, "intel");
  const std::optional<SegmentTable> table = BuildSegmentTable(model, intel);
  ASSERT_TRUE(table);
  EXPECT_THAT(table->lengths_m, ElementsAre(10, 20, 30));
  EXPECT_THAT(table->lengths_from, HasSubstr("10, 20, 30, 40 and 50 % of the reference path (100.0 m)"));
  EXPECT_TRUE(table->notes.empty());
  EXPECT_EQ(table->rows.size(), intel.rows.size());  // every row of intel has segment RPE
  const auto gmapping = std::find_if(table->rows.begin(), table->rows.end(), [&](const SegmentRow& row) {
    return intel.rows[row.row].algorithm == "gmapping";
  });
  ASSERT_NE(gmapping, table->rows.end());
  // Drift of iteration i at 10 m: 1.5 * 1.1 + 0.05 i -> 1.65, 1.70, 1.75.
  const SegmentCell& at_10 = gmapping->cells[0];
  EXPECT_EQ(at_10.mean_drift_pct.n, 3u);
  EXPECT_NEAR(at_10.mean_drift_pct.mean, 1.70, 1e-12);
  EXPECT_NEAR(*at_10.mean_drift_pct.std, 0.05, 1e-12);
  ASSERT_TRUE(at_10.translation_pct);
  EXPECT_EQ(at_10.translation_pct->n, 60u);  // 20 segments of each of 3 runs
  EXPECT_NEAR(at_10.translation_pct->mean, 1.70, 1e-12);
  ASSERT_TRUE(at_10.rotation_deg_per_m);
  EXPECT_NEAR(at_10.rotation_deg_per_m->mean, 0.02 * 1.70, 1e-12);
  // The lowest mean drift at each length is marked, once.
  for (std::size_t k = 0; k < table->lengths_m.size(); ++k) {
    std::size_t best = 0;
    for (const SegmentRow& row : table->rows) best += row.cells[k].best ? 1 : 0;
    EXPECT_EQ(best, 1u);
  }
  EXPECT_FALSE(BuildSegmentTable(model, Table(model, "mit-no-ref")));
}

TEST_F(ViewsModelTest, RunsScoredAtOtherLengthsAreNamedAndNeverPooled) {
  std::vector<testing::FixtureRun> runs;
  for (int i = 0; i < 3; ++i) {
    testing::FixtureRun run = testing::MakeRun("gmapping", "intel", i);
    run.ape_rmse_m = 0.1;
    run.segment_lengths_m = i == 2 ? std::vector<double>{15} : std::vector<double>{10, 20};
    runs.push_back(run);
  }
  const SweepModel model = Load(runs);
  // One run's segments are unreadable: its boxes are left out, its mean drift still counts.
  slamsweep::testing::WriteFile(model.runs[1].dir / "rpe_segments.csv", "not,a,segment,file\n");
  const std::optional<SegmentTable> table = BuildSegmentTable(model, model.sequences[0]);
  ASSERT_TRUE(table);
  EXPECT_THAT(table->lengths_m, ElementsAre(10, 15, 20));
  EXPECT_EQ(table->notes.size(), 1u);
  ASSERT_EQ(table->rows.size(), 1u);
  const SegmentRow& row = table->rows[0];
  EXPECT_EQ(row.cells[0].mean_drift_pct.n, 2u);     // 10 m: runs 0 and 1
  EXPECT_EQ(row.cells[1].mean_drift_pct.n, 1u);     // 15 m: run 2 only
  EXPECT_EQ(row.cells[0].translation_pct->n, 20u);  // run 1's file is unreadable
  ASSERT_EQ(row.notes.size(), 2u);
  EXPECT_THAT(row.notes[0], HasSubstr(model.runs[1].run_id));
  EXPECT_THAT(row.notes[1], HasSubstr("different segment lengths"));
}

TEST_F(ViewsModelTest, OneVaryingParameterIsACurveWithTheOthersNamedConstant) {
  const SweepModel model = Load(testing::ViewsFixtureRuns());
  const SequenceModel& intel = Table(model, "intel");
  const std::optional<ParameterTable> table = BuildParameterTable(model, intel);
  ASSERT_TRUE(table);
  ASSERT_EQ(table->sweeps.size(), 2u);  // icp-slam and rbpf-slam; gmapping and hector have one row each
  const ParameterSweep& icp = table->sweeps[0];
  EXPECT_EQ(icp.algorithm, "icp-slam");
  ASSERT_EQ(icp.axes.size(), 1u);
  EXPECT_EQ(icp.axes[0].name, "ICP.maxIterations");
  EXPECT_TRUE(icp.axes[0].numeric);
  EXPECT_EQ(icp.axes[0].values, (std::vector<nlohmann::json>{20, 40, 80}));
  EXPECT_EQ(icp.constant, "ICP.thresholdDist=0.75");
  ASSERT_EQ(icp.slices.size(), 1u);
  ASSERT_EQ(icp.slices[0].cells.size(), 1u);
  const std::vector<ColumnRef> columns = TableColumns(intel);
  ASSERT_FALSE(columns.empty());
  EXPECT_EQ(ColumnOf(intel, columns[0]).metric, "ape_trans");
  const BestValue best = FindBest(intel, icp.slices[0].Rows(), columns[0]);
  ASSERT_TRUE(best.row);
  EXPECT_EQ(intel.rows[*best.row].parameters, "ICP.maxIterations=40;ICP.thresholdDist=0.75");
  ASSERT_TRUE(best.runner_up);
  EXPECT_EQ(intel.rows[*best.runner_up].parameters, "ICP.maxIterations=80;ICP.thresholdDist=0.75");
  EXPECT_TRUE(best.clear);  // 0.125 +- 0.007 against 0.205 +- 0.007
}

TEST_F(ViewsModelTest, TwoVaryingParametersAreAHeatmap) {
  const SweepModel model = Load(testing::ViewsFixtureRuns());
  const SequenceModel& intel = Table(model, "intel");
  const std::optional<ParameterTable> table = BuildParameterTable(model, intel);
  ASSERT_TRUE(table);
  const ParameterSweep& rbpf = table->sweeps.at(1);
  EXPECT_EQ(rbpf.algorithm, "rbpf-slam");
  ASSERT_EQ(rbpf.axes.size(), 2u);
  // Two values each: ties go by name, so particles across and resample up.
  EXPECT_EQ(rbpf.axes[0].name, "particles");
  EXPECT_EQ(rbpf.axes[1].name, "resample");
  ASSERT_EQ(rbpf.slices.size(), 1u);
  const ParameterSlice& slice = rbpf.slices[0];
  ASSERT_EQ(slice.cells.size(), 2u);
  for (const auto& line : slice.cells) {
    ASSERT_EQ(line.size(), 2u);
    for (const auto& cell : line) EXPECT_TRUE(cell);
  }
  // particles 30, resample 0.5: the lowest ATE (0.5 / 30 + 0.05).
  const BestValue best = FindBest(intel, slice.Rows(), TableColumns(intel)[0]);
  ASSERT_TRUE(best.row);
  EXPECT_EQ(*best.row, *slice.cells[0][1]);
}

TEST_F(ViewsModelTest, ThreeOrMoreVaryingParametersGiveOneSlicePerCombinationOfTheOthers) {
  std::vector<testing::FixtureRun> runs;
  for (const int a : {1, 2, 3}) {
    for (const int b : {1, 2}) {
      for (const std::string c : {"x", "y"}) {
        for (const bool d : {false, true}) {
          testing::FixtureRun run = testing::MakeRun("slam", "intel", 0);
          run.parameters = {{"a", a}, {"b", b}, {"c", c}, {"d", d}};
          run.ape_rmse_m = 0.1 * a + 0.01 * b + (c == "x" ? 0.0 : 0.5) + (d ? 0.2 : 0.0);
          runs.push_back(run);
        }
      }
    }
  }
  const SweepModel model = Load(runs);
  const SequenceModel& intel = model.sequences[0];
  const std::optional<ParameterTable> table = BuildParameterTable(model, intel);
  ASSERT_TRUE(table);
  const ParameterSweep& sweep = table->sweeps.at(0);
  // Drawn: a (3 values) across, then b (2 values, first by name among b, c, d) up; c and d sliced.
  EXPECT_EQ(sweep.axes[0].name, "a");
  EXPECT_EQ(sweep.axes[1].name, "b");
  ASSERT_EQ(sweep.sliced.size(), 2u);
  EXPECT_EQ(sweep.sliced[0].name, "c");
  EXPECT_EQ(sweep.sliced[1].name, "d");
  ASSERT_EQ(sweep.slices.size(), 4u);
  EXPECT_EQ(SliceText(sweep, sweep.slices[0]), "c=x, d=false");
  EXPECT_EQ(SliceText(sweep, sweep.slices[3]), "c=y, d=true");
  // The best is named within a slice: in c=y, d=true it is a=1, b=1 although other slices score lower.
  const ParameterSlice& last = sweep.slices[3];
  EXPECT_EQ(last.Rows().size(), 6u);
  const BestValue best = FindBest(intel, last.Rows(), TableColumns(intel)[0]);
  EXPECT_EQ(*best.row, *last.cells[0][0]);
  EXPECT_FALSE(best.clear) << "one run per row: no spread to tell a difference from noise";
}

TEST_F(ViewsModelTest, EqualMeansAreATieNotABest) {
  std::vector<testing::FixtureRun> runs;
  for (const int p : {1, 2, 3}) {
    for (int i = 0; i < 2; ++i) {
      testing::FixtureRun run = testing::MakeRun("slam", "intel", i);
      run.parameters = {{"p", p}};
      run.ape_rmse_m = p == 3 ? 0.9 : 0.25 + 0.05 * i;  // p=1 and p=2: 0.25 and 0.30 each
      runs.push_back(run);
    }
  }
  const SweepModel model = Load(runs);
  const SequenceModel& intel = model.sequences[0];
  const std::optional<ParameterTable> table = BuildParameterTable(model, intel);
  ASSERT_TRUE(table);
  const BestValue best = FindBest(intel, table->sweeps.at(0).slices[0].Rows(), TableColumns(intel)[0]);
  EXPECT_TRUE(best.tie);
  EXPECT_FALSE(best.clear);
}

TEST_F(ViewsModelTest, RowsWhoseOdometryIsTheReferenceAreNeverBest) {
  std::vector<testing::FixtureRun> runs;
  for (const int p : {1, 2}) {
    testing::FixtureRun run = testing::MakeRun("slam", "intel", 0);
    run.parameters = {{"p", p}};
    run.ape_rmse_m = p == 1 ? 0.01 : 0.5;
    runs.push_back(run);
  }
  testing::WriteFixtureSweep(dir_ / "sweep", runs);
  std::vector<RunRecord> records = LoadRuns(dir_ / "sweep");
  for (RunRecord& record : records) {
    record.flags.Set(orchestrator::RunFlag::kOdometryIsReference, record.parameters == "p=1");
  }
  const SweepModel model = BuildSweepModel(std::move(records));
  const SequenceModel& intel = model.sequences[0];
  const std::optional<ParameterTable> table = BuildParameterTable(model, intel);
  ASSERT_TRUE(table);
  const ParameterSweep& sweep = table->sweeps.at(0);
  const BestValue best = FindBest(intel, sweep.slices[0].Rows(), TableColumns(intel)[0]);
  ASSERT_TRUE(best.row);
  EXPECT_EQ(intel.rows[*best.row].parameters, "p=2");
  EXPECT_FALSE(best.runner_up);
}

}  // namespace
}  // namespace slamsweep::report
