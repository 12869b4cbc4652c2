#include "orchestrator/input_cache/prepared_sequence_cache.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "evaluator/catalog/catalog.h"
#include "evaluator/core/input_error.h"
#include "evaluator/sequence/scan_stamps.h"
#include "evaluator/sequence_io/sequence_file.h"
#include "orchestrator/adapters/run_inputs.h"
#include "orchestrator/build_identity/file_digest.h"
#include "orchestrator/input_cache/digest_memo.h"
#include "tests/orchestrator/worker/run_spec_fixture.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

namespace ev = slamsweep::evaluator;
namespace fs = std::filesystem;

/// Every double and float of two sequences compared bit for bit (== would call -0 and 0 equal).
template <typename T>
bool SameBits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

void ExpectSamePose(const ev::Pose& a, const ev::Pose& b, const std::string& where) {
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(SameBits(a.position[i], b.position[i])) << where;
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(SameBits(a.orientation.coeffs()[i], b.orientation.coeffs()[i])) << where;
}

void ExpectSameTrajectory(const ev::Trajectory& a, const ev::Trajectory& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(SameBits(a.stamps_s()[i], b.stamps_s()[i])) << what << " " << i;
    ExpectSamePose(a.poses()[i], b.poses()[i], what + " " + std::to_string(i));
  }
}

/// Everything a run takes from a prepared sequence is the same, bit for bit.
void ExpectSameForRuns(const ev::Sequence& a, const ev::Sequence& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.warnings, b.warnings);
  ASSERT_EQ(a.scans.size(), b.scans.size());
  for (std::size_t i = 0; i < a.scans.size(); ++i) {
    const ev::LaserScan& x = a.scans[i];
    const ev::LaserScan& y = b.scans[i];
    EXPECT_TRUE(SameBits(x.stamp_s, y.stamp_s) && SameBits(x.angle_min_rad, y.angle_min_rad) &&
                SameBits(x.angle_increment_rad, y.angle_increment_rad) && SameBits(x.range_min_m, y.range_min_m) &&
                SameBits(x.range_max_m, y.range_max_m))
        << "scan " << i;
    ExpectSamePose(x.sensor_pose_on_robot, y.sensor_pose_on_robot, "sensor pose " + std::to_string(i));
    ASSERT_EQ(x.ranges_m.size(), y.ranges_m.size());
    EXPECT_EQ(std::memcmp(x.ranges_m.data(), y.ranges_m.data(), x.ranges_m.size() * sizeof(float)), 0) << i;
  }
  ExpectSameTrajectory(a.odometry, b.odometry, "odometry");
  ExpectSameTrajectory(a.odometry_readings, b.odometry_readings, "odometry readings");
  ASSERT_EQ(a.reference.has_value(), b.reference.has_value());
  if (a.reference) ExpectSameTrajectory(*a.reference, *b.reference, "reference");
  ASSERT_EQ(a.relations.has_value(), b.relations.has_value());
  if (a.relations) {
    ASSERT_EQ(a.relations->size(), b.relations->size());
    for (std::size_t i = 0; i < a.relations->size(); ++i) {
      EXPECT_TRUE(SameBits((*a.relations)[i].t1_s, (*b.relations)[i].t1_s));
      EXPECT_TRUE(SameBits((*a.relations)[i].t2_s, (*b.relations)[i].t2_s));
      ExpectSamePose((*a.relations)[i].delta, (*b.relations)[i].delta, "relation " + std::to_string(i));
    }
  }
  EXPECT_EQ(a.relations_outside_log, b.relations_outside_log);
  ASSERT_EQ(a.stamp_facts.has_value(), b.stamp_facts.has_value());
  if (a.stamp_facts) {
    EXPECT_EQ(ev::StampFactsJson(*a.stamp_facts), ev::StampFactsJson(*b.stamp_facts));
  }
}

/// A run of the odometry baseline on a catalog entry of configs/datasets.yaml, its paths resolved.
RunSpec CatalogRun(const std::string& name, std::size_t max_scans) {
  const ev::Catalog catalog = ev::ReadCatalog(fs::path(SLAMSWEEP_SOURCE_DIR) / "configs" / "datasets.yaml");
  ev::CatalogEntry entry = ev::FindCatalogEntry(catalog, name);
  const ev::CatalogVariables variables = {{"SHARED", slamsweep::testing::SharedRoot().string()}};
  for (std::string* path : {&entry.path, &entry.relations_path}) {
    if (!path->empty()) *path = ev::ResolveCatalogPath(*path, variables).string();
  }
  if (entry.corrected_log) entry.corrected_log->path = ev::ResolveCatalogPath(entry.corrected_log->path, variables);
  RunSpec spec = testing::SimulatedRun("odometry");
  spec.sequence.entry = entry;
  spec.sequence.max_scans = max_scans;
  return spec;
}

ev::Sequence PrepareDirectly(const RunSpec& spec) {
  ev::Sequence sequence = ev::LoadCatalogSequence(spec.sequence.entry, {});
  if (spec.sequence.max_scans) sequence = CutSequence(std::move(sequence), *spec.sequence.max_scans);
  ev::ValidateSequence(sequence);
  return sequence;
}

TEST(PreparedSequenceBytesTest, ACorrectedLogWithRelationsAndWarningsComesBackBitForBit) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");
  SLAMSWEEP_REQUIRE_SHARED(relations, "datasets/intel/intel.relations");
  ev::Sequence sequence = PrepareDirectly(CatalogRun("intel", 80));
  sequence.warnings.push_back("a warning the reader gave, kept with the sequence");
  ASSERT_TRUE(sequence.reference && sequence.relations);
  ASSERT_FALSE(sequence.relations->empty());
  // The recorded odometry stream: its readings between the scans.
  ASSERT_GT(sequence.odometry_readings.size(), sequence.scans.size());
  ExpectSameForRuns(DecodePreparedSequence(EncodePreparedSequence(sequence)), sequence);
}

TEST(PreparedSequenceBytesTest, ARawLogWithoutReferenceComesBackBitForBit) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-raw-scans-0-5504.clf.gz");
  ev::SequenceReadOptions options;
  options.name = "raw";
  options.carmen.logged_pose_is_reference = false;  // a raw log: the logged pose is the odometry
  options.carmen.stamps.repair = ev::StampRepair::kRetime;
  const ev::Sequence sequence = CutSequence(ev::ReadSequence(log, options), 400);
  ASSERT_FALSE(sequence.reference.has_value());
  // The raw log's late stamps are re-timed and their order weighed: facts every run records.
  ASSERT_TRUE(sequence.stamp_facts.has_value());
  ExpectSameForRuns(DecodePreparedSequence(EncodePreparedSequence(sequence)), sequence);
}

TEST(PreparedSequenceBytesTest, ASimulatedFloorKeepsItsReferenceMapAndProvenance) {
  const ev::Sequence sequence = PrepareDirectly(testing::SimulatedRun("odometry", 10));
  ASSERT_TRUE(sequence.reference_map.has_value());
  const ev::Sequence decoded = DecodePreparedSequence(EncodePreparedSequence(sequence));
  ExpectSameForRuns(decoded, sequence);
  ASSERT_TRUE(decoded.reference_map.has_value());
  EXPECT_EQ(decoded.reference_map->width, sequence.reference_map->width);
  EXPECT_EQ(decoded.reference_map->cells, sequence.reference_map->cells);
  EXPECT_EQ(decoded.provenance.citation, sequence.provenance.citation);
  EXPECT_EQ(decoded.provenance.source, sequence.provenance.source);
}

TEST(PreparedSequenceBytesTest, DamagedBytesAreAnInputError) {
  const ev::Sequence sequence = PrepareDirectly(testing::SimulatedRun("odometry", 10));
  const std::string bytes = EncodePreparedSequence(sequence);
  EXPECT_THROW(DecodePreparedSequence(bytes.substr(0, bytes.size() / 2)), ev::InputError);
  EXPECT_THROW(DecodePreparedSequence(bytes + "x"), ev::InputError);
  std::string huge_count = bytes;
  // The scans' count, after the name (its length, then its bytes).
  std::memset(huge_count.data() + 8 + sequence.name.size(), 0xff, 8);
  EXPECT_THROW(DecodePreparedSequence(huge_count), ev::InputError);
}

TEST(PreparedInputCacheDirTest, BesideRunsOfASweepAndNowhereElse) {
  EXPECT_EQ(PreparedInputCacheDir("/out/runs/r1"), fs::path("/out/prepared_inputs"));
  EXPECT_EQ(PreparedInputCacheDir("/out/runs/r1/"), fs::path("/out/prepared_inputs"));
  EXPECT_TRUE(PreparedInputCacheDir("/tmp/r1").empty());
}

TEST(PreparedSequenceCacheTest, TheSecondRunReadsWhatTheFirstPreparedAndGetsTheSameInputs) {
  const slamsweep::testing::TempDir dir;
  RunSpec spec = testing::SimulatedRun("odometry", 30);
  int prepared = 0;
  const auto prepare = [&] {
    ++prepared;
    return PrepareDirectly(spec);
  };
  const PreparedSequence first = LoadOrPrepareSequence(spec, dir / "cache", prepare);
  EXPECT_FALSE(first.from_cache);
  EXPECT_TRUE(first.cache_problem.empty()) << first.cache_problem;
  // Another noise, seed, iteration and algorithm: the same prepared sequence.
  spec.seed = 99;
  spec.iteration = 4;
  spec.noise.name = "noisy";
  spec.noise.odometry = ev::OdometryNoise{0.05, 0.0, 0.05, 0.0, 0.0, 0.0};
  spec.algorithm.name = "other";
  const PreparedSequence second = LoadOrPrepareSequence(spec, dir / "cache", prepare);
  EXPECT_TRUE(second.from_cache);
  EXPECT_EQ(prepared, 1);
  ExpectSameForRuns(second.sequence, first.sequence);
  ExpectSameForRuns(second.sequence, PrepareDirectly(spec));
  // Another cut is another entry.
  spec.sequence.max_scans = 20;
  EXPECT_FALSE(LoadOrPrepareSequence(spec, dir / "cache", prepare).from_cache);
  EXPECT_EQ(prepared, 2);
}

TEST(PreparedSequenceCacheTest, RunInputsWithTheCacheEqualThoseWithout) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");
  const slamsweep::testing::TempDir dir;
  RunSpec spec = CatalogRun("intel", 60);
  spec.noise.name = "noisy";
  spec.noise.odometry = ev::OdometryNoise{0.02, 0.001, 0.02, 0.001, 0.0, 0.0};
  spec.noise.range = ev::RangeNoise{};
  spec.noise.range->sigma_m = 0.01;
  const RunInputs plain = PrepareRunInputs(spec);
  for (int attempt = 0; attempt < 2; ++attempt) {  // made, then found
    const RunInputs cached = PrepareRunInputs(spec, dir / "prepared_inputs");
    EXPECT_EQ(cached.warnings, plain.warnings);
    EXPECT_EQ(cached.noise_record, plain.noise_record);
    EXPECT_EQ(cached.odometry_is_reference, plain.odometry_is_reference);
    ev::Sequence a;
    a.scans = cached.robot.scans;
    a.odometry = cached.robot.odometry;
    a.odometry_readings = cached.robot.odometry_readings;
    a.reference = cached.truth.reference;
    a.relations = cached.truth.relations;
    ev::Sequence b;
    b.scans = plain.robot.scans;
    b.odometry = plain.robot.odometry;
    b.odometry_readings = plain.robot.odometry_readings;
    b.reference = plain.truth.reference;
    b.relations = plain.truth.relations;
    ExpectSameForRuns(a, b);
  }
}

TEST(PreparedSequenceCacheTest, ADamagedEntryIsMadeAgain) {
  const slamsweep::testing::TempDir dir;
  const RunSpec spec = testing::SimulatedRun("odometry", 12);
  int prepared = 0;
  const auto prepare = [&] {
    ++prepared;
    return PrepareDirectly(spec);
  };
  LoadOrPrepareSequence(spec, dir / "cache", prepare);
  std::vector<fs::path> entries;
  for (const auto& file : fs::directory_iterator(dir / "cache")) {
    if (file.path().extension() == ".seq") entries.push_back(file.path());
  }
  ASSERT_EQ(entries.size(), 1u);
  std::string bytes = testing::ReadText(entries[0]);
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x5a);
  std::ofstream(entries[0], std::ios::binary) << bytes;
  const PreparedSequence again = LoadOrPrepareSequence(spec, dir / "cache", prepare);
  EXPECT_FALSE(again.from_cache);
  EXPECT_EQ(prepared, 2);
  ExpectSameForRuns(again.sequence, PrepareDirectly(spec));
  EXPECT_TRUE(LoadOrPrepareSequence(spec, dir / "cache", prepare).from_cache);
}

TEST(PreparedSequenceCacheTest, TheKeyFollowsTheLogsContentNotItsName) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/mit-csail/csail-corrected.log.gz");
  const slamsweep::testing::TempDir dir;
  fs::copy_file(log, dir / "log.gz");
  RunSpec spec = CatalogRun("mit-csail", 20);
  spec.sequence.entry.path = (dir / "log.gz").string();
  const nlohmann::json before = PreparedSequenceKey(spec, dir / "cache");
  EXPECT_EQ(PreparedSequenceKey(spec, dir / "cache"), before);
  // Same name, size and path; other bytes (a re-downloaded file): another key.
  std::string bytes = testing::ReadText(dir / "log.gz");
  bytes[bytes.size() - 10] = static_cast<char>(bytes[bytes.size() - 10] ^ 1);
  std::ofstream(dir / "log.gz", std::ios::binary | std::ios::trunc) << bytes;
  EXPECT_NE(PreparedSequenceKey(spec, dir / "cache")["files_sha256"], before["files_sha256"]);
  // What is said about the data is not the data.
  RunSpec cited = spec;
  cited.sequence.entry.citation = "someone else";
  EXPECT_EQ(PreparedSequenceKey(cited, dir / "cache")["sequence"],
            PreparedSequenceKey(spec, dir / "cache")["sequence"]);
}

TEST(DigestMemoTest, AFileJustWrittenIsDigestedEveryTimeAndNeverRemembered) {
  const slamsweep::testing::TempDir dir;
  slamsweep::testing::WriteFile(dir / "data", "abc");
  // SHA-256("abc"), FIPS 180-2's example.
  const std::string abc = "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad";
  EXPECT_EQ(MemoisedSha256(dir / "data", dir / "memo"), abc);
  // Rewritten at once (within one tick of the file system's clock, same size): the new digest.
  slamsweep::testing::WriteFile(dir / "data", "abd");
  EXPECT_NE(MemoisedSha256(dir / "data", dir / "memo"), abc);
  EXPECT_FALSE(fs::exists(dir / "memo") && !fs::is_empty(dir / "memo"));
  EXPECT_THROW(MemoisedSha256(dir / "missing", dir / "memo"), ev::InputError);
}

TEST(DigestMemoTest, ASettledFileIsDigestedOnceThenRemembered) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/mit-csail/csail-corrected.log.gz");
  const slamsweep::testing::TempDir dir;
  const std::string digest = MemoisedSha256(log, dir / "memo");
  ASSERT_EQ(digest, Sha256OfFile(log));
  std::vector<fs::path> memos;
  for (const auto& file : fs::directory_iterator(dir / "memo")) memos.push_back(file.path());
  ASSERT_EQ(memos.size(), 1u);
  // What is remembered is what is returned: a memo altered by hand is what the next call gives.
  std::string memo = testing::ReadText(memos[0]);
  memo.replace(memo.size() - 65, 64, std::string(64, '0'));
  std::ofstream(memos[0], std::ios::binary | std::ios::trunc) << memo;
  EXPECT_EQ(MemoisedSha256(log, dir / "memo"), std::string(64, '0'));
}

}  // namespace
}  // namespace slamsweep::orchestrator
