// summary.json's "validity" and validity.csv: the same table, written only for sweeps with
// reference data. The correlations themselves are tested in tests/evaluator/validity.
#include "orchestrator/store/validity_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>

#include "orchestrator/store/result_files.h"
#include "tests/orchestrator/store/store_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

using nlohmann::json;

std::string ReadWholeFile(const std::filesystem::path& file) {
  std::ifstream in(file);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Ten runs on intel whose corner count rises with the ATE (0.1 m per iteration).
std::vector<RunRecord> Runs(bool with_ate) {
  std::vector<RunRecord> runs;
  for (int i = 0; i < 10; ++i) {
    const std::string id = "icp-slam-intel-clean-i" + std::to_string(i);
    RunRecord run;
    run.run_id = id;
    run.status = RunStatus::kOk;
    run.algorithm = "icp-slam";
    run.sequence = "intel";
    run.noise = "clean";
    run.run_spec = testing::MakeSpec(id, "icp-slam", "intel", i);
    run.result = testing::MakeOkResult(id, 3.0 + i, 0.1 * (i + 1));
    run.result["command"] = {"icp-slam", "input/icp-slam.ini"};
    ReadResultFields(run.result, run);
    if (with_ate) run.metrics.push_back({"ape_trans", "rmse", 0.1 * (i + 1), "m"});
    run.metrics.push_back({"corners", "value", 10.0 + i, "count"});
    runs.push_back(run);
  }
  return runs;
}

TEST(ValidityTableTest, SummaryJsonAndValidityCsvCarryTheSameTable) {
  slamsweep::testing::TempDir dir;
  const std::vector<RunRecord> runs = Runs(true);
  WriteResultFiles(runs, dir.path());
  const json validity = json::parse(ReadWholeFile(dir / "summary.json")).at("validity");
  EXPECT_EQ(validity.at("sequences"), json::array({"intel"}));
  EXPECT_EQ(validity.at("method").at("resamples"), 2000);

  const json* corners = nullptr;
  for (const json& c : validity.at("correlations")) {
    if (c["candidate"] == "corners.value" && c["target"] == "ape_trans.rmse" && c["pooling"] == "across_noise") {
      corners = &c;
    }
  }
  ASSERT_NE(corners, nullptr);
  EXPECT_EQ(corners->at("sequence"), "intel");
  EXPECT_EQ(corners->at("runs"), 10);
  EXPECT_EQ(corners->at("spearman_rho"), 1.0);
  EXPECT_EQ(corners->at("verdict"), "tracks error");

  // validity.csv: a header and one line per correlation of summary.json, field for field.
  std::istringstream csv(ReadWholeFile(dir / "validity.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line,
            "candidate,target,sequence,pooling,runs,strata,spearman_rho,ci_low,ci_high,resamples_defined,verdict");
  std::size_t rows = 0;
  for (const json& c : validity.at("correlations")) {
    ASSERT_TRUE(std::getline(csv, line));
    std::ostringstream expected;
    expected << c["candidate"].get<std::string>() << "," << c["target"].get<std::string>() << ","
             << (c["sequence"].is_null() ? "" : c["sequence"].get<std::string>()) << ","
             << c["pooling"].get<std::string>() << "," << c["runs"].get<int>() << "," << c["strata"].get<int>() << ",";
    EXPECT_TRUE(line.starts_with(expected.str())) << line << " vs " << expected.str();
    EXPECT_TRUE(line.ends_with("," + c["verdict"].get<std::string>())) << line;
    if (!c["spearman_rho"].is_null()) {
      std::istringstream fields(line.substr(expected.str().size()));
      double rho = 0, low = 0, high = 0;
      char comma = 0;
      fields >> rho >> comma >> low >> comma >> high;
      EXPECT_DOUBLE_EQ(rho, c["spearman_rho"].get<double>()) << line;
      if (!c["ci_low"].is_null()) {
        EXPECT_DOUBLE_EQ(low, c["ci_low"].get<double>()) << line;
        EXPECT_DOUBLE_EQ(high, c["ci_high"].get<double>()) << line;
      }
    }
    ++rows;
  }
  EXPECT_FALSE(std::getline(csv, line)) << "extra line: " << line;
  EXPECT_GT(rows, 10u);
}

TEST(ValidityTableTest, ResourcesCountOnlyForRunsThatRanAProgram) {
  std::vector<RunRecord> runs = Runs(true);
  const evaluator::ValidityRun with_program = ToValidityRun(runs[2]);
  EXPECT_EQ(with_program.values.at("wall_s"), 5.0);
  EXPECT_EQ(with_program.values.at("peak_rss_kb"), 81234.0);
  EXPECT_EQ(with_program.values.at("corners.value"), 12.0);
  runs[2].result["command"] = json::array();  // the odometry baseline
  ReadResultFields(runs[2].result, runs[2]);
  EXPECT_EQ(ToValidityRun(runs[2]).values.count("wall_s"), 0u);
}

TEST(ValidityTableTest, WithoutReferenceDataThereIsNoTable) {
  slamsweep::testing::TempDir dir;
  slamsweep::testing::WriteFile(dir / "validity.csv", "stale\n");
  const std::vector<RunRecord> runs = Runs(false);
  WriteResultFiles(runs, dir.path());
  EXPECT_FALSE(json::parse(ReadWholeFile(dir / "summary.json")).contains("validity"));
  EXPECT_FALSE(std::filesystem::exists(dir / "validity.csv"));
}

TEST(ValidityTableTest, SummaryJsonKeepsTheDigestOfTheStudysInputs) {
  slamsweep::testing::TempDir dir;
  const std::vector<RunRecord> runs = Runs(true);
  WriteResultFiles(runs, dir.path());
  const json validity = json::parse(ReadWholeFile(dir / "summary.json")).at("validity");
  const std::vector<evaluator::ValidityRun> read = ToValidityRuns(runs);
  EXPECT_EQ(validity.at("inputs_sha256"), ValidityInputsDigest(read));
  EXPECT_EQ(validity.at("inputs_sha256").get<std::string>().size(), 64u);

  // The same runs in another order: the same digest, and the stored study is the one computed.
  std::vector<evaluator::ValidityRun> reversed(read.rbegin(), read.rend());
  EXPECT_EQ(ValidityInputsDigest(reversed), ValidityInputsDigest(read));
  const std::optional<evaluator::ValidityStudy> stored = StoredValidityStudyFor(validity, reversed);
  ASSERT_TRUE(stored.has_value());
  EXPECT_EQ(evaluator::ToJson(*stored), evaluator::ToJson(ValidityStudyOf(runs).study));

  // Any value of any run, a run less, or a run left out by its status: another digest, no stored study.
  std::vector<evaluator::ValidityRun> changed = read;
  changed[4].values.at("corners.value") = std::nextafter(changed[4].values.at("corners.value"), 100.0);
  EXPECT_NE(ValidityInputsDigest(changed), ValidityInputsDigest(read));
  EXPECT_FALSE(StoredValidityStudyFor(validity, changed).has_value());
  std::vector<evaluator::ValidityRun> fewer(read.begin(), read.end() - 1);
  EXPECT_FALSE(StoredValidityStudyFor(validity, fewer).has_value());
  std::vector<evaluator::ValidityRun> failed = read;
  failed[0].ok = false;
  EXPECT_FALSE(StoredValidityStudyFor(validity, failed).has_value());
  // A study without a digest (an older slamsweep wrote it) is never taken.
  json without = validity;
  without.erase("inputs_sha256");
  EXPECT_FALSE(StoredValidityStudyFor(without, read).has_value());
}

}  // namespace
}  // namespace slamsweep::orchestrator
