// `slamsweep eval map --json`, the real programs (the core, then slamsweep-maps), against the full JSON
// that an earlier build printed for the same maps (tests/cli/eval_map_golden, recorded before the map
// metrics were made faster): a speed-up must leave every printed value byte for byte as it was.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>

#include "tests/support/shared_data.h"

namespace slamsweep {
namespace {

const std::filesystem::path kGoldenDir = std::filesystem::path(SLAMSWEEP_SOURCE_DIR) / "tests/cli/eval_map_golden";

struct Output {
  int exit_code = -1;
  std::string out;
};

Output RunShell(const std::string& command) {
  Output result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string ReadGolden(const std::string& name) {
  std::ifstream in(kGoldenDir / name, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// `slamsweep eval map MAP ARGS --json` prints exactly the golden file `golden`.
void ExpectGolden(const std::filesystem::path& map, const std::string& args, const std::string& golden) {
  const std::string expected = ReadGolden(golden);
  ASSERT_FALSE(expected.empty()) << "missing " << (kGoldenDir / golden);
  const Output run = RunShell(std::string(SLAMSWEEP_BINARY) + " eval map '" + map.string() + "' " + args + " --json");
  ASSERT_EQ(run.exit_code, 0) << map;
  EXPECT_EQ(run.out, expected) << map << " " << args << " differs from " << golden;
}

TEST(EvalMapGoldenTest, ReferenceMapsPrintTheRecordedJson) {
  SLAMSWEEP_REQUIRE_SHARED(rbpf, "reference/maps/telecom_rbpf.yaml");
  SLAMSWEEP_REQUIRE_SHARED(icp, "reference/maps/telecom_icp.yaml");
  SLAMSWEEP_REQUIRE_SHARED(fastslam, "reference/maps/fastslam_thirdparty.pgm");
  for (const auto& [map, args, stem] :
       {std::tuple{rbpf, std::string(), std::string("telecom_rbpf")},
        std::tuple{icp, std::string(), std::string("telecom_icp")},
        std::tuple{fastslam, std::string("--unknown-value 205"), std::string("fastslam_thirdparty")}}) {
    ExpectGolden(map, args, stem + ".json");
    ExpectGolden(map, args + " --no-crop", stem + ".no-crop.json");
  }
}

TEST(EvalMapGoldenTest, TheBenchmarkFloorPlanPrintsTheRecordedJson) {
  testing::TempDir dir;
  const std::string generator = std::string(SLAMSWEEP_SOURCE_DIR) + "/bench/cli/make_inputs.py";
  const Output made =
      RunShell("/usr/bin/python3 '" + generator + "' '" + dir.path().string() + "' --files map-2000.yaml 2>&1");
  if (made.exit_code != 0)
    SLAMSWEEP_SKIP_OR_FAIL_IN_CI("bench/cli/make_inputs.py (/usr/bin/python3) failed: " << made.out);
  ExpectGolden(dir / "map-2000.yaml", "", "map-2000.json");
  ExpectGolden(dir / "map-2000.yaml", "--no-crop", "map-2000.no-crop.json");
}

}  // namespace
}  // namespace slamsweep
