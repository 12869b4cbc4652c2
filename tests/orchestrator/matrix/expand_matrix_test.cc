#include "orchestrator/matrix/expand_matrix.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <set>

#include "evaluator/core/input_error.h"
#include "evaluator/noise/random.h"
#include "orchestrator/matrix/run_id.h"
#include "tests/orchestrator/matrix/test_config.h"
#include "orchestrator/run/run_json.h"

namespace slamsweep::orchestrator {
namespace {

using nlohmann::json;

/// "algorithm|parameters|sequence|noise|iteration" of each run, to compare orders at a glance.
std::vector<std::string> Cells(const std::vector<RunSpec>& runs) {
  std::vector<std::string> cells;
  for (const RunSpec& run : runs) {
    cells.push_back(run.algorithm.name + "|" + run.algorithm.parameters.dump() + "|" + run.sequence.entry.name + "|" +
                    run.noise.name + "|" + std::to_string(run.iteration));
  }
  return cells;
}

TEST(ExpandMatrixTest, CartesianProductInTheWrittenOrder) {
  SweepConfig config = testing::TwoByTwo();
  config.algorithms.pop_back();
  config.sequences.pop_back();
  config.noise.pop_back();
  config.iterations = 1;
  // p varies slowest (written first), then q.
  EXPECT_THAT(Cells(ExpandMatrix(config)),
              ::testing::ElementsAre(R"(icp|{"p":1,"q":"a"}|seq1|clean|0)", R"(icp|{"p":1,"q":"b"}|seq1|clean|0)",
                                     R"(icp|{"p":2,"q":"a"}|seq1|clean|0)", R"(icp|{"p":2,"q":"b"}|seq1|clean|0)"));
}

TEST(ExpandMatrixTest, NestsAlgorithmParametersSequenceNoiseIteration) {
  const std::vector<RunSpec> runs = ExpandMatrix(testing::TwoByTwo());
  ASSERT_EQ(runs.size(), 40u);  // (4 combinations + 1) x 2 sequences x 2 noise x 2 iterations
  const std::vector<std::string> cells = Cells(runs);
  EXPECT_EQ(cells[0], R"(icp|{"p":1,"q":"a"}|seq1|clean|0)");
  EXPECT_EQ(cells[1], R"(icp|{"p":1,"q":"a"}|seq1|clean|1)");
  EXPECT_EQ(cells[2], R"(icp|{"p":1,"q":"a"}|seq1|noisy|0)");
  EXPECT_EQ(cells[4], R"(icp|{"p":1,"q":"a"}|seq2|clean|0)");
  EXPECT_EQ(cells[8], R"(icp|{"p":1,"q":"b"}|seq1|clean|0)");
  EXPECT_EQ(cells[32], R"(odo|{}|seq1|clean|0)");
  EXPECT_EQ(cells[39], R"(odo|{}|seq2|noisy|1)");
  for (const RunSpec& run : runs) {
    EXPECT_EQ(run.sweep, "t");
    EXPECT_EQ(run.run_id, MakeRunId(run));
  }
  // Deterministic: the same config gives the same runs in the same order.
  EXPECT_EQ(Cells(ExpandMatrix(testing::TwoByTwo())), cells);
}

TEST(ExpandMatrixTest, CarriesTheResolvedSettingsIntoEveryRun) {
  SweepConfig config = testing::TwoByTwo();
  config.algorithms[0].timeout_s = 12;
  config.algorithms[0].memory_limit_mb = 99;
  config.evaluation.align = "sim2";
  config.thresholds = {Threshold{"ape_trans", "rmse", 1.0, std::nullopt}};
  config.sequences[0].max_scans = 30;
  config.sequences[0].entry.ground_truth = evaluator::GroundTruthKind::kCorrectedPoses;
  const RunSpec run = ExpandMatrix(config).front();
  EXPECT_EQ(run.algorithm.timeout_s, 12);
  EXPECT_EQ(run.algorithm.memory_limit_mb, 99u);
  EXPECT_EQ(run.evaluation.align, "sim2");
  ASSERT_EQ(run.thresholds.size(), 1u);
  EXPECT_EQ(run.sequence.max_scans, 30u);
  EXPECT_EQ(run.sequence.entry.path, "/data/seq1.log");
}

TEST(ExpandMatrixTest, AThresholdThatNeedsAReferenceHoldsOnlyWhereThereIsOne) {
  SweepConfig config = testing::TwoByTwo();
  config.thresholds = {
      Threshold{"ape_trans", "rmse", 1.0, std::nullopt}, Threshold{"relations_trans", "mean", 0.5, std::nullopt},
      Threshold{"map_chamfer", "value", 0.2, std::nullopt}, Threshold{"corners", "value", 100.0, std::nullopt}};
  config.sequences[0].entry.ground_truth = evaluator::GroundTruthKind::kCorrectedPoses;
  config.sequences[0].entry.relations_path = "/data/seq1.relations";
  for (const RunSpec& run : ExpandMatrix(config)) {
    std::vector<std::string> metrics;
    for (const Threshold& threshold : run.thresholds) metrics.push_back(threshold.metric);
    if (run.sequence.entry.name == "seq1") {
      EXPECT_THAT(metrics, ::testing::ElementsAre("ape_trans", "relations_trans", "map_chamfer", "corners"));
    } else {
      // No reference of any kind: only the ground-truth-free metric can be held to its limit.
      EXPECT_THAT(metrics, ::testing::ElementsAre("corners"));
    }
  }
}

TEST(ExpandMatrixTest, ExcludeDropsCellsMatchingAllGivenKeys) {
  SweepConfig config = testing::TwoByTwo();
  CellFilter odo_seq2;
  odo_seq2.algorithm = "odo";
  odo_seq2.sequence = "seq2";
  CellFilter p2_noisy;
  p2_noisy.noise = "noisy";
  p2_noisy.parameters = {{"p", 2}};
  config.exclude = {odo_seq2, p2_noisy};
  const std::vector<RunSpec> runs = ExpandMatrix(config);
  // 40 - (odo, seq2: 2 noise x 2 it = 4) - (p=2 noisy: 2 q x 2 seq x 2 it = 8) = 28.
  EXPECT_EQ(runs.size(), 28u);
  for (const RunSpec& run : runs) {
    EXPECT_FALSE(run.algorithm.name == "odo" && run.sequence.entry.name == "seq2");
    EXPECT_FALSE(run.noise.name == "noisy" && run.algorithm.parameters.value("p", 0) == 2);
  }
  // A float 2.0 in a filter matches the integer 2 of the sweep (values compare as numbers).
  config.exclude = {p2_noisy};
  config.exclude[0].parameters = {{"p", 2.0}};
  EXPECT_EQ(ExpandMatrix(config).size(), 32u);
}

TEST(ExpandMatrixTest, IncludeAddsCellsAfterTheProductOnce) {
  SweepConfig config = testing::TwoByTwo();
  config.sequences.push_back(testing::Sequence("extra"));
  CellFilter exclude_extra;
  exclude_extra.sequence = "extra";
  config.exclude = {exclude_extra};
  CellFilter odo_extra_clean;
  odo_extra_clean.algorithm = "odo";
  odo_extra_clean.sequence = "extra";
  odo_extra_clean.noise = "clean";
  CellFilter icp_extra_p9;  // no noise: every noise setting; p replaced, q still swept
  icp_extra_p9.algorithm = "icp";
  icp_extra_p9.sequence = "extra";
  icp_extra_p9.parameters = {{"p", 9}};
  CellFilter already_there;  // in the product: adds nothing
  already_there.algorithm = "odo";
  already_there.sequence = "seq1";
  config.include = {odo_extra_clean, icp_extra_p9, already_there};
  const std::vector<RunSpec> runs = ExpandMatrix(config);
  const std::vector<std::string> cells = Cells(runs);
  ASSERT_EQ(runs.size(), 40u + 2 + 2 * 2 * 2);
  EXPECT_EQ(cells[40], R"(odo|{}|extra|clean|0)");
  EXPECT_EQ(cells[41], R"(odo|{}|extra|clean|1)");
  EXPECT_EQ(cells[42], R"(icp|{"p":9,"q":"a"}|extra|clean|0)");
  EXPECT_EQ(cells[44], R"(icp|{"p":9,"q":"a"}|extra|noisy|0)");
  EXPECT_EQ(cells[46], R"(icp|{"p":9,"q":"b"}|extra|clean|0)");
  std::set<std::string> ids;
  for (const RunSpec& run : runs) ids.insert(run.run_id);
  EXPECT_EQ(ids.size(), runs.size());
}

TEST(ExpandMatrixTest, PerIterationSeedsAreSharedAcrossAlgorithms) {
  const SweepConfig config = testing::TwoByTwo();
  for (const RunSpec& run : ExpandMatrix(config)) {
    EXPECT_EQ(run.seed, evaluator::DeriveSeed(42, static_cast<std::uint64_t>(run.iteration)));
  }
}

TEST(ExpandMatrixTest, PerRunSeedsDifferBetweenCellsAndFollowTheFormula) {
  SweepConfig config = testing::TwoByTwo();
  config.seed_policy = SeedPolicy::kPerRun;
  const std::vector<RunSpec> runs = ExpandMatrix(config);
  std::set<std::uint64_t> seeds;
  for (const RunSpec& run : runs) {
    seeds.insert(run.seed);
    json identity = RunIdentity(run);
    identity.erase("seed");
    EXPECT_EQ(run.seed,
              evaluator::DeriveSeed(42 ^ Fnv1a64(identity.dump()), static_cast<std::uint64_t>(run.iteration)));
  }
  EXPECT_EQ(seeds.size(), runs.size());
  // Same config, same seeds.
  EXPECT_EQ(ExpandMatrix(config).front().seed, runs.front().seed);
}

TEST(ExpandMatrixTest, FixedSeedIsTheBaseSeed) {
  SweepConfig config = testing::TwoByTwo();
  config.seed_policy = SeedPolicy::kFixed;
  for (const RunSpec& run : ExpandMatrix(config)) EXPECT_EQ(run.seed, 42u);
}

TEST(ExpandMatrixTest, IdsStayWhenOtherCellsAreAdded) {
  const std::vector<RunSpec> before = ExpandMatrix(testing::TwoByTwo());
  SweepConfig grown = testing::TwoByTwo();
  grown.sequences.insert(grown.sequences.begin(), testing::Sequence("seq0"));
  grown.iterations = 3;
  std::set<std::string> after;
  for (const RunSpec& run : ExpandMatrix(grown)) after.insert(run.run_id);
  for (const RunSpec& run : before) EXPECT_TRUE(after.contains(run.run_id)) << run.run_id;
}

TEST(ExpandMatrixTest, RefusesAnExplodingProduct) {
  SweepConfig config = testing::TwoByTwo();
  std::vector<nlohmann::json> values;
  for (int i = 0; i < 1000; ++i) values.push_back(i);
  config.algorithms[0].parameters = {{"a", values}, {"b", values}, {"c", values}};
  try {
    ExpandMatrix(config);
    ADD_FAILURE() << "expected an InputError";
  } catch (const evaluator::InputError& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("expands to more than 1000000 runs"));
  }
}

}  // namespace
}  // namespace slamsweep::orchestrator
