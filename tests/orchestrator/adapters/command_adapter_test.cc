#include "orchestrator/adapters/command_adapter.h"

#include <gtest/gtest.h>

#include <string>

#include "evaluator/core/input_error.h"
#include "orchestrator/adapters/mrpt_adapters.h"
#include "orchestrator/run/run_failure.h"
#include "orchestrator/adapters/run_inputs.h"
#include "orchestrator/process/process_set.h"
#include "tests/orchestrator/worker/run_spec_fixture.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

using evaluator::InputError;

PlaceholderValues SomeValues() {
  PlaceholderValues values;
  values.input = "/r/input/s.log";
  values.output_dir = "/r/raw";
  values.input_dir = "/r/input";
  values.seed = "42";
  values.seed32 = "7";
  values.iteration = "3";
  values.parameters = {{"x", "a b"}, {"n", 2.5}, {"flag", false}};
  return values;
}

TEST(ExpandPlaceholdersTest, ReplacesEveryPlaceholder) {
  const PlaceholderValues values = SomeValues();
  EXPECT_EQ(ExpandPlaceholders("--in={input}", values, "f"), "--in=/r/input/s.log");
  EXPECT_EQ(ExpandPlaceholders("{output_dir}/map.yaml", values, "f"), "/r/raw/map.yaml");
  EXPECT_EQ(ExpandPlaceholders("{input_dir}:{seed}:{seed32}:{iteration}", values, "f"), "/r/input:42:7:3");
  // The run folder holds the run's record (and, after the program, its truth): no placeholder names it.
  EXPECT_THROW(ExpandPlaceholders("{run_dir}", values, "f"), InputError);
  EXPECT_EQ(ExpandPlaceholders("{param:x}|{param:n}|{param:flag}", values, "f"), "a b|2.5|false");
  EXPECT_EQ(ExpandPlaceholders("{{\"k\": 1}}", values, "f"), "{\"k\": 1}");
  EXPECT_EQ(ExpandPlaceholders("plain", values, "f"), "plain");
}

TEST(ExpandPlaceholdersTest, NamesTheFieldAndWhatIsAccepted) {
  const PlaceholderValues values = SomeValues();
  try {
    ExpandPlaceholders("{outputdir}", values, "algorithm.command.argv[2]");
    FAIL() << "accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("algorithm.command.argv[2]: unknown placeholder {outputdir}"), std::string::npos) << message;
    EXPECT_NE(message.find("{output_dir}"), std::string::npos) << message;
  }
  try {
    ExpandPlaceholders("{param:missing}", values, "argv[1]");
    FAIL() << "accepted";
  } catch (const InputError& error) {
    EXPECT_NE(
        std::string(error.what()).find("{param:missing} names no parameter of the algorithm (declared: flag, n, x)"),
        std::string::npos)
        << error.what();
  }
  EXPECT_THROW(ExpandPlaceholders("{input", values, "f"), InputError);
  EXPECT_THROW(ExpandPlaceholders("a}b", values, "f"), InputError);
}

TEST(CommandAdapterTest, HostileParameterValuesStayOneArgumentEach) {
  const slamsweep::testing::TempDir dir;
  const RunPaths paths{dir.path()};
  RunSpec spec = testing::SimulatedRun("command", 20);
  spec.algorithm.parameters = {{"x", "a b; touch " + (dir / "pwned").string()},
                               {"y", "$(touch " + (dir / "pwned2").string() + ") `id` | cat > out"},
                               {"z", "'quoted\" \\ line\nbreak"}};
  CommandDeclaration declaration;
  declaration.argv = {"/usr/bin/printf", "%s\\n", "{param:x}", "{param:y}", "{param:z}", "{seed}"};
  declaration.trajectory = DeclaredOutput{"out.tum", "tum"};
  spec.algorithm.command = declaration;

  const RunInputs inputs = PrepareRunInputs(spec);
  const PreparedRun prepared = CommandAdapter().Prepare(spec, inputs.robot, paths);
  ASSERT_EQ(prepared.argv.size(), 6u);
  EXPECT_TRUE(std::filesystem::exists(paths.InputDir() / "simulated-floor.log"));

  ProcessSpec process;
  process.argv = prepared.argv;
  process.working_dir = paths.root;
  process.log_path = paths.Log();
  process.timeout_s = 10;
  const ProcessOutcome outcome = RunProcess(process);
  ASSERT_TRUE(outcome.ok()) << outcome.reason;
  // printf's format is used again for each further argument: one line per argument, verbatim.
  EXPECT_EQ(testing::ReadText(paths.Log()), spec.algorithm.parameters["x"].get<std::string>() + "\n" +
                                                spec.algorithm.parameters["y"].get<std::string>() + "\n" +
                                                spec.algorithm.parameters["z"].get<std::string>() + "\n7\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "pwned"));
  EXPECT_FALSE(std::filesystem::exists(dir / "pwned2"));
}

TEST(CommandAdapterTest, RefusesBadDeclarationsBeforeWritingAnything) {
  const slamsweep::testing::TempDir dir;
  const RunPaths paths{dir.path() / "run"};
  RunSpec spec = testing::SimulatedRun("command", 20);
  const RunInputs inputs = PrepareRunInputs(spec);
  EXPECT_THROW(CommandAdapter().Prepare(spec, inputs.robot, paths), InputError);  // no declaration

  CommandDeclaration declaration;
  declaration.argv = {"prog", "{output_dir}"};
  spec.algorithm.command = declaration;
  EXPECT_THROW(CommandAdapter().Prepare(spec, inputs.robot, paths), InputError);  // no outputs declared

  declaration.trajectory = DeclaredOutput{"../../escape.tum", "tum"};
  spec.algorithm.command = declaration;
  EXPECT_THROW(CommandAdapter().Prepare(spec, inputs.robot, paths), InputError);  // leaves raw/

  declaration.trajectory = DeclaredOutput{"t.tum", "yaml"};
  spec.algorithm.command = declaration;
  EXPECT_THROW(CommandAdapter().Prepare(spec, inputs.robot, paths), InputError);  // unknown format

  declaration.trajectory = DeclaredOutput{"t.tum", "tum"};
  declaration.input_format = "bag";
  spec.algorithm.command = declaration;
  EXPECT_THROW(CommandAdapter().Prepare(spec, inputs.robot, paths), InputError);  // unknown input format
  EXPECT_FALSE(std::filesystem::exists(paths.InputDir()));
}

TEST(MrptAdapterTest, MissingOutputsAndTemplatesAreNamed) {
  const slamsweep::testing::TempDir dir;
  const RunPaths paths{dir.path()};
  const RunSpec spec = testing::SimulatedRun("mrpt-icp-slam", 20);
  const RunInputs inputs = PrepareRunInputs(spec);
  try {
    IcpSlamAdapter().Collect(spec, inputs.robot, paths);
    FAIL() << "collected nothing";
  } catch (const RunFailure& failure) {
    EXPECT_EQ(failure.kind(), FailureKind::kMissingOutput);
    EXPECT_STREQ(failure.what(), "no map: raw/_finalmaps_.txt_mrpt__maps__COccupancyGridMap2D_00.png missing");
  }
  try {
    RbpfSlamAdapter(dir / "no-template.ini").Prepare(spec, inputs.robot, paths);
    FAIL() << "prepared without a template";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find((dir / "no-template.ini").string() + " missing"), std::string::npos)
        << error.what();
  }
}

TEST(MakeAdapterTest, KnowsEveryAdapterAndListsThemOtherwise) {
  for (const char* name : {"mrpt-icp-slam", "mrpt-rbpf-slam", "command", "odometry", "gmapping", "tinyslam", "vinyslam",
                           "hector", "cartographer", "slam-toolbox", "lama", "lama-pf"}) {
    EXPECT_NE(MakeAdapter(name), nullptr) << name;
  }
  try {
    MakeAdapter("gfs_nogui");
    FAIL() << "accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what())
                  .find("algorithm.adapter: expected mrpt-icp-slam, mrpt-rbpf-slam, command, "
                        "odometry, gmapping, tinyslam, vinyslam, hector, cartographer, slam-toolbox, lama or "
                        "lama-pf, got 'gfs_nogui'"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace slamsweep::orchestrator
