#include "orchestrator/adapters/mrpt_ini.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "evaluator/core/input_error.h"
#include "orchestrator/adapters/mrpt_adapters.h"
#include "tests/orchestrator/worker/run_spec_fixture.h"

namespace slamsweep::orchestrator {
namespace {

using evaluator::InputError;

constexpr const char* kTemplate =
    "# comment = not a key\n"
    "[ICP]\n"
    "maxIterations = 80 // iterations\n"
    "thresholdDist=0.75\n"
    "\n"
    "[MappingApplication]\n"
    "rawlog_file=../old.rawlog\n"
    "; maxIterations=1\n"
    "maxIterations=5\n"
    "\n";

TEST(RenderIniTest, ReplacesTheKeyOnlyInItsOwnSection) {
  const std::vector<IniSetting> settings = {{"ICP", "maxIterations", "120"}};
  EXPECT_EQ(RenderIni(kTemplate, settings),
            "# comment = not a key\n"
            "[ICP]\n"
            "maxIterations=120\n"
            "thresholdDist=0.75\n"
            "\n"
            "[MappingApplication]\n"
            "rawlog_file=../old.rawlog\n"
            "; maxIterations=1\n"
            "maxIterations=5\n"
            "\n");
}

TEST(RenderIniTest, MatchesSectionAndKeyIgnoringCaseAsMrptDoes) {
  const std::vector<IniSetting> settings = {{"icp", "THRESHOLDDIST", "0.5"}};
  const std::string out = RenderIni(kTemplate, settings);
  EXPECT_NE(out.find("\nTHRESHOLDDIST=0.5\n"), std::string::npos) << out;
  EXPECT_EQ(out.find("thresholdDist=0.75"), std::string::npos) << out;
}

TEST(RenderIniTest, AddsAnUnknownKeyAtTheEndOfItsSection) {
  const std::vector<IniSetting> settings = {{"ICP", "newKey", "1"}};
  const std::string out = RenderIni(kTemplate, settings);
  EXPECT_NE(out.find("thresholdDist=0.75\nnewKey=1\n\n[MappingApplication]"), std::string::npos) << out;
}

TEST(RenderIniTest, AppendsAMissingSection) {
  const std::vector<IniSetting> settings = {{"Extra", "a", "1"}, {"Extra", "b", "two words"}};
  const std::string out = RenderIni(kTemplate, settings);
  EXPECT_TRUE(out.ends_with("\n[Extra]\na=1\nb=two words\n")) << out;
}

TEST(RenderIniTest, LaterSettingsWinAndCommentsStay) {
  const std::vector<IniSetting> settings = {{"MappingApplication", "maxIterations", "6"},
                                            {"MappingApplication", "maxIterations", "7"}};
  const std::string out = RenderIni(kTemplate, settings);
  EXPECT_NE(out.find("; maxIterations=1\nmaxIterations=7\n"), std::string::npos) << out;
  EXPECT_NE(out.find("maxIterations = 80 // iterations"), std::string::npos) << out;
}

TEST(IniSettingsFromParametersTest, SplitsAtTheFirstDotAndFormatsScalars) {
  const nlohmann::json parameters = {{"ICP.maxIterations", 80},
                                     {"ICP.onlyClosestCorrespondences", true},
                                     {"MappingApplication.insertionLinDistance", 0.25},
                                     {"MappingApplication.verbosity_level", "INFO"}};
  const std::vector<IniSetting> settings = IniSettingsFromParameters(parameters);
  ASSERT_EQ(settings.size(), 4u);
  // nlohmann::json keeps object keys sorted.
  EXPECT_EQ(settings[0], (IniSetting{"ICP", "maxIterations", "80"}));
  EXPECT_EQ(settings[1], (IniSetting{"ICP", "onlyClosestCorrespondences", "true"}));
  EXPECT_EQ(settings[2], (IniSetting{"MappingApplication", "insertionLinDistance", "0.25"}));
  EXPECT_EQ(settings[3], (IniSetting{"MappingApplication", "verbosity_level", "INFO"}));
}

TEST(IniSettingsFromParametersTest, RefusesANameWithoutSectionNamingIt) {
  for (const std::string name : {"maxIterations", ".key", "ICP."}) {
    try {
      IniSettingsFromParameters({{name, 1}});
      ADD_FAILURE() << name << " accepted";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("algorithm.parameters." + name + ": expected a name SECTION.key"),
                std::string::npos)
          << error.what();
    }
  }
}

TEST(IniSettingsFromParametersTest, RefusesValuesThatAreNotOneLineScalars) {
  EXPECT_THROW(IniSettingsFromParameters({{"ICP.a", nlohmann::json::array({1, 2})}}), InputError);
  EXPECT_THROW(IniSettingsFromParameters({{"ICP.a", nullptr}}), InputError);
  EXPECT_THROW(IniSettingsFromParameters({{"ICP.a", "1\n[Other]\nb=2"}}), InputError);
}

TEST(MrptSettingsTest, AdapterControlledKeysWinAndCannotBeParameters) {
  RunSpec spec = testing::SimulatedRun("mrpt-icp-slam");
  spec.algorithm.parameters = {{"ICP.maxIterations", 40}};
  const std::vector<IniSetting> settings = IcpSlamSettings(spec, "x.rawlog");
  const std::string ini =
      RenderIni("[MappingApplication]\nrawlog_file=a\nSAVE_3D_SCENE=1\n[ICP]\nmaxIterations=80\n", settings);
  // The program runs in raw/: its input is beside it, its output is where it runs.
  EXPECT_NE(ini.find("rawlog_file=../input/x.rawlog\n"), std::string::npos) << ini;
  EXPECT_NE(ini.find("SAVE_3D_SCENE=0\n"), std::string::npos) << ini;
  EXPECT_NE(ini.find("logOutput_dir=.\n"), std::string::npos) << ini;
  EXPECT_NE(ini.find("maxIterations=40\n"), std::string::npos) << ini;

  spec.algorithm.parameters = {{"MappingApplication.logOutput_dir", "/tmp/elsewhere"}};
  EXPECT_THROW(IcpSlamSettings(spec, "x.rawlog"), InputError);
}

TEST(MrptSettingsTest, IcpDefaultsMatchAgainstPointsAndInsertDenselyUnlessAParameterSaysOtherwise) {
  RunSpec spec = testing::SimulatedRun("mrpt-icp-slam");
  const std::string template_text =
      "[ICP]\nthresholdDist=0.5\n[MappingApplication]\ninsertionLinDistance=2.0\nmatchAgainstTheGrid=true\n"
      "pointsMap_count=0 // 1\noccupancyGrid_count=1\n";
  const std::string ini = RenderIni(template_text, IcpSlamSettings(spec, "x.rawlog"));
  EXPECT_NE(ini.find("insertionLinDistance=0.5\n"), std::string::npos) << ini;
  EXPECT_NE(ini.find("matchAgainstTheGrid=false\n"), std::string::npos) << ini;
  EXPECT_NE(ini.find("pointsMap_count=1\n"), std::string::npos) << ini;
  EXPECT_NE(ini.find("thresholdDist=0.3\n"), std::string::npos) << ini;
  // The grid stays: it is the map the adapter collects.
  EXPECT_NE(ini.find("occupancyGrid_count=1\n"), std::string::npos) << ini;

  spec.algorithm.parameters = {{"MappingApplication.insertionLinDistance", 2.0},
                               {"MappingApplication.matchAgainstTheGrid", true}};
  const std::string tuned = RenderIni(template_text, IcpSlamSettings(spec, "x.rawlog"));
  EXPECT_NE(tuned.find("insertionLinDistance=2.0\n"), std::string::npos) << tuned;
  EXPECT_NE(tuned.find("matchAgainstTheGrid=true\n"), std::string::npos) << tuned;
  EXPECT_EQ(tuned.find("insertionLinDistance=0.5\n"), std::string::npos) << tuned;
}

TEST(MrptSettingsTest, RbpfLogsAboutOneStageMapPerStageAndDefaultsToFiveParticles) {
  RunSpec spec = testing::SimulatedRun("mrpt-rbpf-slam");
  spec.evaluation.stages = 24;
  const std::string ini =
      RenderIni("[MappingApplication]\nsampleSize=20\nLOG_FREQUENCY=10\n", RbpfSlamSettings(spec, "x.rawlog", 300));
  // ceil(300 / 24) = 13: maps at steps 0, 13, ..., 299 -> 24 of them.
  EXPECT_NE(ini.find("LOG_FREQUENCY=13\n"), std::string::npos) << ini;
  EXPECT_NE(ini.find("sampleSize=5\n"), std::string::npos) << ini;

  spec.algorithm.parameters = {{"MappingApplication.sampleSize", 12}};
  const std::string tuned = RenderIni("[MappingApplication]\nsampleSize=20\n", RbpfSlamSettings(spec, "x.rawlog", 300));
  EXPECT_NE(tuned.find("sampleSize=12\n"), std::string::npos) << tuned;
  EXPECT_EQ(tuned.find("sampleSize=5\n"), std::string::npos) << tuned;
}

}  // namespace
}  // namespace slamsweep::orchestrator
