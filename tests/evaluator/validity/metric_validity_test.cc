// The metric validity study on hand-made runs whose correlations are known by construction.
#include "evaluator/validity/metric_validity.h"

#include "evaluator/core/input_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace slamsweep::evaluator {
namespace {

ValidityRun MakeRun(const std::string& sequence, const std::string& noise, int i, double ate, double corners) {
  ValidityRun run;
  run.run_id = sequence + "-" + noise + "-i" + std::to_string(i);
  run.sequence = sequence;
  run.noise = noise;
  run.algorithm = "icp-slam";
  run.ok = true;
  run.values = {{"ape_trans.rmse", ate}, {"corners.value", corners}, {"enclosed_areas.value", 3.0}};
  return run;
}

const ValidityCorrelation& Get(const ValidityStudy& study, const std::string& candidate, const std::string& sequence,
                               ValidityPooling pooling, const std::string& target = "ape_trans.rmse") {
  const ValidityCorrelation* found = study.Find(candidate, target, sequence, pooling);
  if (found == nullptr) throw std::runtime_error("no correlation " + candidate + " " + sequence);
  return *found;
}

TEST(MetricValidityTest, BelowEightRunsThereIsNoNumber) {
  std::vector<ValidityRun> runs;
  for (int i = 0; i < 7; ++i) runs.push_back(MakeRun("intel", "n1", i, 0.1 * (i + 1), 10.0 + i));
  const ValidityStudy seven = ComputeValidityStudy(runs);
  const ValidityCorrelation& few = Get(seven, "corners.value", "intel", ValidityPooling::kAcrossNoise);
  EXPECT_EQ(few.verdict, ValidityVerdict::kTooFewRuns);
  EXPECT_EQ(few.runs, 7u);
  EXPECT_FALSE(few.rho);
  EXPECT_FALSE(few.interval);

  runs.push_back(MakeRun("intel", "n1", 7, 0.8, 17.0));
  const ValidityStudy eight = ComputeValidityStudy(runs);
  const ValidityCorrelation& enough = Get(eight, "corners.value", "intel", ValidityPooling::kAcrossNoise);
  EXPECT_EQ(enough.runs, 8u);
  ASSERT_TRUE(enough.rho);
  EXPECT_DOUBLE_EQ(*enough.rho, 1.0);
  EXPECT_EQ(enough.verdict, ValidityVerdict::kTracksError);
  ASSERT_TRUE(enough.interval);
  EXPECT_DOUBLE_EQ(enough.interval->low, 1.0);
  // A constant metric has no rank order.
  EXPECT_EQ(Get(eight, "enclosed_areas.value", "intel", ValidityPooling::kAcrossNoise).verdict,
            ValidityVerdict::kNoVariation);
  // One sequence: no "all sequences" scope; no relations or map values: no such target.
  EXPECT_EQ(eight.Find("corners.value", "ape_trans.rmse", "", ValidityPooling::kAcrossNoise), nullptr);
  EXPECT_EQ(eight.Find("corners.value", "relations_trans.mean", "intel", ValidityPooling::kAcrossNoise), nullptr);
  // Resources are candidates too, absent here: no pairs, too few runs.
  EXPECT_EQ(Get(eight, "wall_s", "intel", ValidityPooling::kAcrossNoise).runs, 0u);
}

TEST(MetricValidityTest, AMetricFallingWithTheErrorIsOpposite) {
  std::vector<ValidityRun> runs;
  for (int i = 0; i < 12; ++i) runs.push_back(MakeRun("floor", "n1", i, 0.1 * (i + 1), 100.0 - 3 * i));
  const ValidityStudy study = ComputeValidityStudy(runs);  // kept: Get returns a reference into it
  const ValidityCorrelation& c = Get(study, "corners.value", "floor", ValidityPooling::kAcrossNoise);
  EXPECT_DOUBLE_EQ(*c.rho, -1.0);
  EXPECT_EQ(c.verdict, ValidityVerdict::kOpposite);
}

TEST(MetricValidityTest, FailedAndOdometryIsReferenceRunsAreLeftOut) {
  std::vector<ValidityRun> runs;
  for (int i = 0; i < 8; ++i) runs.push_back(MakeRun("intel", "n1", i, 0.1 * (i + 1), 10.0 + i));
  ValidityRun failed = MakeRun("intel", "n1", 8, 0.05, 99.0);
  failed.ok = false;
  ValidityRun upper_bound = MakeRun("intel", "clean", 0, 0.01, 99.0);
  upper_bound.odometry_is_reference = true;
  runs.push_back(failed);
  runs.push_back(upper_bound);
  const ValidityStudy study = ComputeValidityStudy(runs);
  EXPECT_EQ(study.runs_used, 8u);
  EXPECT_EQ(study.runs_odometry_is_reference, 1u);
  EXPECT_DOUBLE_EQ(*Get(study, "corners.value", "intel", ValidityPooling::kAcrossNoise).rho, 1.0);
  EXPECT_EQ(ValidityPoints(runs, "corners.value", "ape_trans.rmse", "intel").size(), 8u);
}

TEST(MetricValidityTest, SequencesAreNeverRankedTogether) {
  // On each sequence the corners rise with the error, but the floor has ten times more corners
  // at a tenth of the error: ranking both sequences together would say "opposite".
  std::vector<ValidityRun> runs;
  for (int i = 0; i < 8; ++i) {
    runs.push_back(MakeRun("intel", "n1", i, 1.0 + i, 10.0 + i));
    runs.push_back(MakeRun("floor", "n1", i, 0.1 + 0.01 * i, 100.0 + i));
  }
  const ValidityStudy study = ComputeValidityStudy(runs);
  const ValidityCorrelation& all = Get(study, "corners.value", "", ValidityPooling::kAcrossNoise);
  EXPECT_EQ(all.runs, 16u);
  EXPECT_EQ(all.strata, 2u);
  EXPECT_DOUBLE_EQ(*all.rho, 1.0);
  EXPECT_EQ(study.sequences, (std::vector<std::string>{"floor", "intel"}));
}

TEST(MetricValidityTest, ATargetIsStudiedOnlyWhereItExists) {
  // Relations exist on intel alone: no floor column and no "all sequences" column for them.
  std::vector<ValidityRun> runs;
  for (int i = 0; i < 8; ++i) {
    ValidityRun intel = MakeRun("intel", "n1", i, 1.0 + i, 10.0 + i);
    intel.values["relations_trans.mean"] = 0.5 + i;
    runs.push_back(intel);
    runs.push_back(MakeRun("floor", "n1", i, 0.1 + 0.01 * i, 100.0 + i));
  }
  const ValidityStudy study = ComputeValidityStudy(runs);
  const std::string relations = "relations_trans.mean";
  EXPECT_NE(study.Find("corners.value", relations, "intel", ValidityPooling::kAcrossNoise), nullptr);
  EXPECT_EQ(study.Find("corners.value", relations, "floor", ValidityPooling::kAcrossNoise), nullptr);
  EXPECT_EQ(study.Find("corners.value", relations, "", ValidityPooling::kAcrossNoise), nullptr);
  EXPECT_NE(study.Find("corners.value", "ape_trans.rmse", "", ValidityPooling::kAcrossNoise), nullptr);
}

TEST(MetricValidityTest, WithinNoiseRanksOnlyRunsOfOneNoiseSetting) {
  // The noise level drives both the error and the corners up (across noise: tracks), but within
  // each noise level the run with more corners has the smaller error (within noise: opposite).
  std::vector<ValidityRun> runs;
  for (int level = 0; level < 4; ++level) {
    const std::string noise(1, static_cast<char>('0' + level));
    for (int i = 0; i < 4; ++i) {
      runs.push_back(MakeRun("intel", noise, i, 10.0 * level + (3 - i), 100.0 * level + i));
    }
  }
  const ValidityStudy study = ComputeValidityStudy(runs);
  const ValidityCorrelation& across = Get(study, "corners.value", "intel", ValidityPooling::kAcrossNoise);
  const ValidityCorrelation& within = Get(study, "corners.value", "intel", ValidityPooling::kWithinNoise);
  EXPECT_GT(*across.rho, 0.8);
  EXPECT_EQ(across.verdict, ValidityVerdict::kTracksError);
  EXPECT_EQ(within.strata, 4u);
  EXPECT_DOUBLE_EQ(*within.rho, -1.0);
  EXPECT_EQ(within.verdict, ValidityVerdict::kOpposite);
}

TEST(MetricValidityTest, TheOrderOfRunsDoesNotMatter) {
  std::vector<ValidityRun> runs;
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int i = 0; i < 30; ++i) {
    const double ate = uniform(random);
    const std::string noise = std::string("n") + static_cast<char>('0' + i % 3);
    runs.push_back(MakeRun(i % 2 ? "intel" : "floor", noise, i, ate, ate + uniform(random)));
  }
  const nlohmann::json first = ToJson(ComputeValidityStudy(runs));
  std::shuffle(runs.begin(), runs.end(), random);
  EXPECT_EQ(ToJson(ComputeValidityStudy(runs)), first);
  EXPECT_EQ(first["method"]["resamples"], 2000);
  EXPECT_EQ(first["method"]["min_runs"], 8);
  EXPECT_FALSE(first["correlations"].empty());
  for (const nlohmann::json& c : first["correlations"]) {
    if (c["spearman_rho"].is_null() || c["ci_low"].is_null()) continue;
    EXPECT_LE(c["ci_low"].get<double>(), c["ci_high"].get<double>());
  }
}

TEST(MetricValidityTest, AStudyReadBackFromJsonHasTheSameVerdicts) {
  std::vector<ValidityRun> runs;
  for (int i = 0; i < 12; ++i) runs.push_back(MakeRun(i % 2 ? "intel" : "floor", "n1", i, 0.1 * (i + 1), 10.0 + i));
  const ValidityStudy study = ComputeValidityStudy(runs);
  const ValidityStudy back = ValidityStudyFromJson(ToJson(study));
  EXPECT_EQ(back.sequences, study.sequences);
  ASSERT_EQ(back.correlations.size(), study.correlations.size());
  EXPECT_EQ(ToJson(back), ToJson(study));
  const ValidityCorrelation& corners = Get(back, "corners.value", "", ValidityPooling::kWithinNoise);
  EXPECT_EQ(corners.verdict, ValidityVerdict::kTracksError);
  EXPECT_EQ(corners.runs, 12u);

  nlohmann::json broken = ToJson(study);
  broken["correlations"][0]["verdict"] = "splendid";
  EXPECT_THROW(ValidityStudyFromJson(broken), InputError);
  broken.erase("sequences");
  EXPECT_THROW(ValidityStudyFromJson(broken), InputError);
}

TEST(MetricValidityTest, DecidedVerdictsAreRedrawnAtTheBonferroniLevel) {
  // 12 sequences of 10 runs whose corners follow the error only loosely (noise a third of their range), and one
  // sequence where they follow it exactly: many intervals, some excluding 0 at 95 % by chance.
  std::mt19937 engine(5);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<ValidityRun> runs;
  for (int s = 0; s < 12; ++s) {
    for (int i = 0; i < 10; ++i) {
      const double ate = 0.1 * (i + 1);
      runs.push_back(MakeRun("seq" + std::to_string(s), "n1", i, ate, 10.0 * ate + 3.0 * noise(engine)));
    }
  }
  for (int i = 0; i < 10; ++i) runs.push_back(MakeRun("exact", "n1", i, 0.1 * (i + 1), 10.0 + i));
  const ValidityStudy study = ComputeValidityStudy(runs);
  std::size_t intervals = 0;
  for (const ValidityCorrelation& c : study.correlations) intervals += c.interval ? 1 : 0;
  EXPECT_EQ(study.family_size, intervals);
  EXPECT_DOUBLE_EQ(study.family_confidence, 1.0 - 0.05 / static_cast<double>(intervals));
  std::size_t decided = 0, survived = 0;
  for (const ValidityCorrelation& c : study.correlations) {
    const bool is_decided = c.verdict == ValidityVerdict::kTracksError || c.verdict == ValidityVerdict::kOpposite;
    EXPECT_EQ(c.family_interval.has_value(), is_decided) << c.candidate << " " << c.sequence;
    if (!is_decided) continue;
    ++decided;
    // Wider percentiles of the same resamples hold the 95 % interval.
    EXPECT_LE(c.family_interval->low, c.interval->low);
    EXPECT_GE(c.family_interval->high, c.interval->high);
    EXPECT_EQ(c.survives_family, c.verdict == ValidityVerdict::kTracksError ? c.family_interval->low > 0.0
                                                                            : c.family_interval->high < 0.0);
    survived += c.survives_family ? 1 : 0;
    if (!c.sequence.empty() && c.pooling == ValidityPooling::kAcrossNoise) {
      // One sequence across noise is one stratum: the family interval is the bootstrap drawn afresh at the
      // family's confidence.
      PairedStratum stratum;
      for (const ValidityPoint& point : ValidityPoints(runs, c.candidate, c.target, c.sequence)) {
        stratum.x.push_back(point.x);
        stratum.y.push_back(point.y);
      }
      BootstrapOptions family;
      family.confidence = study.family_confidence;
      const std::optional<BootstrapInterval> redrawn = BootstrapPooledRankCorrelation({stratum}, family);
      ASSERT_TRUE(redrawn.has_value());
      EXPECT_EQ(c.family_interval->low, redrawn->low) << c.candidate << " " << c.sequence;
      EXPECT_EQ(c.family_interval->high, redrawn->high) << c.candidate << " " << c.sequence;
      EXPECT_EQ(c.family_interval->defined, redrawn->defined);
    }
  }
  EXPECT_GT(decided, survived);  // some decided verdicts do not survive the correction
  const ValidityCorrelation& exact = Get(study, "corners.value", "exact", ValidityPooling::kAcrossNoise);
  EXPECT_TRUE(exact.survives_family);  // rho = 1 in every resample
  EXPECT_EQ(ToJson(ValidityStudyFromJson(ToJson(study))), ToJson(study));
}

}  // namespace
}  // namespace slamsweep::evaluator
