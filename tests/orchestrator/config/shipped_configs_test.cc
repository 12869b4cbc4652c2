// Every sweep file shipped in configs/ must load: a typo in a shipped config is a bug found here,
// not at 3 a.m. in the nightly sweep.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "evaluator/core/input_error.h"
#include "orchestrator/config/sweep_config.h"
#include "orchestrator/matrix/expand_matrix.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

const std::filesystem::path kConfigs = std::filesystem::path(SLAMSWEEP_SOURCE_DIR) / "configs";

std::string Contents(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// configs/*.yaml that are sweeps (a top-level `algorithms:`), not the dataset catalog.
std::vector<std::filesystem::path> SweepFiles() {
  std::vector<std::filesystem::path> files;
  for (const auto& item : std::filesystem::directory_iterator(kConfigs)) {
    if (item.path().extension() != ".yaml") continue;
    const std::string text = Contents(item.path());
    if (text.starts_with("algorithms:") || text.find("\nalgorithms:") != std::string::npos) {
      files.push_back(item.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

SweepConfigContext RepositoryContext() {
  return {kConfigs / "datasets.yaml", {{"SHARED", testing::SharedRoot().string()}}, {}};
}

TEST(ShippedConfigsTest, TheQuickstartAndNightlySweepsAreShipped) {
  const std::vector<std::filesystem::path> files = SweepFiles();
  EXPECT_NE(std::find(files.begin(), files.end(), kConfigs / "quickstart.yaml"), files.end());
  EXPECT_NE(std::find(files.begin(), files.end(), kConfigs / "radish.yaml"), files.end());
}

TEST(ShippedConfigsTest, EverySweepFileValidatesAndExpands) {
  const std::vector<std::filesystem::path> files = SweepFiles();
  ASSERT_FALSE(files.empty());
  for (const std::filesystem::path& file : files) {
    SCOPED_TRACE(file.string());
    const std::string text = Contents(file);
    if (text.find("${SHARED}") != std::string::npos || file.filename() == "radish.yaml") {
      // Sweeps over the logs of ../shared need them (skipped, or failed under CI, when absent).
      SLAMSWEEP_REQUIRE_SHARED(shared_intel, "datasets/intel/intel-corrected.log.gz");
    }
    try {
      const SweepConfig config = ReadSweepConfig(file, RepositoryContext());
      EXPECT_EQ(config.name, file.stem().string());
      const std::vector<RunSpec> runs = ExpandMatrix(config);
      EXPECT_FALSE(runs.empty());
    } catch (const evaluator::InputError& error) {
      const std::string message = error.what();
      if (message.find("/usr/share/mrpt") != std::string::npos) {
        SLAMSWEEP_SKIP_OR_FAIL_IN_CI("MRPT sample data not installed (apt install mrpt-common): " << message);
      }
      ADD_FAILURE() << message;
    }
  }
}

TEST(ShippedConfigsTest, QuickstartIsTheDocumentedSmallMatrix) {
  if (!std::filesystem::exists("/usr/share/mrpt/datasets")) SLAMSWEEP_SKIP_OR_FAIL_IN_CI("mrpt-common not installed");
  const SweepConfig config = ReadSweepConfig(kConfigs / "quickstart.yaml", RepositoryContext());
  // 3 algorithms x 2 sequences x 1 noise setting x 3 iterations.
  EXPECT_EQ(ExpandMatrix(config).size(), 18u);
  for (const AlgorithmConfig& algorithm : config.algorithms) EXPECT_LE(algorithm.timeout_s, 120.0);
  ASSERT_EQ(config.noise.size(), 1u);
  EXPECT_TRUE(config.noise[0].odometry.has_value()) << "iterations must differ";
}

// The parameter-sweep example (configs/examples/, beside the sweeps above): one algorithm varying one
// parameter (the Parameters page's curves), one varying two (its heatmaps), all rows comparable.
TEST(ShippedConfigsTest, TheParameterSweepExampleVariesOneAndTwoParameters) {
  SLAMSWEEP_REQUIRE_SHARED(shared_intel, "datasets/intel/intel-corrected.log.gz");
  const SweepConfig config = ReadSweepConfig(kConfigs / "examples/parameter-sweep.yaml", RepositoryContext());
  std::map<std::string, std::size_t> varying;
  for (const AlgorithmConfig& algorithm : config.algorithms) {
    for (const ParameterAxis& axis : algorithm.parameters) varying[algorithm.name] += axis.values.size() > 1 ? 1 : 0;
  }
  EXPECT_EQ(varying["icp-slam"], 1u);
  EXPECT_EQ(varying["icp-slam-grid"], 2u);
  // (4 + 2 x 2 + 1 odometry) groups x 3 iterations, on one sequence and one noise setting.
  EXPECT_EQ(ExpandMatrix(config).size(), 27u);
  ASSERT_EQ(config.noise.size(), 1u);
  EXPECT_TRUE(config.noise[0].odometry.has_value())
      << "intel is corrected: without noise its odometry is the reference";
  EXPECT_FALSE(config.evaluation.rpe_segments_m) << "segment lengths from the reference path";
}

}  // namespace
}  // namespace slamsweep::orchestrator
