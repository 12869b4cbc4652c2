#include "evaluator/catalog/catalog.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>

#include "evaluator/core/input_error.h"
#include "evaluator/sequence_io/sequence_file.h"
#include "tests/support/shared_data.h"
#include "tests/support/input_error_text.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

using slamsweep::testing::ErrorOf;

std::filesystem::path ShippedCatalog() {
  // Not __FILE__: compiler caches may make it relative to the build folder.
  return std::filesystem::path(SLAMSWEEP_SOURCE_DIR) / "configs" / "datasets.yaml";
}

CatalogVariables Shared() { return {{"SHARED", testing::SharedRoot().string()}}; }

/// FLASER count and beam count from the "Stats:" line of a dataset's PROVENANCE.txt.
std::pair<std::size_t, std::size_t> ProvenanceCounts(const std::filesystem::path& provenance) {
  std::ifstream in(provenance);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::smatch match;
  if (!std::regex_search(text, match, std::regex(R"(Stats: .*FLASER=(\d+) .*readings=\[(\d+)\])"))) return {0, 0};
  return {std::stoul(match[1]), std::stoul(match[2])};
}

TEST(CatalogTest, ShippedCatalogValidatesAndNamesEverySharedDataset) {
  const Catalog catalog = ReadCatalog(ShippedCatalog());
  for (const char* name : {"mrpt-telecom", "intel", "fr079", "fr101", "mit-csail", "freiburg-campus",
                           "mit-infinite-corridor", "orebro", "belgioioso", "mit-killian", "simulated-floor"}) {
    const CatalogEntry& entry = FindCatalogEntry(catalog, name);
    EXPECT_FALSE(entry.citation.empty()) << name;
    EXPECT_FALSE(entry.licence_note.empty()) << name;
    if (entry.format != "simulated") {
      EXPECT_FALSE(entry.download_hint.empty()) << name;
    }
  }
  EXPECT_EQ(FindCatalogEntry(catalog, "simulated-floor").ground_truth, GroundTruthKind::kExact);
  EXPECT_EQ(FindCatalogEntry(catalog, "mit-killian").ground_truth, GroundTruthKind::kRelationsOnly);
  EXPECT_EQ(FindCatalogEntry(catalog, "intel").ground_truth, GroundTruthKind::kCorrectedPoses);
  // PROVENANCE.txt of intel: relation stamps minus ~976052857.337 are the corrected log's stamps.
  EXPECT_DOUBLE_EQ(FindCatalogEntry(catalog, "intel").relations_offset_s, -976052857.337);
}

TEST(CatalogTest, EveryCarmenDatasetInSharedLoadsWithItsProvenanceCounts) {
  SLAMSWEEP_REQUIRE_SHARED(datasets, "datasets/intel/PROVENANCE.txt");
  const Catalog catalog = ReadCatalog(ShippedCatalog());
  std::size_t loaded = 0;
  for (const CatalogEntry& entry : catalog.entries) {
    if (entry.format != "carmen" || entry.ground_truth != GroundTruthKind::kCorrectedPoses) continue;
    const std::filesystem::path path = ResolveCatalogPath(entry.path, Shared());
    const auto [scans, beams] = ProvenanceCounts(path.parent_path() / "PROVENANCE.txt");
    ASSERT_GT(scans, 0u) << entry.name;
    const Sequence sequence = LoadCatalogSequence(entry, Shared());
    EXPECT_EQ(sequence.name, entry.name);
    EXPECT_EQ(sequence.scans.size(), scans) << entry.name;
    EXPECT_EQ(sequence.scans.front().BeamCount(), beams) << entry.name;
    EXPECT_TRUE(sequence.reference.has_value()) << entry.name;
    ++loaded;
  }
  EXPECT_EQ(loaded, 8u);
}

TEST(CatalogTest, IntelRelationsLandOnTheLogClock) {
  SLAMSWEEP_REQUIRE_SHARED(relations, "datasets/intel/intel.relations");
  const Sequence sequence = LoadCatalogSequence(FindCatalogEntry(ReadCatalog(ShippedCatalog()), "intel"), Shared());
  ASSERT_TRUE(sequence.relations.has_value());
  // PROVENANCE.txt: relation stamps 976052896.78..976055541.11, log stamps 32.9..2683.8.
  double first_s = 1e300;
  double last_s = -1e300;
  for (const Relation& relation : *sequence.relations) {
    first_s = std::min({first_s, relation.t1_s, relation.t2_s});
    last_s = std::max({last_s, relation.t1_s, relation.t2_s});
  }
  EXPECT_NEAR(first_s, 976052896.78 - 976052857.337, 0.01);
  // The last stamp lies where the recorded readings' repaired clock puts its raw scan: the stream's
  // stamps step back (by up to 0.9 s) near the end, and the repairs lift them.
  EXPECT_GE(last_s, 976055541.11 - 976052857.337 - 0.01);
  EXPECT_LT(last_s, 976055541.11 - 976052857.337 + 1.0);
  EXPECT_GT(first_s, sequence.scans.front().stamp_s);
  EXPECT_LE(last_s, sequence.odometry_readings.stamps_s().back());
  // With recorded odometry every relation stamp names one raw scan: it is a reading's stamp.
  ASSERT_EQ(sequence.odometry_readings.size(), 13631u);
  const std::vector<double>& readings = sequence.odometry_readings.stamps_s();
  std::size_t on_a_reading = 0;
  for (const Relation& relation : *sequence.relations) {
    for (double stamp : {relation.t1_s, relation.t2_s}) {
      on_a_reading += std::binary_search(readings.begin(), readings.end(), stamp) ? 1 : 0;
    }
  }
  EXPECT_EQ(on_a_reading, 2 * sequence.relations->size());
}

TEST(CatalogTest, OdometryModeDefaultsToRecordedOnCorrectedLogsOnly) {
  const Catalog catalog = ReadCatalog(ShippedCatalog());
  const CatalogEntry& intel = FindCatalogEntry(catalog, "intel");
  EXPECT_TRUE(OdometryModeApplies(intel));
  EXPECT_EQ(EffectiveOdometryMode(intel), OdometryMode::kRecorded);
  CatalogEntry reference = intel;
  reference.odometry = OdometryMode::kReference;
  EXPECT_EQ(EffectiveOdometryMode(reference), OdometryMode::kReference);
  const CatalogEntry& floor = FindCatalogEntry(catalog, "simulated-floor");
  EXPECT_FALSE(OdometryModeApplies(floor));
  EXPECT_EQ(EffectiveOdometryMode(floor), OdometryMode::kRecorded);
  // Reference mode on a sequence that has only its recorded odometry is an error at its line.
  const std::string text =
      "sequences:\n  - {name: sim, format: simulated, ground_truth: exact, odometry: reference, simulation: {}}\n";
  try {
    ParseCatalog(text, "c.yaml");
    ADD_FAILURE() << "reference mode on a simulated sequence was accepted";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("c.yaml:2"));
    EXPECT_THAT(error.what(), ::testing::HasSubstr("only its recorded odometry"));
  }
  EXPECT_THROW(ParseCatalog("sequences:\n  - {name: a, format: carmen, path: a.log, ground_truth: corrected_poses, "
                            "odometry: wheels}\n",
                            "c.yaml"),
               InputError);
}

TEST(CatalogTest, IntelReferenceModeHandsTheCorrectedPathAsOdometry) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");
  CatalogEntry entry = FindCatalogEntry(ReadCatalog(ShippedCatalog()), "intel");
  EXPECT_FALSE(OdometryEqualsReference(LoadCatalogSequence(entry, Shared())));
  entry.odometry = OdometryMode::kReference;
  const Sequence reference = LoadCatalogSequence(entry, Shared());
  EXPECT_TRUE(OdometryEqualsReference(reference));
  EXPECT_TRUE(reference.odometry_readings.empty());
}

TEST(CatalogTest, EveryEntryWithAMissingFileSaysWhereToGetIt) {
  // Entries whose file is not in ../shared must name a download (data info prints it).
  for (const CatalogEntry& entry : ReadCatalog(ShippedCatalog()).entries) {
    if (entry.format == "simulated") continue;
    const std::filesystem::path path = ResolveCatalogPath(entry.path, Shared());
    if (std::filesystem::exists(path)) continue;
    EXPECT_FALSE(entry.download_hint.empty()) << entry.name;
    try {
      LoadCatalogSequence(entry, Shared());
      ADD_FAILURE() << entry.name << ": loaded without its file";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find(entry.download_hint), std::string::npos) << error.what();
    }
  }
}

TEST(CatalogTest, OrebroMaxRangeOverrideTurnsItsSickOverflowIntoNoReturn) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/orebro/orebro-corrected.log.gz");
  const Sequence sequence = LoadCatalogSequence(FindCatalogEntry(ReadCatalog(ShippedCatalog()), "orebro"), Shared());
  // Counted with awk over the FLASER readings: 463 at 32.767, 7 at 32.765, 465 at 32.763, 33 at 32.759.
  std::size_t misses = 0;
  for (const LaserScan& scan : sequence.scans) {
    for (float range : scan.ranges_m) misses += scan.IsHit(range) ? 0 : 1;
  }
  EXPECT_EQ(misses, 463u + 7u + 465u + 33u);
}

TEST(CatalogTest, SimulatedEntryGeneratesASequenceWithExactGroundTruth) {
  const Sequence sequence =
      LoadCatalogSequence(FindCatalogEntry(ReadCatalog(ShippedCatalog()), "simulated-floor"), Shared());
  ASSERT_FALSE(sequence.scans.empty());
  ASSERT_TRUE(sequence.reference.has_value());
  EXPECT_EQ(sequence.reference->size(), sequence.scans.size());
  EXPECT_TRUE(sequence.reference_map.has_value());
  EXPECT_NO_THROW(ValidateSequence(sequence));
}

constexpr const char* kMinimal =
    "sequences:\n"
    "  - name: a\n"
    "    format: carmen\n"
    "    path: ${ROOT}/a.log\n"
    "    ground_truth: none\n"
    "    download: example.org/a\n";

// Found by fuzzing service_submission: a map as the key of an entry (`- {catalog: intel, ...}: 1`) made
// yaml-cpp's BadConversion leave the parser instead of an InputError; so at every level of a catalog.
TEST(CatalogTest, AKeyThatIsAMapOrAListIsAnErrorAtItsLine) {
  const std::string expected = "expected a key of plain text, got a map or a list";
  EXPECT_THAT(ErrorOf([] { ParseCatalog("{a: 1}: x\n", "c.yaml"); }), HasSubstr("c.yaml:1: " + expected));
  EXPECT_THAT(ErrorOf([] { ParseCatalog("sequences:\n  - {name: a}: 1\n", "c.yaml"); }),
              HasSubstr("c.yaml:2: " + expected));
  EXPECT_THAT(ErrorOf([] { ParseCatalog(std::string(kMinimal) + "    [x]: 1\n", "c.yaml"); }),
              HasSubstr("c.yaml:7: " + expected));
  EXPECT_THAT(ErrorOf([] {
                ParseCatalog(
                    "sequences:\n  - name: s\n    format: simulated\n    ground_truth: exact\n"
                    "    simulation: {{seed: 3}: 1}\n",
                    "c.yaml");
              }),
              HasSubstr("c.yaml:5: " + expected));
}

TEST(CatalogTest, UnknownKeysAndBadValuesNameFileAndLine) {
  EXPECT_THAT(ErrorOf([] { ParseCatalog(std::string(kMinimal) + "    max_rang_m: 30\n", "c.yaml"); }),
              HasSubstr("c.yaml:7: unknown key 'max_rang_m'"));
  EXPECT_THAT(ErrorOf([] { ParseCatalog("sequence:\n  - name: a\n", "c.yaml"); }),
              HasSubstr("c.yaml:1: unknown key 'sequence'"));
  EXPECT_THAT(ErrorOf([] { ParseCatalog(std::string(kMinimal) + "    max_range_m: far\n", "c.yaml"); }),
              HasSubstr("c.yaml:7: max_range_m: expected a finite number, got 'far'"));
  EXPECT_THAT(ErrorOf([] { ParseCatalog(std::string(kMinimal) + "    stamp_policy: sometimes\n", "c.yaml"); }),
              HasSubstr("c.yaml:7: stamp_policy"));
  EXPECT_THAT(ErrorOf([] {
                ParseCatalog("sequences:\n  - name: a\n    format: vhs\n    path: x\n    ground_truth: none\n",
                             "c.yaml");
              }),
              HasSubstr("c.yaml:3: format: expected carmen, rawlog, rosbag, rosbag2 or simulated, got 'vhs'"));
  EXPECT_THAT(ErrorOf([] { ParseCatalog(std::string(kMinimal) + std::string(kMinimal).substr(11), "c.yaml"); }),
              HasSubstr("c.yaml:7: sequence 'a' is listed twice"));
  EXPECT_THAT(ErrorOf([] { ParseCatalog("sequences:\n  - name: a\n    format: carmen\n    path: x\n", "c.yaml"); }),
              HasSubstr("c.yaml:2: sequence 'a': no ground_truth"));
  EXPECT_THAT(ErrorOf([] {
                ParseCatalog(
                    "sequences:\n  - name: s\n    format: simulated\n    ground_truth: exact\n"
                    "    simulation: {noise_sed: 3}\n",
                    "c.yaml");
              }),
              HasSubstr("c.yaml:5: "));
  EXPECT_THAT(ErrorOf([] { ParseCatalog("sequences: [\n", "c.yaml"); }), HasSubstr("c.yaml:"));
}

constexpr const char* kBag =
    "sequences:\n"
    "  - name: run1\n"
    "    format: rosbag2\n"
    "    path: bags/run1\n";

TEST(CatalogTest, ABagEntryNamesItsTopicsFramesAndMeasuredReference) {
  const Catalog catalog = ParseCatalog(std::string(kBag) +
                                           "    ground_truth: measured\n"
                                           "    reference_topic: /ground_truth\n"
                                           "    scan_topic: /scan_front\n"
                                           "    odometry_topic: /wheel_odom\n"
                                           "    base_frame: base_footprint\n"
                                           "    laser_frame: front_laser\n",
                                       "c.yaml");
  const CatalogEntry& entry = catalog.entries.at(0);
  EXPECT_EQ(entry.ground_truth, GroundTruthKind::kMeasured);
  EXPECT_EQ(GroundTruthKindName(entry.ground_truth), "measured");
  EXPECT_TRUE(GroundTruthHasPoses(entry.ground_truth));
  EXPECT_EQ(entry.bag.reference_topic, "/ground_truth");
  EXPECT_EQ(entry.bag.scan_topic, "/scan_front");
  EXPECT_EQ(entry.bag.odometry_topic, "/wheel_odom");
  EXPECT_EQ(entry.bag.BaseFrame(), "base_footprint");
  EXPECT_EQ(entry.bag.OdomFrame(), "odom");
  EXPECT_EQ(entry.bag.laser_frame, "front_laser");
  const Catalog by_tf =
      ParseCatalog(std::string(kBag) + "    ground_truth: measured\n    reference_frame: map\n", "c.yaml");
  EXPECT_EQ(by_tf.entries.at(0).bag.reference_frame, "map");
  // What the reference is stays the kind's to say: a bag written from a corrected log carries GMapping's poses.
  const Catalog corrected = ParseCatalog(
      std::string(kBag) + "    ground_truth: corrected_poses\n    reference_topic: /ground_truth\n", "c.yaml");
  EXPECT_EQ(corrected.entries.at(0).ground_truth, GroundTruthKind::kCorrectedPoses);
  EXPECT_EQ(ParseCatalog(std::string(kBag) + "    ground_truth: none\n", "c.yaml").entries.at(0).bag, BagChoices{});
}

TEST(CatalogTest, BagKeysAndTheMeasuredKindAreCheckedAgainstEachOther) {
  EXPECT_THAT(ErrorOf([] { ParseCatalog(std::string(kBag) + "    ground_truth: measured\n", "c.yaml"); }),
              HasSubstr("c.yaml:5: sequence 'run1': ground_truth measured needs the reference's source in the bag: "
                        "reference_topic (e.g. /ground_truth) or reference_frame (e.g. map)"));
  EXPECT_THAT(
      ErrorOf([] { ParseCatalog(std::string(kBag) + "    ground_truth: none\n    reference_topic: /gt\n", "c.yaml"); }),
      HasSubstr("c.yaml:5: sequence 'run1': reference_topic or reference_frame names a reference, but ground_truth "
                "is none"));
  EXPECT_THAT(ErrorOf([] {
                ParseCatalog(std::string(kBag) +
                                 "    ground_truth: measured\n    reference_topic: /gt\n    reference_frame: map\n",
                             "c.yaml");
              }),
              HasSubstr("exclude each other"));
  EXPECT_THAT(ErrorOf([] { ParseCatalog(std::string(kMinimal) + "    scan_topic: /scan\n", "c.yaml"); }),
              HasSubstr("c.yaml:7: sequence 'a': topics and frames apply to ROS bags (format rosbag or rosbag2), not "
                        "to format carmen"));
  EXPECT_THAT(ErrorOf([] {
                ParseCatalog("sequences:\n  - name: a\n    format: carmen\n    path: x\n    ground_truth: measured\n",
                             "c.yaml");
              }),
              HasSubstr("c.yaml:5: sequence 'a': ground_truth measured is a reference recorded in a ROS bag"));
  EXPECT_THAT(ErrorOf([] { ParseCatalog(std::string(kBag) + "    ground_truth: guessed\n", "c.yaml"); }),
              HasSubstr("c.yaml:5: ground_truth: expected one of corrected_poses, exact, measured, relations_only, "
                        "none, got 'guessed'"));
  EXPECT_THAT(
      ErrorOf([] { ParseCatalog(std::string(kBag) + "    ground_truth: none\n    scan_topic: \"\"\n", "c.yaml"); }),
      HasSubstr("c.yaml:6: scan_topic: expected a topic or frame name"));
}

TEST(CatalogTest, ABagFolderMustHoldItsMetadataAndSplitFiles) {
  testing::TempDir dir;
  std::filesystem::create_directories(dir / "bags" / "run1");
  const Catalog catalog = ParseCatalog(std::string(kBag) + "    ground_truth: none\n", dir / "c.yaml");
  const CatalogVariables none;
  CatalogEntry entry = catalog.entries.at(0);
  entry.path = (dir / "bags" / "run1").string();
  EXPECT_THAT(ErrorOf([&] { LoadCatalogSequence(entry, none); }),
              AllOf(HasSubstr("catalog sequence 'run1'"), HasSubstr("no metadata.yaml in the folder")));
  testing::WriteFile(dir / "bags" / "run1" / "metadata.yaml",
                     "rosbag2_bagfile_information:\n  version: 5\n  storage_identifier: mcap\n"
                     "  relative_file_paths:\n    - run1_0.mcap\n");
  EXPECT_THAT(ErrorOf([&] { LoadCatalogSequence(entry, none); }),
              HasSubstr("split file run1_0.mcap named by metadata.yaml is missing"));
}

// ground_truth says what a CARMEN log's logged pose is: the reference of a corrected log, the odometry of a
// raw one (relations_only, none), which then has no reference to be flagged against.
TEST(CatalogTest, ACarmenLogUnderRelationsOnlyOrNoneIsRaw) {
  testing::TempDir dir;
  std::string log;
  for (int i = 0; i < 5; ++i) {
    log += "FLASER 180";
    for (int b = 0; b < 180; ++b) log += " 2.0";
    log += " " + std::to_string(0.1 * i) + " 0 0 " + std::to_string(0.1 * i) + " 0 0 " + std::to_string(i) +
           " nohost " + std::to_string(i) + "\n";
  }
  testing::WriteFile(dir / "a.log", log);
  const CatalogVariables variables{{"ROOT", dir.path().string()}};
  CatalogEntry entry = ParseCatalog(kMinimal, "c.yaml").entries.at(0);
  for (GroundTruthKind raw : {GroundTruthKind::kNone, GroundTruthKind::kRelationsOnly}) {
    entry.ground_truth = raw;
    EXPECT_FALSE(LoggedPoseIsReference(entry));
    const Sequence sequence = LoadCatalogSequence(entry, variables);
    EXPECT_FALSE(sequence.reference.has_value()) << GroundTruthKindName(raw);
    EXPECT_FALSE(OdometryEqualsReference(sequence));
  }
  entry.ground_truth = GroundTruthKind::kCorrectedPoses;
  EXPECT_TRUE(LoggedPoseIsReference(entry));
  const Sequence corrected = LoadCatalogSequence(entry, variables);
  ASSERT_TRUE(corrected.reference.has_value());
  EXPECT_TRUE(OdometryEqualsReference(corrected)) << "a corrected log without an ODOM stream: flagged, not hidden";
}

TEST(CatalogTest, ARelationsWindowIsTwoStampsInOrderAndNeedsRelations) {
  const Catalog catalog = ParseCatalog(
      std::string(kMinimal) + "    relations: r.relations\n    relations_window: [100.5, 200]\n", "c.yaml");
  ASSERT_TRUE(catalog.entries.at(0).relations_window_s.has_value());
  EXPECT_EQ((*catalog.entries.at(0).relations_window_s)[0], 100.5);
  EXPECT_EQ((*catalog.entries.at(0).relations_window_s)[1], 200.0);
  EXPECT_THAT(ErrorOf([] {
                ParseCatalog(std::string(kMinimal) + "    relations: r\n    relations_window: [2, 1]\n", "c.yaml");
              }),
              HasSubstr("c.yaml:8: relations_window: expected from < to"));
  EXPECT_THAT(
      ErrorOf([] { ParseCatalog(std::string(kMinimal) + "    relations: r\n    relations_window: 5\n", "c.yaml"); }),
      HasSubstr("relations_window: expected [from, to]"));
  EXPECT_THAT(ErrorOf([] { ParseCatalog(std::string(kMinimal) + "    relations_window: [1, 2]\n", "c.yaml"); }),
              HasSubstr("relations_window without relations"));
  EXPECT_THAT(ErrorOf([] { ParseGroundTruthKind("corrected", "--ground-truth"); }),
              HasSubstr("--ground-truth: expected one of corrected_poses, exact, measured, relations_only, none"));
}

TEST(CatalogTest, AnEntryMayNameAReferenceMap) {
  const Catalog catalog = ParseCatalog(std::string(kMinimal) + "    reference_map: ${SHARED}/maps/a.yaml\n", "c.yaml");
  EXPECT_EQ(catalog.entries.at(0).reference_map_path, "${SHARED}/maps/a.yaml");
  EXPECT_TRUE(ParseCatalog(kMinimal, "c.yaml").entries.at(0).reference_map_path.empty());
}

TEST(CatalogTest, MissingFileNamesEntryPathAndWhereToGetIt) {
  const Catalog catalog = ParseCatalog(kMinimal, "c.yaml");
  const std::string error = ErrorOf([&] { LoadCatalogSequence(catalog.entries[0], {{"ROOT", "/nowhere"}}); });
  EXPECT_THAT(error, HasSubstr("catalog sequence 'a'"));
  EXPECT_THAT(error, HasSubstr("/nowhere/a.log is missing"));
  EXPECT_THAT(error, HasSubstr("get it from: example.org/a"));
  EXPECT_THAT(ErrorOf([&] { LoadCatalogSequence(catalog.entries[0], {}); }), HasSubstr("unknown variable ${ROOT}"));
  EXPECT_THAT(ErrorOf([&] { FindCatalogEntry(catalog, "b"); }),
              HasSubstr("no sequence named 'b' in the catalog c.yaml (known: a)"));
}

TEST(CatalogTest, Fr079HasItsRelationsOnTheLogsClock) {
  SLAMSWEEP_REQUIRE_SHARED(relations, "datasets/fr079/fr079.relations");
  const Catalog catalog = ReadCatalog(ShippedCatalog());
  const CatalogEntry& entry = FindCatalogEntry(catalog, "fr079");
  EXPECT_NE(entry.relations_rate, 1.0);  // the relations' clock runs at another rate (the fitted map)
  EXPECT_FALSE(entry.notes.empty());     // how the map was fitted, and its residual
  const Sequence sequence = LoadCatalogSequence(entry, Shared());
  ASSERT_TRUE(sequence.relations.has_value());
  EXPECT_EQ(sequence.relations->size(), 1685u);
  // Every relation falls inside the log's span once mapped.
  for (const Relation& relation : *sequence.relations) {
    ASSERT_GE(std::min(relation.t1_s, relation.t2_s), sequence.odometry_readings.stamps_s().front());
    ASSERT_LE(std::max(relation.t1_s, relation.t2_s), sequence.odometry_readings.stamps_s().back());
  }
}

TEST(CatalogTest, DenseIntelTakesTheCorrectedLogsClockReferenceAndRelations) {
  SLAMSWEEP_REQUIRE_SHARED(rawlog, "datasets/intel/intel-mrpt-every5.rawlog.gz");
  if (!RawlogSupported()) {
    if (testing::RunningInCi()) FAIL() << "MRPT not built";
    GTEST_SKIP() << "MRPT not built";
  }
  const Sequence dense = LoadCatalogSequence(FindCatalogEntry(ReadCatalog(ShippedCatalog()), "intel-dense"), Shared());
  const Sequence intel = LoadCatalogSequence(FindCatalogEntry(ReadCatalog(ShippedCatalog()), "intel"), Shared());
  // Three times the corrected log's density, on its clock: the scans' stamps are readings' stamps.
  EXPECT_GT(dense.scans.size(), 2700u);
  ASSERT_TRUE(dense.reference.has_value());
  ASSERT_TRUE(dense.relations.has_value());
  EXPECT_EQ(dense.relations->size(), intel.relations->size());
  const std::vector<double>& readings = intel.odometry_readings.stamps_s();
  for (const LaserScan& scan : dense.scans) {
    ASSERT_TRUE(std::binary_search(readings.begin(), readings.end(), scan.stamp_s)) << scan.stamp_s;
  }
  // Scans both logs hold (the same stamp) have identical ranges: the time map is right.
  std::size_t shared = 0;
  std::size_t k = 0;
  for (const LaserScan& scan : intel.scans) {
    while (k < dense.scans.size() && dense.scans[k].stamp_s < scan.stamp_s) ++k;
    if (k == dense.scans.size() || dense.scans[k].stamp_s != scan.stamp_s) continue;
    ++shared;
    ASSERT_EQ(dense.scans[k].ranges_m, scan.ranges_m) << scan.stamp_s;
  }
  EXPECT_GT(shared, 150u);  // PROVENANCE.txt: 174 of the 910 scans are in both
}

}  // namespace
}  // namespace slamsweep::evaluator
