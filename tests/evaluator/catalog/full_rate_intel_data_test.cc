// The full-rate raw intel log (../shared/datasets/intel/intel-raw-scans-0-5504.clf.gz) as the catalog reads
// it, and the facts of its PROVENANCE.txt that the catalog entry rests on, checked against the corrected
// log of the same run.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "evaluator/catalog/catalog.h"
#include "evaluator/formats/trajectory/carmen_log.h"
#include "evaluator/formats/trajectory/relations_format.h"
#include "evaluator/sequence/sequence.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

constexpr const char* kRawLog = "datasets/intel/intel-raw-scans-0-5504.clf.gz";
constexpr const char* kCorrectedLog = "datasets/intel/intel-corrected.log.gz";
constexpr const char* kRelations = "datasets/intel/intel.relations";

const CatalogEntry& ShippedEntry(const std::string& name) {
  static const Catalog catalog = ReadCatalog(std::filesystem::path(SLAMSWEEP_SOURCE_DIR) / "configs" / "datasets.yaml");
  return FindCatalogEntry(catalog, name);
}

std::vector<const CarmenLaserRecord*> Flasers(const CarmenLog& log) {
  std::vector<const CarmenLaserRecord*> scans;
  for (const CarmenLaserRecord& record : log.lasers) {
    if (record.type == "FLASER") scans.push_back(&record);
  }
  return scans;
}

/// The corrected log's real ODOM readings (one per raw scan of the run): every ODOM record but the reset
/// right after each FLASER (PROVENANCE.txt), with `crosses_keyframe[k]` true when a FLASER lies between
/// reading k and k + 1.
struct OdomStream {
  std::vector<Pose> poses;
  std::vector<bool> crosses_keyframe;
};

OdomStream RealReadings(const CarmenLog& log) {
  std::map<std::size_t, bool> lines;  // line -> is a laser record
  for (const CarmenLaserRecord& record : log.lasers) lines[record.line] = true;
  std::map<std::size_t, const CarmenOdomRecord*> odometry;
  for (const CarmenOdomRecord& record : log.odometry) {
    lines[record.line] = false;
    odometry[record.line] = &record;
  }
  OdomStream stream;
  bool after_laser = false;
  bool laser_since_reading = false;
  for (const auto& [line, is_laser] : lines) {
    if (is_laser) {
      after_laser = true;
      laser_since_reading = true;
      continue;
    }
    if (after_laser) {  // the reset
      after_laser = false;
      continue;
    }
    if (!stream.poses.empty()) stream.crosses_keyframe.push_back(laser_since_reading);
    stream.poses.push_back(odometry.at(line)->pose);
    laser_since_reading = false;
  }
  return stream;
}

// The catalog entry: a raw log (no reference, never odometry = reference) on the relations' own clock,
// whose records keep file order (PROVENANCE: 265 backward steps by up to 0.897 s, no duplicates).
TEST(FullRateIntelTest, TheCatalogReadsItAsARawLogOnTheRelationsClock) {
  SLAMSWEEP_REQUIRE_SHARED(raw, kRawLog);
  SLAMSWEEP_REQUIRE_SHARED(relations, kRelations);
  const Sequence sequence =
      LoadCatalogSequence(ShippedEntry("intel-full-rate"), {{"SHARED", testing::SharedRoot().string()}});
  ASSERT_EQ(sequence.scans.size(), 5505u);
  EXPECT_FALSE(sequence.reference.has_value());
  EXPECT_FALSE(OdometryEqualsReference(sequence));
  // The first 1,088.6 s of the run, on the ipc clock (logger + 976052857.337284).
  EXPECT_NEAR(sequence.scans.front().stamp_s, 976052857.337284 + 0.000246, 0.005);
  EXPECT_NEAR(sequence.scans.back().stamp_s - sequence.scans.front().stamp_s, 1088.6, 0.05);
  ASSERT_TRUE(sequence.stamp_facts.has_value());
  EXPECT_EQ(sequence.stamp_facts->steps_back, 265u);
  EXPECT_EQ(sequence.stamp_facts->duplicates, 0u);
  EXPECT_NEAR(sequence.stamp_facts->largest_step_back_s, 0.897, 0.001);
  EXPECT_EQ(sequence.stamp_facts->outcome, StampOutcome::kRetimed);
  // The longest increasing run of stamps leaves out 323 (an independent script's count, catalog notes).
  EXPECT_EQ(sequence.stamp_facts->changed, 323u);
  // File order is the acquisition order: at most backward steps the scans change less in file order.
  ASSERT_TRUE(sequence.stamp_facts->order_check.has_value());
  const RecordOrderCheck& check = *sequence.stamp_facts->order_check;
  EXPECT_EQ(check.steps, 265u);
  EXPECT_GT(check.scans_closer_in_file_order, 9 * check.scans_closer_in_stamp_order);
  EXPECT_GT(check.odometry_shorter_in_file_order, 3 * check.odometry_shorter_in_stamp_order);
  // PROVENANCE: 1,033 of intel.relations' 2,984 relations have both stamps inside the log.
  ASSERT_TRUE(sequence.relations.has_value());
  EXPECT_EQ(sequence.relations->size(), 1033u);
  EXPECT_EQ(sequence.relations_outside_log, 2984u - 1033u);
  EXPECT_NO_THROW(ValidateSequence(sequence));
}

// PROVENANCE: 345 of the corrected log's 910 keyframes (keyframes 0..344, keyframe 0 = raw scan 169) have
// bit-identical ranges in the full-rate log, in the same order.
TEST(FullRateIntelTest, TheCorrectedLogsFirst345KeyframesAreItsScans) {
  SLAMSWEEP_REQUIRE_SHARED(raw_path, kRawLog);
  SLAMSWEEP_REQUIRE_SHARED(corrected_path, kCorrectedLog);
  const CarmenLog raw = ReadCarmenLog(raw_path);
  const CarmenLog corrected = ReadCarmenLog(corrected_path);
  std::map<std::vector<double>, std::size_t> raw_by_ranges;
  const std::vector<const CarmenLaserRecord*> raw_scans = Flasers(raw);
  for (std::size_t i = 0; i < raw_scans.size(); ++i) raw_by_ranges.emplace(raw_scans[i]->ranges_m, i);
  std::vector<std::size_t> matched_keyframes;
  std::vector<std::size_t> raw_indices;
  const std::vector<const CarmenLaserRecord*> keyframes = Flasers(corrected);
  for (std::size_t k = 0; k < keyframes.size(); ++k) {
    const auto found = raw_by_ranges.find(keyframes[k]->ranges_m);
    if (found == raw_by_ranges.end()) continue;
    matched_keyframes.push_back(k);
    raw_indices.push_back(found->second);
  }
  ASSERT_EQ(matched_keyframes.size(), 345u);
  EXPECT_EQ(matched_keyframes.front(), 0u);
  EXPECT_EQ(matched_keyframes.back(), 344u);
  EXPECT_EQ(raw_indices.front(), 169u);
  for (std::size_t i = 1; i < raw_indices.size(); ++i) EXPECT_GT(raw_indices[i], raw_indices[i - 1]) << i;
}

// PROVENANCE: the full-rate log's odometry steps equal the corrected log's ODOM-stream steps within 2 mm /
// 2 mrad, except the 345 steps that cross a keyframe (where the stream restarts from the corrected pose).
TEST(FullRateIntelTest, ItsOdometryStepsAreTheCorrectedLogsOdomStreamSteps) {
  SLAMSWEEP_REQUIRE_SHARED(raw_path, kRawLog);
  SLAMSWEEP_REQUIRE_SHARED(corrected_path, kCorrectedLog);
  const CarmenLog raw = ReadCarmenLog(raw_path);
  const OdomStream stream = RealReadings(ReadCarmenLog(corrected_path));
  const std::vector<const CarmenLaserRecord*> raw_scans = Flasers(raw);
  ASSERT_GE(stream.poses.size(), raw_scans.size());
  std::size_t equal = 0;
  std::size_t different_across_keyframe = 0;
  std::size_t crossing = 0;
  for (std::size_t k = 0; k + 1 < raw_scans.size(); ++k) {
    const Pose raw_step = Relative(raw_scans[k]->odom_pose, raw_scans[k + 1]->odom_pose);
    const Pose stream_step = Relative(stream.poses[k], stream.poses[k + 1]);
    const Pose difference = Relative(raw_step, stream_step);
    const bool same = difference.position.norm() <= 0.002 && RotationAngleRad(difference.orientation) <= 0.002;
    if (stream.crosses_keyframe[k]) ++crossing;
    if (same) {
      ++equal;
    } else if (stream.crosses_keyframe[k]) {
      ++different_across_keyframe;
    } else {
      ADD_FAILURE() << "step " << k << " differs by " << difference.position.norm() << " m and does not cross a "
                    << "keyframe";
    }
  }
  EXPECT_EQ(crossing, 345u);
  EXPECT_EQ(different_across_keyframe, 345u);
  EXPECT_EQ(equal, 5504u - 345u);
}

}  // namespace
}  // namespace slamsweep::evaluator
