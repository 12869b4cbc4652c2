// "Best" only where it is earned: a row is a candidate only when every run succeeded, it is a
// contestant (never the odometry baseline) and carries no run mark; a ground-truth-free metric is
// marked best only where the metric validity study shows that it tracks the error.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "evaluator/validity/metric_validity.h"
#include "orchestrator/store/named_study.h"
#include "report/model/load_runs.h"
#include "report/model/named_study.h"
#include "report/model/parameter_model.h"
#include "report/model/sweep_model.h"
#include "tests/report/fixture_sweep.h"
#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

using slamsweep::testing::TempDir;
using testing::FixtureRun;
using ::testing::HasSubstr;
using testing::MakeRun;
using ::testing::Not;

const SequenceModel& Sequence(const SweepModel& model, const std::string& name) {
  for (const SequenceModel& sequence : model.sequences) {
    if (sequence.name == name) return sequence;
  }
  throw std::runtime_error("no sequence " + name);
}

const AlgorithmRow& Row(const SequenceModel& sequence, const std::string& algorithm) {
  for (const AlgorithmRow& row : sequence.rows) {
    if (row.algorithm == algorithm) return row;
  }
  throw std::runtime_error("no row " + algorithm);
}

std::size_t Column(const std::vector<MetricColumn>& columns, const std::string& metric) {
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (columns[c].metric == metric) return c;
  }
  throw std::runtime_error("no column " + metric);
}

/// Four iterations of "good", "fair", "flaky" (lowest ATE, one failed run) and the odometry
/// baseline on "floor" (with a reference). Corners rise exactly with the ATE (the study finds
/// they track it); the occupied ratio zigzags against it (the study finds no relation), and the
/// baseline's is the lowest of all, like the smeared map of the quick start's Telecom table.
/// "hall" has no reference: the same algorithms with corners and occupied ratios only.
std::vector<FixtureRun> BestFixtureRuns(bool with_floor = true) {
  struct Algorithm {
    const char* name;
    const char* adapter;
    double ate;
  };
  const Algorithm algorithms[] = {
      {"good", "generic", 0.10}, {"fair", "generic", 0.20}, {"flaky", "generic", 0.05}, {"odometry", "odometry", 1.00}};
  std::vector<FixtureRun> runs;
  for (const Algorithm& algorithm : algorithms) {
    for (int i = 0; i < 4; ++i) {
      const double ate = algorithm.ate + 0.01 * i;
      const double zigzag = (i % 2 == 0 ? 0.3 : 0.1) + 0.01 * (algorithm.ate > 0.15 ? 1 : 0);
      const double occupied = std::string(algorithm.adapter) == "odometry" ? 0.01 : zigzag;
      if (with_floor) {
        FixtureRun floor = MakeRun(algorithm.name, "floor", i);
        floor.adapter = algorithm.adapter;
        floor.ape_rmse_m = ate;
        floor.corners = 100.0 * ate;
        floor.occupied_ratio = occupied;
        floor.enclosed_areas = 1.0;
        if (std::string(algorithm.name) == "flaky" && i == 3) floor.ok = false;
        runs.push_back(floor);
      }
      FixtureRun hall = MakeRun(algorithm.name, "hall", i);
      hall.adapter = algorithm.adapter;
      hall.with_reference = false;
      hall.corners = 100.0 * ate + 5.0;
      hall.occupied_ratio = occupied;
      runs.push_back(hall);
    }
  }
  return runs;
}

SweepModel ModelOf(const std::vector<FixtureRun>& runs, TempDir& dir) {
  testing::WriteFixtureSweep(dir.path(), runs);
  return BuildSweepModel(LoadRuns(dir.path()), LoadSweepModelOptions(dir.path()));
}

TEST(BestMarksTest, ARowWithAFailedRunIsNeverBestEvenWithTheLowestMean) {
  TempDir dir;
  const SweepModel model = ModelOf(BestFixtureRuns(), dir);
  const SequenceModel& floor = Sequence(model, "floor");
  const std::size_t ate = Column(floor.trajectory_columns, "ape_trans");
  const AlgorithmRow& flaky = Row(floor, "flaky");
  EXPECT_EQ(flaky.counts.ok, 3u);
  EXPECT_LT(flaky.trajectory_cells[ate].summary.mean, Row(floor, "good").trajectory_cells[ate].summary.mean);
  EXPECT_FALSE(IsBestCandidate(flaky));
  EXPECT_FALSE(flaky.trajectory_cells[ate].best);
  EXPECT_TRUE(Row(floor, "good").trajectory_cells[ate].best);
  // The parameter pages' ranking goes through the same rule.
  std::vector<std::size_t> all(floor.rows.size());
  for (std::size_t r = 0; r < all.size(); ++r) all[r] = r;
  const BestValue best = FindBest(floor, all, ColumnRef{true, ate});
  ASSERT_TRUE(best.row);
  EXPECT_EQ(floor.rows[*best.row].algorithm, "good");
}

// A run reused under another build (--reuse-stale) keeps its numbers on the page but never wins: "good"
// has the lowest complete mean, and stale it gives the mark to "fair".
TEST(BestMarksTest, AStaleRowIsShownWithItsMarkButNeverBest) {
  TempDir dir;
  testing::WriteFixtureSweep(dir.path(), BestFixtureRuns());
  std::vector<RunRecord> records = LoadRuns(dir.path());
  for (RunRecord& record : records) record.flags.Set(orchestrator::RunFlag::kStale, record.algorithm == "good");
  const SweepModel model = BuildSweepModel(std::move(records), LoadSweepModelOptions(dir.path()));
  const SequenceModel& floor = Sequence(model, "floor");
  const std::size_t ate = Column(floor.trajectory_columns, "ape_trans");
  const AlgorithmRow& good = Row(floor, "good");
  EXPECT_TRUE(good.flags.Has(orchestrator::RunFlag::kStale));
  EXPECT_FALSE(IsBestCandidate(good));
  EXPECT_FALSE(good.trajectory_cells[ate].best);
  EXPECT_LT(good.trajectory_cells[ate].summary.mean, Row(floor, "fair").trajectory_cells[ate].summary.mean);
  EXPECT_TRUE(Row(floor, "fair").trajectory_cells[ate].best);
  std::vector<std::size_t> all(floor.rows.size());
  for (std::size_t r = 0; r < all.size(); ++r) all[r] = r;
  const BestValue best = FindBest(floor, all, ColumnRef{true, ate});
  ASSERT_TRUE(best.row);
  EXPECT_EQ(floor.rows[*best.row].algorithm, "fair");
}

TEST(BestMarksTest, TheOdometryBaselineIsALineToBeatNeverBest) {
  TempDir dir;
  const SweepModel model = ModelOf(BestFixtureRuns(), dir);
  const SequenceModel& floor = Sequence(model, "floor");
  const AlgorithmRow& odometry = Row(floor, "odometry");
  EXPECT_EQ(odometry.kind, RowKind::kOdometryBaseline);
  EXPECT_FALSE(IsBestCandidate(odometry));
  for (const MetricCell& cell : odometry.map_cells) EXPECT_FALSE(cell.best);
  for (const MetricCell& cell : odometry.trajectory_cells) EXPECT_FALSE(cell.best);
}

TEST(BestMarksTest, AMapMetricTheStudySupportsIsMarkedOneItDoesNotIsShownWithTheReason) {
  TempDir dir;
  const SweepModel model = ModelOf(BestFixtureRuns(), dir);
  const SequenceModel& floor = Sequence(model, "floor");
  const std::size_t corners = Column(floor.map_columns, "corners");
  const std::size_t occupied = Column(floor.map_columns, "occupied_to_free_unknown");
  // Corners track the ATE (rho = 1 within the one noise setting): the lowest candidate is best.
  EXPECT_EQ(floor.map_columns[corners].best_withheld, "");
  EXPECT_TRUE(Row(floor, "good").map_cells[corners].best);
  EXPECT_FALSE(Row(floor, "fair").map_cells[corners].best);
  // The occupied ratio does not: shown, every cell unmarked, and the note says why and on what evidence.
  const std::string& why = floor.map_columns[occupied].best_withheld;
  EXPECT_THAT(why, HasSubstr("Occupied proportion"));
  EXPECT_THAT(why, HasSubstr("does not show that it tracks the error"));
  EXPECT_THAT(why, HasSubstr("ATE translation RMSE"));
  for (const AlgorithmRow& row : floor.rows) {
    EXPECT_EQ(row.map_cells[occupied].summary.n > 0, true) << row.algorithm;
    EXPECT_FALSE(row.map_cells[occupied].best) << row.algorithm;
  }
}

TEST(BestMarksTest, WithoutAReferenceTheSweepsStudyOfAnotherSequenceDecides) {
  TempDir dir;
  const SweepModel model = ModelOf(BestFixtureRuns(), dir);
  const SequenceModel& hall = Sequence(model, "hall");
  ASSERT_FALSE(hall.has_reference);
  const std::size_t corners = Column(hall.map_columns, "corners");
  const std::size_t occupied = Column(hall.map_columns, "occupied_to_free_unknown");
  EXPECT_EQ(hall.map_columns[corners].best_withheld, "");
  EXPECT_TRUE(Row(hall, "flaky").map_cells[corners].best);  // all four of its runs on hall succeeded
  EXPECT_THAT(hall.map_columns[occupied].best_withheld, HasSubstr("this sweep's sequence floor"));
}

TEST(BestMarksTest, WithoutAnyReferenceOnlyANamedStudyEarnsABest) {
  TempDir alone;
  const SweepModel unsupported = ModelOf(BestFixtureRuns(false), alone);
  const SequenceModel& hall = Sequence(unsupported, "hall");
  for (const MetricColumn& column : hall.map_columns) {
    EXPECT_THAT(column.best_withheld, HasSubstr("no sequence of this sweep has a reference")) << column.metric;
  }
  for (const AlgorithmRow& row : hall.rows) {
    for (const MetricCell& cell : row.map_cells) EXPECT_FALSE(cell.best) << row.algorithm;
  }

  // A study of another sweep (the floor runs), named by this one and copied into its result directory.
  TempDir other;
  const SweepModel studied = ModelOf(BestFixtureRuns(), other);
  orchestrator::NamedStudy named;
  named.source = "validity/summary.json";
  named.json = evaluator::ToJson(studied.validity);
  TempDir with_study;
  testing::WriteFixtureSweep(with_study.path(), BestFixtureRuns(false));
  orchestrator::WriteNamedStudy(named, with_study.path());
  const SweepModel supported = BuildSweepModel(LoadRuns(with_study.path()), LoadSweepModelOptions(with_study.path()));
  const SequenceModel& hall2 = Sequence(supported, "hall");
  const std::size_t corners = Column(hall2.map_columns, "corners");
  EXPECT_EQ(hall2.map_columns[corners].best_withheld, "");
  EXPECT_TRUE(Row(hall2, "flaky").map_cells[corners].best);
  EXPECT_THAT(hall2.map_columns[Column(hall2.map_columns, "occupied_to_free_unknown")].best_withheld,
              HasSubstr("the named study validity/summary.json"));
}

TEST(BuildSplitTest, RunsOfOneAlgorithmByDifferentBuildsAreSeparateLabelledRows) {
  std::vector<FixtureRun> runs;
  for (int i = 0; i < 4; ++i) {
    FixtureRun run = MakeRun("gmapping", "intel", i);
    run.ape_rmse_m = i < 2 ? 0.1 : 0.3;
    run.build = {{"slamsweep_revision", "0.1+abc"},
                 {"program_files", {{"/opt/slamsweep-slam-gmapping", std::string(64, i < 2 ? '1' : '2')}}}};
    runs.push_back(run);
  }
  TempDir dir;
  const SweepModel model = ModelOf(runs, dir);
  const SequenceModel& intel = Sequence(model, "intel");
  ASSERT_EQ(intel.rows.size(), 2u);
  const std::size_t ate = Column(intel.trajectory_columns, "ape_trans");
  for (const AlgorithmRow& row : intel.rows) {
    EXPECT_TRUE(row.build_split);
    EXPECT_THAT(row.algorithm, HasSubstr("gmapping [build b"));
    EXPECT_THAT(row.build_description, HasSubstr("slamsweep-slam-gmapping"));
    EXPECT_EQ(row.counts.total, 2u);
    EXPECT_DOUBLE_EQ(row.trajectory_cells[ate].summary.std.value_or(-1), 0.0);  // 0.1, 0.1 or 0.3, 0.3: never mixed
  }
  EXPECT_NE(intel.rows[0].build, intel.rows[1].build);
}

TEST(OdometrySplitTest, RunsOnRecordedAndOnReferenceOdometryAreSeparateLabelledRows) {
  std::vector<FixtureRun> runs;
  for (int i = 0; i < 4; ++i) {
    FixtureRun run = MakeRun("gmapping", "intel", i);
    run.ape_rmse_m = i < 2 ? 0.1 : 0.3;
    run.odometry = i < 2 ? "reference" : "recorded";
    runs.push_back(run);
  }
  TempDir dir;
  const SweepModel model = ModelOf(runs, dir);
  const SequenceModel& intel = Sequence(model, "intel");
  ASSERT_EQ(intel.rows.size(), 2u);
  const std::size_t ate = Column(intel.trajectory_columns, "ape_trans");
  for (const AlgorithmRow& row : intel.rows) {
    EXPECT_THAT(row.algorithm, ::testing::AnyOf(HasSubstr("gmapping [recorded odometry]"),
                                                HasSubstr("gmapping [reference odometry]")));
    EXPECT_EQ(row.counts.total, 2u);
    EXPECT_DOUBLE_EQ(row.trajectory_cells[ate].summary.std.value_or(-1), 0.0);  // never mixed
  }
}

TEST(BestMarksTest, ANamedStudyThatIsNotAStudyIsAnErrorNamingTheFile) {
  TempDir dir;
  testing::WriteFixtureSweep(dir.path(), BestFixtureRuns(false));
  slamsweep::testing::WriteFile(dir / "validity_study.json", R"({"source": "x", "validity": {"method": {}}})");
  try {
    LoadSweepModelOptions(dir.path());
    FAIL() << "expected an InputError";
  } catch (const std::exception& error) {
    EXPECT_THAT(error.what(), HasSubstr("validity_study.json"));
    EXPECT_THAT(error.what(), HasSubstr("confidence"));
  }
}

/// A run on a corrected log with relations: ATE, relations and the reference floor as result.json has them.
RunRecord CorrectedLogRun(const std::string& algorithm, const std::string& adapter, double ate_m, double relations_m,
                          double floor_m) {
  RunRecord run;
  run.run_id = algorithm + "-intel";
  run.algorithm = algorithm;
  run.sequence = "intel";
  run.noise = "none";
  run.status = RunStatus::kOk;
  run.run_spec =
      nlohmann::json{{"algorithm", {{"adapter", adapter}}}, {"sequence", {{"ground_truth", "corrected_poses"}}}};
  run.metrics = {{"ape_trans", "rmse", ate_m, "m"},
                 {"relations_trans", "mean", relations_m, "m"},
                 {"relations_trans", "n", 2984.0, "count"}};
  run.reference_floor = {{"relations_trans", "mean", floor_m, "m"}, {"relations_trans", "n", 2984.0, "count"}};
  return run;
}

TEST(ReferenceFloorTest, CorrectedLogTablesLeadWithRelationsShowTheFloorAndNeverRankIt) {
  // GMapping agrees best with the corrected log (its own output); Cartographer has the lower
  // relations error; the floor (the corrected log itself) is lower still but is no contestant.
  const SweepModel model = BuildSweepModel({CorrectedLogRun("gmapping", "gmapping", 0.10, 0.17, 0.067),
                                            CorrectedLogRun("cartographer", "cartographer", 1.40, 0.05, 0.067),
                                            CorrectedLogRun("odometry", "odometry", 21.0, 7.4, 0.067)});
  const SequenceModel& intel = Sequence(model, "intel");
  ASSERT_FALSE(intel.trajectory_columns.empty());
  EXPECT_EQ(intel.trajectory_columns[0].metric, "relations_trans");
  const std::size_t ate = Column(intel.trajectory_columns, "ape_trans");
  EXPECT_THAT(intel.trajectory_columns[ate].title, HasSubstr("agreement with the corrected log (GMapping's output)"));
  const std::size_t relations = Column(intel.trajectory_columns, "relations_trans");
  EXPECT_THAT(intel.trajectory_columns[relations].title, Not(HasSubstr("agreement")));

  const AlgorithmRow& floor = Row(intel, "reference floor: the corrected log itself");
  EXPECT_EQ(floor.kind, RowKind::kReferenceFloor);
  EXPECT_FALSE(IsBestCandidate(floor));
  EXPECT_DOUBLE_EQ(floor.trajectory_cells[relations].summary.mean, 0.067);
  EXPECT_FALSE(floor.trajectory_cells[relations].best);
  EXPECT_EQ(floor.trajectory_cells[ate].summary.n, 0u);
  EXPECT_TRUE(floor.runs.empty());
  // Best by the relations error: Cartographer, not the floor and not GMapping.
  EXPECT_TRUE(Row(intel, "cartographer").trajectory_cells[relations].best);
  EXPECT_FALSE(Row(intel, "gmapping").trajectory_cells[relations].best);
  EXPECT_EQ(Row(intel, "odometry").kind, RowKind::kOdometryBaseline);
}

TEST(ReferenceFloorTest, NoRelationsNoFloorRow) {
  RunRecord run = CorrectedLogRun("gmapping", "gmapping", 0.1, 0.1, 0.1);
  run.metrics = {{"ape_trans", "rmse", 0.1, "m"}};
  run.reference_floor.clear();
  const SweepModel model = BuildSweepModel({run});
  for (const AlgorithmRow& row : Sequence(model, "intel").rows) EXPECT_NE(row.kind, RowKind::kReferenceFloor);
}

}  // namespace
}  // namespace slamsweep::report
