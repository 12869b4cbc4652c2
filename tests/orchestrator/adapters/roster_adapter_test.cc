#include "orchestrator/adapters/roster_adapter.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/map_server_format.h"
#include "evaluator/formats/trajectory/tum_format.h"
#include "orchestrator/adapters/adapter.h"
#include "orchestrator/adapters/build_stamp.h"
#include "orchestrator/adapters/program_identity.h"
#include "orchestrator/adapters/run_inputs.h"
#include "tests/orchestrator/worker/run_spec_fixture.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

AlgorithmSpec Algorithm(const std::string& adapter) {
  AlgorithmSpec algorithm;
  algorithm.adapter = adapter;
  return algorithm;
}

/// Points the roster at a folder of our own for the test's lifetime: a fake driver and prefix, so the
/// adapter's contract is checked whether or not any upstream is installed.
class RosterEnvironment {
 public:
  explicit RosterEnvironment(const fs::path& root) {
    fs::create_directories(root / "bin");
    fs::create_directories(root / "prefix" / "share" / "slamsweep" / "slam");
    setenv("SLAMSWEEP_SLAM_DRIVER_DIR", (root / "bin").c_str(), 1);
    setenv("SLAMSWEEP_SLAM_PREFIX", (root / "prefix").c_str(), 1);
  }
  ~RosterEnvironment() {
    unsetenv("SLAMSWEEP_SLAM_DRIVER_DIR");
    unsetenv("SLAMSWEEP_SLAM_PREFIX");
  }
};

void WriteExecutable(const fs::path& path) {
  slamsweep::testing::WriteFile(path, "#!/bin/sh\nexit 0\n");
  fs::permissions(path, fs::perms::owner_all);
}

TEST(RosterTest, ListsThePapersFiveThenTheThreeBeyondItWithTheirUpstreams) {
  std::vector<std::string> names;
  for (const RosterAlgorithm& algorithm : Roster()) names.emplace_back(algorithm.name);
  EXPECT_EQ(names, (std::vector<std::string>{"gmapping", "tinyslam", "vinyslam", "hector", "cartographer",
                                             "slam-toolbox", "lama", "lama-pf"}));
  EXPECT_EQ(FindRosterAlgorithm("vinyslam")->upstream, "slam-constructor");
  EXPECT_EQ(FindRosterAlgorithm("lama-pf")->upstream, "lama");
  EXPECT_EQ(FindRosterAlgorithm("icp-slam"), nullptr);
  // Every roster name is an adapter a sweep can use.
  for (const RosterAlgorithm& algorithm : Roster()) EXPECT_NO_THROW(MakeAdapter(algorithm.name)) << algorithm.name;
}

TEST(RosterAdapterTest, RunsTheDriverFromRawWithTheContractsArguments) {
  const slamsweep::testing::TempDir dir;
  const RosterEnvironment environment(dir / "roster");
  WriteExecutable(dir / "roster" / "bin" / "slamsweep-slam-gmapping");
  RunSpec spec = testing::SimulatedRun("gmapping", 20);
  spec.seed = 18446744073709551557ULL;
  spec.evaluation.stages = 6;
  spec.algorithm.parameters = {{"particles", 30}, {"srr", 0.25}, {"generateMap", true}, {"label", "a b"}};
  const RunPaths paths{dir / "run"};
  const RunInputs inputs = PrepareRunInputs(spec);

  const PreparedRun prepared = MakeAdapter("gmapping")->Prepare(spec, inputs.robot, paths);
  const std::vector<std::string> expected = {(dir / "roster" / "bin" / "slamsweep-slam-gmapping").string(),
                                             "--input",
                                             "../input/simulated-floor.log",
                                             "--output-dir",
                                             ".",
                                             "--seed",
                                             "18446744073709551557",
                                             "--stages",
                                             "6",
                                             "generateMap=true",
                                             "label=a b",
                                             "particles=30",
                                             "srr=0.25"};
  EXPECT_EQ(prepared.argv, expected);
  EXPECT_TRUE(fs::is_regular_file(paths.InputDir() / "simulated-floor.log"));
  EXPECT_TRUE(fs::is_directory(paths.RawDir()));
}

TEST(RosterAdapterTest, CollectsTrajectoryMapAndStagesInScanOrder) {
  const slamsweep::testing::TempDir dir;
  RunSpec spec = testing::SimulatedRun("hector", 20);
  spec.evaluation.stages = 2;
  const RunPaths paths{dir.path()};
  fs::create_directories(paths.RawDir() / "stages");
  evaluator::Trajectory trajectory;
  trajectory.Add(1.0, evaluator::Pose::Planar(0, 0, 0));
  trajectory.Add(2.0, evaluator::Pose::Planar(1, 0, 0));
  evaluator::WriteTum(trajectory, paths.RawDir() / "trajectory.tum");
  evaluator::OccupancyGrid small(3, 2, 0.05);
  small.at(0, 0) = 1.0f;
  evaluator::OccupancyGrid big(5, 4, 0.05);
  evaluator::WriteMapServer(big, paths.RawDir() / "map.yaml");
  // Written out of order: the adapter must order them by scan index.
  evaluator::WriteMapServer(big, paths.RawDir() / "stages" / "stage-000019.yaml");
  evaluator::WriteMapServer(small, paths.RawDir() / "stages" / "stage-000009.yaml");
  const RunInputs inputs = PrepareRunInputs(spec);

  const CollectedOutputs outputs = MakeAdapter("hector")->Collect(spec, inputs.robot, paths);
  ASSERT_TRUE(outputs.trajectory.has_value());
  EXPECT_EQ(outputs.trajectory->size(), 2u);
  EXPECT_EQ(outputs.map.width, 5);
  ASSERT_EQ(outputs.stages.size(), 2u);
  EXPECT_EQ(outputs.stages[0].cols, 3);
  EXPECT_EQ(outputs.stages[1].cols, 5);
}

TEST(RosterAdapterTest, AMissingOutputNamesTheFile) {
  const slamsweep::testing::TempDir dir;
  RunSpec spec = testing::SimulatedRun("hector", 20);
  const RunPaths paths{dir.path()};
  fs::create_directories(paths.RawDir());
  const RunInputs inputs = PrepareRunInputs(spec);
  try {
    MakeAdapter("hector")->Collect(spec, inputs.robot, paths);
    FAIL() << "no error";
  } catch (const std::exception& error) {
    EXPECT_THAT(error.what(), HasSubstr("raw/map.yaml"));
  }
}

TEST(RosterAdapterTest, SaysHowToInstallAMissingDriverOrUpstream) {
  const slamsweep::testing::TempDir dir;
  const RosterEnvironment environment(dir / "roster");
  const std::string old_path = std::getenv("PATH") ? std::getenv("PATH") : "";
  setenv("PATH", (dir / "empty").c_str(), 1);
  try {
    ProgramFilesOf(Algorithm("vinyslam"));
    FAIL() << "no error";
  } catch (const evaluator::InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("slamsweep-slam-vinyslam is not built"));
    EXPECT_THAT(error.what(), HasSubstr("scripts/install-slam.sh slam-constructor"));
  }
  setenv("PATH", old_path.c_str(), 1);

  WriteExecutable(dir / "roster" / "bin" / "slamsweep-slam-vinyslam");
  try {
    ProgramFilesOf(Algorithm("vinyslam"));
    FAIL() << "no error";
  } catch (const evaluator::InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("slam-constructor.json missing"));
  }
  slamsweep::testing::WriteFile(dir / "roster" / "prefix" / "share" / "slamsweep" / "slam" / "slam-constructor.json",
                                "{\"commit\": \"d70196c\"}");
  const std::vector<fs::path> files = ProgramFilesOf(Algorithm("vinyslam"));
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0].filename(), "slamsweep-slam-vinyslam");
  EXPECT_EQ(files[1].filename(), "slam-constructor.json");
}

TEST(RosterAdapterTest, CartographersLuaFileIsPartOfItsBuildIdentity) {
  const slamsweep::testing::TempDir dir;
  const RosterEnvironment environment(dir / "roster");
  WriteExecutable(dir / "roster" / "bin" / "slamsweep-slam-cartographer");
  slamsweep::testing::WriteFile(dir / "roster" / "prefix" / "share" / "slamsweep" / "slam" / "cartographer.json",
                                "{\"commit\": \"877157a\"}");
  try {
    ProgramFilesOf(Algorithm("cartographer"));
    FAIL() << "a driver without its Lua options must not be planned";
  } catch (const evaluator::InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("slamsweep-slam-cartographer.lua missing"));
  }
  const fs::path lua = dir / "roster" / "bin" / "slamsweep-slam-cartographer.lua";
  slamsweep::testing::WriteFile(lua, "options = { map_builder = MAP_BUILDER }\n");
  try {
    ProgramFilesOf(Algorithm("cartographer"));
    FAIL() << "a driver without upstream's configuration files must not be planned";
  } catch (const evaluator::InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("configuration_files missing or empty"));
  }
  // The upstream files slamsweep_2d.lua includes (map_builder.lua, trajectory_builder.lua, ...).
  const fs::path upstream =
      dir / "roster" / "prefix" / "cartographer" / "share" / "cartographer" / "configuration_files";
  fs::create_directories(upstream);
  slamsweep::testing::WriteFile(upstream / "trajectory_builder.lua", "TRAJECTORY_BUILDER = {}\n");
  slamsweep::testing::WriteFile(upstream / "map_builder.lua", "MAP_BUILDER = {}\n");
  EXPECT_EQ(RosterUpstreamConfigDir(*FindRosterAlgorithm("cartographer")), upstream);
  const std::vector<fs::path> files = ProgramFilesOf(Algorithm("cartographer"));
  ASSERT_EQ(files.size(), 5u);
  EXPECT_EQ(files[1], lua);
  EXPECT_EQ(files[2], upstream / "map_builder.lua");
  EXPECT_EQ(files[3], upstream / "trajectory_builder.lua");
  // An edited Lua file, ours or upstream's, is another build: its results are never reused or pooled
  // with the old ones.
  std::vector<RunSpec> runs(1);
  runs[0].algorithm = Algorithm("cartographer");
  StampBuildIdentity(runs);
  const std::string before = BuildSignature(runs[0].build);
  slamsweep::testing::WriteFile(lua, "options = { map_builder = MAP_BUILDER, tuned = true }\n");
  StampBuildIdentity(runs);
  const std::string after_ours = BuildSignature(runs[0].build);
  EXPECT_NE(after_ours, before);
  slamsweep::testing::WriteFile(upstream / "map_builder.lua", "MAP_BUILDER = { num_background_threads = 4 }\n");
  StampBuildIdentity(runs);
  EXPECT_NE(BuildSignature(runs[0].build), after_ours);
}

TEST(RosterAdapterTest, TheSharedLibraryBesideAnInstalledDriverIsReadableAndPartOfItsBuildIdentity) {
  const slamsweep::testing::TempDir dir;
  const RosterEnvironment environment(dir / "roster");
  WriteExecutable(dir / "roster" / "bin" / "slamsweep-slam-lama");
  slamsweep::testing::WriteFile(dir / "roster" / "prefix" / "share" / "slamsweep" / "slam" / "lama.json",
                                "{\"commit\": \"fd60e55\"}");
  const RosterAlgorithm& lama = *FindRosterAlgorithm("lama");
  // A build: the library under the roster prefix, where the driver's RUNPATH points; missing, no plan.
  const fs::path built = dir / "roster" / "prefix" / "lama" / "lib" / "libiris_lama.so";
  EXPECT_EQ(RosterSharedLibrary(lama), built);
  try {
    ProgramFilesOf(Algorithm("lama"));
    FAIL() << "a driver without its shared library must not be planned";
  } catch (const evaluator::InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("libiris_lama.so missing"));
    EXPECT_THAT(error.what(), HasSubstr("scripts/install-slam.sh lama"));
  }
  // An installation: the library beside the driver (RUNPATH $ORIGIN), which the sandbox shows by name only.
  const fs::path beside = dir / "roster" / "bin" / "libiris_lama.so";
  slamsweep::testing::WriteFile(beside, "version 1");
  EXPECT_EQ(RosterSharedLibrary(lama), beside);
  const std::vector<fs::path> reads = RosterProgramReads(lama);
  EXPECT_NE(std::find(reads.begin(), reads.end(), beside), reads.end());
  const std::vector<fs::path> files = ProgramFilesOf(Algorithm("lama"));
  EXPECT_NE(std::find(files.begin(), files.end(), beside), files.end());
  // A relinked library is another build.
  std::vector<RunSpec> runs(1);
  runs[0].algorithm = Algorithm("lama");
  StampBuildIdentity(runs);
  const std::string before = BuildSignature(runs[0].build);
  slamsweep::testing::WriteFile(beside, "version 2");
  StampBuildIdentity(runs);
  EXPECT_NE(BuildSignature(runs[0].build), before);
  // The paper's five link their upstreams statically: nothing to show.
  EXPECT_TRUE(RosterSharedLibrary(*FindRosterAlgorithm("hector")).empty());
}

TEST(RosterAdapterTest, TheRandomisedAlgorithmsAreSeeded) {
  // GMapping's particle filter and slam-constructor's Monte-Carlo scan matcher draw random numbers.
  EXPECT_EQ(SeedingOf(Algorithm("gmapping")), Seeding::kSeeded);
  EXPECT_EQ(SeedingOf(Algorithm("tinyslam")), Seeding::kSeeded);
  EXPECT_EQ(SeedingOf(Algorithm("vinyslam")), Seeding::kSeeded);
  EXPECT_EQ(SeedingOf(Algorithm("hector")), Seeding::kDeterministic);
  // LaMa's particle filter draws; Karto and LaMa's Slam2D do not.
  EXPECT_EQ(SeedingOf(Algorithm("lama-pf")), Seeding::kSeeded);
  EXPECT_EQ(SeedingOf(Algorithm("lama")), Seeding::kDeterministic);
  EXPECT_EQ(SeedingOf(Algorithm("slam-toolbox")), Seeding::kDeterministic);
}

}  // namespace
}  // namespace slamsweep::orchestrator
