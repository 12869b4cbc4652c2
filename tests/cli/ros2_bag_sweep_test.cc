// A sweep over ROS 2 bags written from a CARMEN log gives the scores of the sweep over the log itself: the
// same scans and odometry reach every program (their input files are the same, byte for byte, but for the
// sequence's name) and every metric agrees to the last digit. The real binary runs the sweep.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/evaluator/formats/rosbag2/bag_fixtures.h"
#include "tests/support/shared_data.h"

namespace slamsweep {
namespace {

std::string ReadAll(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

int RunSlamsweep(const std::string& arguments, const std::filesystem::path& log) {
  return std::system((std::string(SLAMSWEEP_BINARY) + " " + arguments + " > '" + log.string() + "' 2>&1").c_str());
}

/// The program's input files of a run (its input folder), by extension: the sequence's name, which they
/// hold in a CARMEN log's first line and in a rawlog's name in the ini, is taken out. "(no input)" for a
/// program that reads none (the odometry adapter).
std::map<std::string, std::string> ProgramInputs(const std::filesystem::path& run_dir, const std::string& sequence) {
  std::map<std::string, std::string> inputs;
  if (!std::filesystem::exists(run_dir / "input")) return {{"", "(no input)"}};
  for (const auto& entry : std::filesystem::recursive_directory_iterator(run_dir / "input")) {
    if (!entry.is_regular_file()) continue;
    std::string text = ReadAll(entry.path());
    if (text.starts_with("#")) text = text.substr(text.find('\n') + 1);
    for (std::size_t at = text.find(sequence + "."); at != std::string::npos; at = text.find(sequence + ".", at)) {
      text.replace(at, sequence.size(), "SEQUENCE");
    }
    inputs[entry.path().extension().string()] = text;
  }
  return inputs;
}

/// Where two inputs first differ, "" when they are the same (inputs may be binary: a rawlog).
std::string FirstDifference(const std::string& a, const std::string& b) {
  if (a == b) return "";
  const auto [in_a, in_b] = std::mismatch(a.begin(), a.end(), b.begin(), b.end());
  return "sizes " + std::to_string(a.size()) + " and " + std::to_string(b.size()) + ", first difference at byte " +
         std::to_string(in_a - a.begin());
}

TEST(Ros2BagSweepTest, BagsWrittenFromACarmenLogScoreAsTheLogDoes) {
  REQUIRE_CARMEN_FIXTURE();
  SLAMSWEEP_REQUIRE_SHARED(intel, "datasets/intel/intel-corrected.log.gz");
  SLAMSWEEP_REQUIRE_SHARED(relations, "datasets/intel/intel.relations");
  testing::TempDir dir;
  const std::filesystem::path log = testing::RawCarmenLog().log;
  for (const std::string storage : {"mcap", "sqlite3"}) {
    const std::filesystem::path out = dir / ("convert_" + storage + ".out");
    ASSERT_EQ(RunSlamsweep("data convert '" + log.string() + "' --to rosbag2 --storage " + storage + " -o '" +
                               (dir / ("bag_" + storage)).string() + "'",
                           out),
              0)
        << ReadAll(out);
  }
  // A reference map for the map-against-reference scores: the corrected intel map.
  ASSERT_EQ(RunSlamsweep("data map intel -o '" + (dir / "reference.yaml").string() + "'", dir / "map.out"), 0)
      << ReadAll(dir / "map.out");
  // A program reading the CARMEN input: its odometry as its trajectory.
  const std::filesystem::path program = testing::WriteFile(
      dir / "odometry_of_input.sh",
      "#!/bin/sh\nawk '$1 == \"ODOM\" { print $8, $2, $3, 0, 0, 0, sin($4 / 2), cos($4 / 2) }' \"$1\" | "
      "sort -u -k1,1 -g > \"$2/trajectory.tum\"\n");
  std::filesystem::permissions(program, std::filesystem::perms::owner_all | std::filesystem::perms::others_read |
                                            std::filesystem::perms::others_exec);
  // Scored against the map and against Kuemmerle's relations within the log's 150 scans (the relations are
  // on the raw log's clock: the shipped catalog's offset, configs/datasets.yaml).
  const std::string sequence_keys = "ground_truth: relations_only, relations: '" + relations.string() +
                                    "', relations_offset_s: -976052857.337, reference_map: reference.yaml";
  const std::filesystem::path sweep =
      testing::WriteFile(dir / "sweep.yaml",
                         "name: ros2-parity\noutput: out\niterations: 1\nseed: 3\n"
                         "algorithms:\n"
                         "  - {name: odometry, adapter: odometry}\n"
                         "  - {name: icp-slam, adapter: mrpt-icp-slam, timeout_s: 300}\n"
                         "  - name: carmen-reader\n    adapter: command\n    command:\n"
                         "      argv: [" +
                             program.string() +
                             ", \"{input}\", \"{output_dir}\"]\n"
                             "      input_format: carmen\n      trajectory: {path: trajectory.tum, format: tum}\n"
                             "sequences:\n"
                             "  - {name: carmen, format: carmen, path: '" +
                             log.string() + "', " + sequence_keys +
                             "}\n"
                             "  - {name: bag-mcap, format: rosbag2, path: bag_mcap, " +
                             sequence_keys +
                             "}\n"
                             "  - {name: bag-sqlite3, format: rosbag2, path: bag_sqlite3, " +
                             sequence_keys + "}\n");
  ASSERT_EQ(RunSlamsweep("run '" + sweep.string() + "' --no-report", dir / "run.out"), 0) << ReadAll(dir / "run.out");

  const nlohmann::json summary = nlohmann::json::parse(ReadAll(dir / "out" / "summary.json"));
  std::map<std::string, std::map<std::string, nlohmann::json>> runs;  // algorithm -> sequence -> run
  for (const nlohmann::json& run : summary.at("runs")) {
    ASSERT_EQ(run.at("status"), "ok") << run.dump();
    runs[run.at("algorithm")][run.at("sequence")] = run;
  }
  ASSERT_EQ(runs.size(), 3u);
  for (const auto& [algorithm, by_sequence] : runs) {
    ASSERT_EQ(by_sequence.size(), 3u) << algorithm;
    const nlohmann::json& carmen = by_sequence.at("carmen");
    for (const std::string bag : {"bag-mcap", "bag-sqlite3"}) {
      const nlohmann::json& from_bag = by_sequence.at(bag);
      EXPECT_EQ(from_bag.at("metrics"), carmen.at("metrics")) << algorithm << " on " << bag;
      // summary.json names run folders relative to the sweep's output.
      const auto bag_inputs = ProgramInputs(dir / "out" / from_bag.at("run_dir").get<std::string>(), bag);
      const auto log_inputs = ProgramInputs(dir / "out" / carmen.at("run_dir").get<std::string>(), "carmen");
      ASSERT_EQ(bag_inputs.size(), log_inputs.size()) << algorithm << " on " << bag;
      for (const auto& [extension, text] : log_inputs) {
        EXPECT_EQ(FirstDifference(bag_inputs.at(extension), text), "")
            << algorithm << " on " << bag << ": " << extension;
      }
    }
    EXPECT_FALSE(carmen.at("metrics").empty()) << algorithm;
  }
  // The scores compared include the maps against the reference map and the relations.
  for (const char* metric : {"map_iou_occupied", "relations_trans", "relations_rot"}) {
    EXPECT_TRUE(runs.at("icp-slam").at("carmen").at("metrics").contains(metric))
        << metric << ": " << runs.at("icp-slam").at("carmen").dump();
  }
}

}  // namespace
}  // namespace slamsweep
