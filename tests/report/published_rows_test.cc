// Published relations errors beside a table: drawn as reference lines for a whole log scored against that
// log's relations file, never ranked, never for a cut of the log. Values are those of the test's own file.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "evaluator/core/input_error.h"
#include "report/model/published_figures.h"
#include "report/model/sweep_model.h"
#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

RunRecord MakeRecord(const std::string& algorithm, const std::string& sequence, int iteration, double relations_m,
                     const nlohmann::json& max_scans) {
  RunRecord run;
  run.run_id = algorithm + "-" + sequence + "-i" + std::to_string(iteration);
  run.algorithm = algorithm;
  run.sequence = sequence;
  run.noise = "none";
  run.iteration = iteration;
  run.status = RunStatus::kOk;
  run.metrics = {{"relations_trans", "mean", relations_m, "m"}, {"relations_rot", "mean", 1.0, "deg"}};
  run.run_spec = {
      {"algorithm", {{"adapter", algorithm}}},
      {"sequence", {{"name", sequence}, {"relations", "/data/intel/intel.relations"}, {"max_scans", max_scans}}}};
  return run;
}

std::vector<PublishedFigure> Figures(const slamsweep::testing::TempDir& dir) {
  const auto file = slamsweep::testing::WriteFile(dir / "published.yaml", R"(sources:
  paper: {citation: "A. Author, A Paper, 2016", verified: true}
  notes: {citation: "B. Other, 2009", verified: false}
published:
  - {sequence: intel, source: paper, label: Cartographer, trans_abs: [0.0229, 0.0239], rot_abs: [0.453, 1.335]}
  - {sequence: intel, source: notes, label: RBPF, trans_abs: [0.070, 0.083]}
  - {sequence: fr079, source: paper, label: Cartographer, trans_abs: [0.0452, 0.0354]}
)");
  return ReadPublishedFigures(file);
}

TEST(PublishedRowsTest, AWholeLogGetsItsPublishedRowsNeverRanked) {
  slamsweep::testing::TempDir dir;
  SweepModelOptions options;
  options.published = Figures(dir);
  ASSERT_EQ(options.published.size(), 3u);
  std::vector<RunRecord> runs;
  for (int i = 0; i < 3; ++i) runs.push_back(MakeRecord("gmapping", "intel", i, 0.5 + 0.1 * i, nullptr));
  const SweepModel model = BuildSweepModel(runs, options);
  ASSERT_EQ(model.sequences.size(), 1u);
  const SequenceModel& table = model.sequences[0];
  std::vector<const AlgorithmRow*> published;
  for (const AlgorithmRow& row : table.rows) {
    if (row.kind == RowKind::kPublished) published.push_back(&row);
  }
  ASSERT_EQ(published.size(), 2u);  // intel's two figures, not fr079's
  EXPECT_EQ(published[0]->algorithm, "published: Cartographer [paper]");
  EXPECT_EQ(published[1]->algorithm, "published: RBPF [notes, unverified]");
  std::size_t trans = table.trajectory_columns.size();
  for (std::size_t c = 0; c < table.trajectory_columns.size(); ++c) {
    if (table.trajectory_columns[c].metric == "relations_trans") trans = c;
  }
  ASSERT_LT(trans, table.trajectory_columns.size());
  EXPECT_DOUBLE_EQ(published[0]->trajectory_cells[trans].summary.mean, 0.0229);
  EXPECT_DOUBLE_EQ(*published[0]->trajectory_cells[trans].summary.std, 0.0239);
  // The published figures are far lower than gmapping's 0.6 m, yet only the contestant is marked best.
  for (const AlgorithmRow* row : published) {
    EXPECT_FALSE(IsBestCandidate(*row));
    for (const MetricCell& cell : row->trajectory_cells) EXPECT_FALSE(cell.best);
  }
  for (const AlgorithmRow& row : table.rows) {
    if (row.kind == RowKind::kContestant) {
      EXPECT_TRUE(row.trajectory_cells[trans].best) << row.algorithm;
    }
  }
}

TEST(PublishedRowsTest, ACutOfTheLogGetsNone) {
  slamsweep::testing::TempDir dir;
  SweepModelOptions options;
  options.published = Figures(dir);
  std::vector<RunRecord> runs;
  for (int i = 0; i < 2; ++i) runs.push_back(MakeRecord("gmapping", "intel-200", i, 0.5, 200));
  const SweepModel model = BuildSweepModel(runs, options);
  for (const AlgorithmRow& row : model.sequences.at(0).rows) EXPECT_NE(row.kind, RowKind::kPublished) << row.algorithm;
}

// A log of part of the run (its relations file reaches beyond it): the published figures are over the whole
// log, so each row says its figure was not measured on the same relations.
TEST(PublishedRowsTest, APartialLogGetsThemWithANoteThatTheRelationsDiffer) {
  slamsweep::testing::TempDir dir;
  SweepModelOptions options;
  options.published = Figures(dir);
  std::vector<RunRecord> runs;
  for (int i = 0; i < 2; ++i) {
    RunRecord run = MakeRecord("cartographer", "intel-full-rate", i, 0.03, nullptr);
    run.metrics.push_back({"relations_trans", "n", 1033.0, "count"});
    run.metrics.push_back({"relations_trans", "not_covered", 0.0, "count"});
    run.metrics.push_back({"relations_trans", "outside_log", 1951.0, "count"});
    runs.push_back(run);
  }
  const SweepModel model = BuildSweepModel(runs, options);
  std::size_t published = 0;
  for (const AlgorithmRow& row : model.sequences.at(0).rows) {
    if (row.kind != RowKind::kPublished) {
      EXPECT_TRUE(row.scope_note.empty());
      continue;
    }
    ++published;
    EXPECT_EQ(row.scope_note,
              "over the whole log's relations, not the same relations: this table scores the 1033 of 2984 that lie "
              "inside its log");
  }
  EXPECT_EQ(published, 2u);
}

TEST(PublishedRowsTest, AMalformedEntryIsNamed) {
  slamsweep::testing::TempDir dir;
  const auto file = slamsweep::testing::WriteFile(
      dir / "bad.yaml", "sources: {}\npublished:\n  - {sequence: intel, label: X, source: nowhere}\n");
  try {
    ReadPublishedFigures(file);
    FAIL() << "no error";
  } catch (const evaluator::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("published[0]"), std::string::npos) << error.what();
  }
}

TEST(PublishedRowsTest, TheShippedFileReads) {
  const std::vector<PublishedFigure> shipped =
      ReadPublishedFigures(std::filesystem::path(SLAMSWEEP_SOURCE_DIR) / "configs/published.yaml");
  bool intel_cartographer = false;
  for (const PublishedFigure& figure : shipped) {
    if (figure.sequence == "intel" && figure.label == "Cartographer" && figure.trans_abs) {
      intel_cartographer = figure.trans_abs->first == 0.0229 && figure.verified;
    }
  }
  EXPECT_TRUE(intel_cartographer) << "Hess et al. 2016's intel figure, as configs/published.yaml states it";
}

}  // namespace
}  // namespace slamsweep::report
