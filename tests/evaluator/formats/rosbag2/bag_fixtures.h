#pragma once

// What the ROS 2 bag tests share: the raw CARMEN log the independent writers turn into bags, the
// independent tools (foxglove's npm packages, Python's sqlite3 and zstandard) and their output.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "evaluator/sequence/sequence.h"
#include "tests/support/shared_data.h"

namespace slamsweep::testing {

/// A raw CARMEN log that slamsweep writes (FormatCarmenLog) from the first 150 scans of the shared
/// intel log, with its recorded odometry readings, stamps on whole nanoseconds: the input of every
/// independent bag writer.
/// Empty when the shared log is missing (`why` says so).
struct CarmenFixture {
  std::filesystem::path log;
  std::string why;
};
const CarmenFixture& RawCarmenLog();

/// The folder holding node_modules of scripts/install-bag-tools.sh, or why there is none.
struct BagTools {
  std::filesystem::path prefix;
  std::string why;
};
const BagTools& NpmBagTools();

/// Runs `command` with output in `log`; the output when it fails, empty on success.
std::string RunCommand(const std::string& command, const std::filesystem::path& log);

/// `node bag_tool.cjs ARGS` (tests/evaluator/formats/rosbag2/bag_tools); throws with its output when it fails.
std::string RunBagTool(const std::string& arguments);

/// The npm reader's view of an MCAP file: `node bag_tool.cjs dump BAG TOPICS...` parsed.
nlohmann::json NpmDump(const std::filesystem::path& bag, const std::string& topics);

/// Where the writers' bags are written, once per test program.
const std::filesystem::path& FixtureDir();

/// Expects two sequences to hold the same scans (stamps, ranges bit for bit, fans within float rounding,
/// range limits within float rounding, mounts) and odometry (stamps exactly, x and y exactly, yaw within
/// 1e-12 rad), and the same odometry readings.
void ExpectSameRobotData(const evaluator::Sequence& expected, const evaluator::Sequence& actual);

}  // namespace slamsweep::testing

/// Skips (fails under CI=true) when the npm tools or the shared log are missing.
#define REQUIRE_NPM_TOOLS()                                                            \
  if (const std::string why = ::slamsweep::testing::NpmBagTools().why; !why.empty()) { \
    SLAMSWEEP_SKIP_OR_FAIL_IN_CI(why);                                                 \
  }
#define REQUIRE_CARMEN_FIXTURE()                                                        \
  if (const std::string why = ::slamsweep::testing::RawCarmenLog().why; !why.empty()) { \
    SLAMSWEEP_SKIP_OR_FAIL_IN_CI(why);                                                  \
  }
