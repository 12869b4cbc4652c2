#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/formats/map/map_server_format.h"
#include "evaluator/formats/trajectory/tum_format.h"
#include "evaluator/sequence_io/sequence_file.h"
#include "tests/cli/run_cli.h"
#include "tests/support/shared_data.h"
#include "tests/support/sparse_carmen_log.h"

namespace slamsweep {
namespace {

using ::testing::HasSubstr;
using testing::RunCli;

std::string Slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

TEST(DataInfoCommandTest, IntelByCatalogNameHasTheCountsOfItsProvenance) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");
  const auto run = RunCli({"data", "info", "intel", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json info = nlohmann::json::parse(run.out);
  // PROVENANCE.txt: FLASER=910 readings=[180] t=[32.907,2683.770].
  EXPECT_EQ(info.at("scans"), 910);
  EXPECT_EQ(info.at("beams"), 180);
  // On the recorded odometry's clock: the scans take their raw readings' stamps, repaired where the
  // stream's stepped back (by up to 0.9 s), so the span is that of the repaired readings.
  EXPECT_NEAR(info.at("duration_s").get<double>(), 2683.770 - 32.907, 1.0);
  EXPECT_EQ(info.at("has_reference"), true);
  EXPECT_EQ(info.at("recorded_odometry"), true);
  EXPECT_EQ(info.at("odometry"), "recorded");
  EXPECT_EQ(info.at("recorded_odometry_readings"), 13631);
  EXPECT_EQ(info.at("relations"), 2984);
  ASSERT_TRUE(info.at("warnings").is_array());
  EXPECT_EQ(info.at("warnings").size(), 1u);  // the repaired reading stamps
  EXPECT_THAT(info.at("warnings").at(0).get<std::string>(), ::testing::HasSubstr("recorded odometry"));

  const auto reference = RunCli({"data", "info", "intel", "--odometry", "reference", "--json"});
  ASSERT_EQ(reference.exit_code, 0) << reference.err;
  const nlohmann::json reference_info = nlohmann::json::parse(reference.out);
  EXPECT_EQ(reference_info.at("recorded_odometry"), false);
  EXPECT_EQ(reference_info.at("recorded_odometry_readings"), 0);
  EXPECT_NEAR(reference_info.at("duration_s").get<double>(), 2683.770 - 32.907, 0.01);
}

TEST(DataInfoCommandTest, RecordedOdometryAskedOfALogWithoutAStreamNamesTheLine) {
  testing::TempDir dir;
  const auto log = testing::WriteFile(dir / "bare.log",
                                      "FLASER 3 1 1 1 0 0 0 0 0 0 1.0 pippo 1.0\n"
                                      "FLASER 3 1 1 1 1 0 0 1 0 0 2.0 pippo 2.0\n");
  const auto recorded = RunCli({"data", "info", log.string(), "--odometry", "recorded", "--json"});
  EXPECT_NE(recorded.exit_code, 0);
  EXPECT_THAT(recorded.err, ::testing::HasSubstr("bare.log:1"));
  // Not asked for explicitly: the logged odometry, and a warning.
  const auto implicit = RunCli({"data", "info", log.string(), "--json"});
  ASSERT_EQ(implicit.exit_code, 0) << implicit.err;
  EXPECT_EQ(nlohmann::json::parse(implicit.out).at("recorded_odometry"), false);
}

TEST(DataInfoCommandTest, Fr079ByPath) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/fr079/freiburg-079-corrected.log.gz");
  const auto run = RunCli({"data", "info", log.string(), "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json info = nlohmann::json::parse(run.out);
  EXPECT_EQ(info.at("scans"), 4791);  // PROVENANCE.txt: FLASER=4791 readings=[360]
  EXPECT_EQ(info.at("beams"), 360);
  // Its ODOM stream logs no backward step; the one warning says the scans' reversals were given back.
  ASSERT_EQ(info.at("warnings").size(), 1u);
  EXPECT_NE(info.at("warnings")[0].get<std::string>().find("without their sign"), std::string::npos);
}

TEST(DataInfoCommandTest, TheIntelLogsSpacingSaysWhichIsDenseEnoughForScanMatching) {
  SLAMSWEEP_REQUIRE_SHARED(raw, "datasets/intel/intel-raw-scans-0-5504.clf.gz");
  SLAMSWEEP_REQUIRE_SHARED(corrected, "datasets/intel/intel-corrected.log.gz");
  // Every scan of the run's first 1,088.6 s, its odometry the FLASER records' odometry fields in file order.
  // Expected values from a short Python reading of those fields (docs/data-density.md), not from slamsweep.
  const auto full = RunCli({"data", "info", "intel-full-rate", "--json"});
  ASSERT_EQ(full.exit_code, 0) << full.err;
  const nlohmann::json dense = nlohmann::json::parse(full.out).at("scan_spacing");
  EXPECT_EQ(dense.at("steps"), 5504);
  EXPECT_NEAR(dense.at("travel_m").at("median").get<double>(), 0.055507, 1e-6);
  EXPECT_NEAR(dense.at("travel_m").at("p95").get<double>(), 0.063280, 1e-6);
  EXPECT_NEAR(dense.at("rotation_rad").at("median").get<double>(), 0.006146, 1e-6);
  EXPECT_NEAR(dense.at("rotation_rad").at("p95").get<double>(), 0.091260, 1e-6);
  EXPECT_EQ(dense.at("too_sparse_for_scan_matching"), false);
  const auto full_text = RunCli({"data", "info", "intel-full-rate"});
  ASSERT_EQ(full_text.exit_code, 0) << full_text.err;
  EXPECT_THAT(full_text.out, HasSubstr("  travel:   0.056 m / 0.063 m\n"));
  EXPECT_THAT(full_text.out, HasSubstr("dense enough for scan matching"));
  EXPECT_THAT(full_text.out, ::testing::Not(HasSubstr("too far apart")));

  // GMapping's 910 keyframes, two thirds of a metre apart: marked, whatever the odometry they are read with.
  const auto keyframes = RunCli({"data", "info", "intel"});
  ASSERT_EQ(keyframes.exit_code, 0) << keyframes.err;
  EXPECT_THAT(keyframes.out, HasSubstr("between consecutive scans (909 steps)"));
  EXPECT_THAT(keyframes.out, HasSubstr("warning: scans too far apart for scan matching: consecutive scans are 0.67 m"));
  const auto logged = RunCli({"data", "info", "intel", "--odometry", "reference", "--json"});
  ASSERT_EQ(logged.exit_code, 0) << logged.err;
  const nlohmann::json sparse = nlohmann::json::parse(logged.out).at("scan_spacing");
  // The corrected log's own FLASER poses and stamps, read the same way in Python.
  EXPECT_NEAR(sparse.at("gap_s").at("median").get<double>(), 3.35, 1e-6);
  EXPECT_NEAR(sparse.at("gap_s").at("p95").get<double>(), 4.83, 1e-6);
  EXPECT_NEAR(sparse.at("travel_m").at("median").get<double>(), 0.670118, 1e-6);
  EXPECT_NEAR(sparse.at("travel_m").at("p95").get<double>(), 1.037998, 1e-6);
  EXPECT_EQ(sparse.at("too_sparse_for_scan_matching"), true);
}

TEST(DataInfoCommandTest, ScanSpacingIsPrintedAndSparseScansAreWarnedOf) {
  testing::TempDir dir;
  const auto log = testing::WriteFile(dir / "sparse.log", testing::SparseCarmenLog());
  const auto json = RunCli({"data", "info", log.string(), "--json"});
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const nlohmann::json spacing = nlohmann::json::parse(json.out).at("scan_spacing");
  EXPECT_EQ(spacing.at("steps"), 4);
  EXPECT_NEAR(spacing.at("gap_s").at("median").get<double>(), testing::kSparseLogMedianGapS, 1e-9);
  EXPECT_NEAR(spacing.at("gap_s").at("p95").get<double>(), testing::kSparseLogP95GapS, 1e-9);
  EXPECT_NEAR(spacing.at("travel_m").at("median").get<double>(), testing::kSparseLogMedianTravelM, 1e-9);
  EXPECT_NEAR(spacing.at("travel_m").at("p95").get<double>(), testing::kSparseLogP95TravelM, 1e-9);
  EXPECT_NEAR(spacing.at("rotation_rad").at("median").get<double>(), testing::kSparseLogMedianRotationRad, 1e-9);
  EXPECT_NEAR(spacing.at("rotation_rad").at("p95").get<double>(), testing::kSparseLogP95RotationRad, 1e-9);
  EXPECT_EQ(spacing.at("motion_from"), "odometry poses at the scans");
  EXPECT_EQ(spacing.at("too_sparse_for_scan_matching"), true);

  const auto text = RunCli({"data", "info", log.string()});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("from the odometry poses at the scans"));
  EXPECT_THAT(text.out, HasSubstr("time gap: 1.500 s / 2.000 s\n"));
  EXPECT_THAT(text.out, HasSubstr("travel:   5.000 m / 10.950 m\n"));
  EXPECT_THAT(text.out, HasSubstr("rotation: 0.150 rad / 0.470 rad\n"));
  EXPECT_THAT(text.out, HasSubstr("warning: scans too far apart for scan matching"));

  // The same path in 1 cm steps is dense, however slowly it was driven (scans 10 s apart).
  std::string dense;
  for (int i = 0; i < 5; ++i) {
    const std::string x = std::to_string(0.01 * i);
    const std::string stamp = std::to_string(10 * i);
    dense += "FLASER 3 1.5 2.5 3.5 " + x + " 0 0 " + x + " 0 0 " + stamp + " host " + stamp + "\n";
  }
  const auto slow = RunCli({"data", "info", testing::WriteFile(dir / "slow.log", dense).string()});
  ASSERT_EQ(slow.exit_code, 0) << slow.err;
  EXPECT_THAT(slow.out, HasSubstr("time gap: 10.000 s / 10.000 s\n"));
  EXPECT_THAT(slow.out, HasSubstr("dense enough for scan matching"));
  EXPECT_THAT(slow.out, ::testing::Not(HasSubstr("warning: scans too far apart")));
}

// A file declared raw: its logged pose is the odometry (not the reference), and the stamps the reader had
// to change are counted.
TEST(DataInfoCommandTest, AFileDeclaredRawHasNoReferenceAndItsStampFactsAreShown) {
  testing::TempDir dir;
  std::string text;
  for (int scan = 0; scan < 100; ++scan) {
    text += "FLASER 180";
    for (int b = 0; b < 180; ++b) text += " 1.5";
    const std::string pose = std::to_string(0.05 * scan) + " 0 0 ";
    // Scan 50's stamp arrived 0.5 s late.
    const double stamp_s = 0.2 * scan + (scan == 50 ? 0.5 : 0.0);
    text += " " + pose + pose + std::to_string(stamp_s) + " host " + std::to_string(stamp_s) + "\n";
  }
  testing::WriteFile(dir / "raw.clf", text);
  const auto raw = RunCli({"data", "info", (dir / "raw.clf").string(), "--ground-truth", "none", "--json"});
  ASSERT_EQ(raw.exit_code, 0) << raw.err;
  const nlohmann::json info = nlohmann::json::parse(raw.out);
  EXPECT_EQ(info.at("has_reference"), false);
  EXPECT_EQ(info.at("recorded_odometry"), true);
  EXPECT_EQ(info.at("stamps").at("outcome"), "retimed");
  EXPECT_EQ(info.at("stamps").at("steps_back"), 1);
  EXPECT_EQ(info.at("stamps").at("changed"), 1);
  EXPECT_NEAR(info.at("duration_s").get<double>(), 19.8, 1e-6);
  // Undeclared, a CARMEN file is read as a corrected log: the logged pose is the reference.
  const auto corrected = RunCli({"data", "info", (dir / "raw.clf").string(), "--json"});
  ASSERT_EQ(corrected.exit_code, 0) << corrected.err;
  EXPECT_EQ(nlohmann::json::parse(corrected.out).at("has_reference"), true);
  EXPECT_EQ(nlohmann::json::parse(corrected.out).at("odometry"), "reference");
  const auto wrong = RunCli({"data", "info", (dir / "raw.clf").string(), "--ground-truth", "raw"});
  EXPECT_EQ(wrong.exit_code, 2);
  EXPECT_THAT(wrong.err,
              HasSubstr("--ground-truth: expected one of corrected_poses, exact, measured, relations_only, none"));
}

// The full-rate intel entry: a raw log read on its own clock, with the relations inside it.
TEST(DataInfoCommandTest, TheFullRateIntelEntryIsReadOnItsOwnClock) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-raw-scans-0-5504.clf.gz");
  SLAMSWEEP_REQUIRE_SHARED(relations, "datasets/intel/intel.relations");
  const auto run = RunCli({"data", "info", "intel-full-rate", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json info = nlohmann::json::parse(run.out);
  EXPECT_EQ(info.at("scans"), 5505);
  // PROVENANCE.txt: the first 1,088.6 s of the run (not one made-up second per scan).
  EXPECT_NEAR(info.at("duration_s").get<double>(), 1088.6, 0.05);
  EXPECT_EQ(info.at("has_reference"), false);
  EXPECT_EQ(info.at("odometry"), "recorded");
  EXPECT_EQ(info.at("relations"), 1033);
  EXPECT_EQ(info.at("relations_outside_log"), 2984 - 1033);
  EXPECT_EQ(info.at("stamps").at("steps_back"), 265);
  EXPECT_EQ(info.at("stamps").at("duplicates"), 0);
  EXPECT_TRUE(info.at("stamps").contains("order_check"));
  for (const nlohmann::json& warning : info.at("warnings")) {
    EXPECT_THAT(warning.get<std::string>(), ::testing::Not(HasSubstr("record order")));
    EXPECT_THAT(warning.get<std::string>(), ::testing::Not(HasSubstr("no odometry stream")));
  }
}

// A raw log has no ODOM stream: the clock fit pairs the relation stamps with the laser records' own.
TEST(DataRelationsClockCommandTest, OnTheRawFullRateLogTheRelationsClockIsTheLogsOwn) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-raw-scans-0-5504.clf.gz");
  SLAMSWEEP_REQUIRE_SHARED(relations, "datasets/intel/intel.relations");
  const auto run = RunCli({"data", "relations-clock", "intel-full-rate", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json fit = nlohmann::json::parse(run.out);
  EXPECT_EQ(fit.at("readings_from"), "laser records");
  EXPECT_EQ(fit.at("readings"), 5505);
  // PROVENANCE.txt: 1,033 relations lie inside the log; ipc = logger + 976052857.337284 is the relations' own
  // clock, so each stamp of those pairs with a scan's exactly, and the map is about the identity there.
  EXPECT_EQ(fit.at("relations_inside"), 1033);
  EXPECT_EQ(fit.at("matched"), fit.at("matched_within_10ms"));
  EXPECT_LT(fit.at("rms_residual_s").get<double>(), 0.001);
  EXPECT_NEAR(fit.at("offset_s").get<double>() + (fit.at("rate").get<double>() - 1.0) * 976053400.0, 0.0, 0.01);
  // The scans' fit, which reads no stamp pairing, lands there too.
  const nlohmann::json& by_scans = fit.at("by_scans");
  EXPECT_NEAR(by_scans.at("offset_s").get<double>() + (by_scans.at("rate").get<double>() - 1.0) * 976053400.0, 0.0,
              0.01);
}

TEST(DataInfoCommandTest, DistinctBeamCountsAreListed) {
  testing::TempDir dir;
  std::string text;
  for (int scan = 0; scan < 3; ++scan) {
    const int beams = scan == 1 ? 361 : 180;
    text += "FLASER " + std::to_string(beams);
    for (int b = 0; b < beams; ++b) text += " 1.5";
    text += " 0 0 0 0 0 0 " + std::to_string(scan + 1) + " host 0\n";
  }
  testing::WriteFile(dir / "mixed.log", text);
  const auto run = RunCli({"data", "info", (dir / "mixed.log").string(), "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json info = nlohmann::json::parse(run.out);
  EXPECT_EQ(info.at("scans"), 3);
  EXPECT_EQ(info.at("beams"), nlohmann::json::array({180, 361}));
  EXPECT_EQ(info.at("duration_s"), 2.0);
}

TEST(DataInfoCommandTest, MissingFileAndUnknownNameExitTwoNamingThem) {
  const auto missing = RunCli({"data", "info", "/nowhere/run.log", "--json"});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_THAT(missing.err, HasSubstr("/nowhere/run.log"));
  const auto unknown = RunCli({"data", "info", "no-such-dataset"});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_THAT(unknown.err, HasSubstr("no-such-dataset"));
  EXPECT_THAT(unknown.err, HasSubstr("intel"));                 // lists what the catalog knows
  const auto absent = RunCli({"data", "info", "mit-killian"});  // only its relations are shipped
  EXPECT_EQ(absent.exit_code, 2);
  EXPECT_THAT(absent.err, HasSubstr("mit-killian.clf is missing"));
  EXPECT_THAT(absent.err, HasSubstr("slamevaluation"));
}

TEST(DataConvertCommandTest, NoisyCarmenIsReproducibleAndRecordsItsNoise) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");
  testing::TempDir dir;
  // Noise drawn around the reference (the corrected path handed as odometry).
  const std::vector<std::string> args = {"data",
                                         "convert",
                                         "intel",
                                         "--odometry",
                                         "reference",
                                         "--to",
                                         "carmen",
                                         "--odometry-noise",
                                         "0.01,0.001,0.01,0.001",
                                         "--drift",
                                         "0.002",
                                         "--range-noise",
                                         "0.02",
                                         "--seed",
                                         "7",
                                         "--reference-out",
                                         (dir / "ref.tum").string(),
                                         "-o"};
  auto first_args = args;
  first_args.push_back((dir / "a.log").string());
  auto second_args = args;
  second_args.push_back((dir / "b.log").string());
  const auto first = RunCli(first_args);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  ASSERT_EQ(RunCli(second_args).exit_code, 0);
  EXPECT_EQ(Slurp(dir / "a.log"), Slurp(dir / "b.log"));

  const nlohmann::json noise = nlohmann::json::parse(Slurp(dir / "a.log.noise.json"));
  EXPECT_EQ(noise.at("seed"), 7);
  EXPECT_EQ(noise.at("odometry_noise").at("alpha2"), 0.001);
  EXPECT_EQ(noise.at("odometry_noise").at("drift_heading_rad_per_m"), 0.002);
  EXPECT_EQ(noise.at("range_noise").at("sigma_m"), 0.02);
  EXPECT_EQ(noise.at("odometry"), "reference");
  EXPECT_EQ(noise.at("odometry_noise_around"), "reference");

  const evaluator::Sequence converted = evaluator::ReadSequence(dir / "a.log");
  const evaluator::Sequence original = evaluator::ReadSequence(log);
  ASSERT_EQ(converted.scans.size(), 910u);
  // A program input: the noisy odometry only. The reference goes to its own file, on request.
  EXPECT_FALSE(converted.reference.has_value());
  const evaluator::Trajectory reference = evaluator::ReadTum(dir / "ref.tum");
  ASSERT_EQ(reference.size(), 910u);
  EXPECT_NEAR((reference.poses().back().position - original.reference->poses().back().position).norm(), 0.0, 1e-6);
  // The odometry starts on the reference and then drifts away.
  EXPECT_EQ(converted.odometry.poses().front().position, original.reference->poses().front().position);
  EXPECT_GT((converted.odometry.poses().back().position - original.reference->poses().back().position).norm(), 0.1);
  EXPECT_NE(converted.scans[5].ranges_m, original.scans[5].ranges_m);
}

TEST(DataConvertCommandTest, TumHoldsTheOdometry) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");
  testing::TempDir dir;
  const auto run = RunCli(
      {"data", "convert", log.string(), "--to", "tum", "--odometry", "reference", "-o", (dir / "intel.tum").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const evaluator::Trajectory tum = evaluator::ReadTum(dir / "intel.tum");
  ASSERT_EQ(tum.size(), 910u);
  // In reference mode the corrected log's odometry is its reference pose: the FLASER odom fields.
  // The first FLASER of the file: odometry 0.600266 -0.0320327 -0.354665 at 32.9068.
  EXPECT_EQ(tum.stamps_s().front(), 32.9068);
  EXPECT_DOUBLE_EQ(tum.poses().front().position.x(), 0.600266);
  EXPECT_NEAR(tum.poses().front().Yaw(), -0.354665, 1e-12);

  // Recorded: one row per FLASER, the robot's odometry at its raw reading. Read off the file: the
  // ODOM line before the first FLASER is "0.698035 -0.0132843 -0.460915 ... 32.9068", after one
  // stamped 33.1085, so its stamp is lifted to 33.1085 + 1 ms (the stamp policy's repair).
  const auto recorded = RunCli({"data", "convert", log.string(), "--to", "tum", "--odometry", "recorded", "-o",
                                (dir / "recorded.tum").string()});
  ASSERT_EQ(recorded.exit_code, 0) << recorded.err;
  const evaluator::Trajectory wheels = evaluator::ReadTum(dir / "recorded.tum");
  ASSERT_EQ(wheels.size(), 910u);
  EXPECT_NEAR(wheels.stamps_s().front(), 33.1095, 1e-9);
  EXPECT_DOUBLE_EQ(wheels.poses().front().position.x(), 0.698035);
  EXPECT_NEAR(wheels.poses().front().Yaw(), -0.460915, 1e-9);
  for (std::size_t i = 1; i < wheels.size(); ++i) ASSERT_GT(wheels.stamps_s()[i], wheels.stamps_s()[i - 1]);
  // It drifts from the corrected path by tens of metres by the end.
  EXPECT_GT((wheels.poses().back().position - tum.poses().back().position).norm(), 30.0);
}

TEST(DataConvertCommandTest, RawlogOfIntelReadsBackWhenMrptIsBuilt) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");
  if (!evaluator::RawlogSupported()) SLAMSWEEP_SKIP_OR_FAIL_IN_CI("MRPT not built");
  testing::TempDir dir;
  const auto run = RunCli({"data", "convert", "intel", "--to", "rawlog", "-o", (dir / "intel.rawlog").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto info = RunCli({"data", "info", (dir / "intel.rawlog").string(), "--json"});
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const nlohmann::json j = nlohmann::json::parse(info.out);
  EXPECT_EQ(j.at("scans"), 910);
  EXPECT_EQ(j.at("beams"), 180);
}

TEST(DataConvertCommandTest, BadOptionsExitTwoNamingTheOption) {
  testing::TempDir dir;
  const auto bad_to = RunCli({"data", "convert", "intel", "--to", "png", "-o", (dir / "x").string()});
  EXPECT_EQ(bad_to.exit_code, 2);
  EXPECT_THAT(bad_to.err, HasSubstr("--to"));
  EXPECT_THAT(bad_to.err, HasSubstr("png"));
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");
  const auto short_noise =
      RunCli({"data", "convert", "intel", "--to", "carmen", "--odometry-noise", "0.1,0.2", "-o", (dir / "x").string()});
  EXPECT_EQ(short_noise.exit_code, 2);
  EXPECT_THAT(short_noise.err, HasSubstr("--odometry-noise"));
  const auto negative =
      RunCli({"data", "convert", "intel", "--to", "carmen", "--range-noise", "-1", "-o", (dir / "x").string()});
  EXPECT_EQ(negative.exit_code, 2);
  EXPECT_THAT(negative.err, HasSubstr("sigma_m"));
  EXPECT_EQ(RunCli({"data", "convert", "intel", "--to", "carmen"}).exit_code, 2);  // no -o
}

TEST(DataMapCommandTest, IntelReferenceMapHasWallsAndFreeSpace) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");
  testing::TempDir dir;
  const auto run = RunCli({"data", "map", "intel", "-o", (dir / "intel.yaml").string(), "--resolution", "0.1"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const evaluator::OccupancyGrid grid = evaluator::ReadMapServer(dir / "intel.yaml");
  EXPECT_DOUBLE_EQ(grid.resolution_m, 0.1);
  std::size_t occupied = 0, free = 0;
  for (float p : grid.cells) {
    if (p == evaluator::OccupancyGrid::kUnknown) continue;
    (p > 0.5f ? occupied : free) += 1;
  }
  EXPECT_GT(occupied, 1000u);
  EXPECT_GT(free, occupied);
  // The Intel lab is about 30 m x 30 m: the map must not be much larger.
  EXPECT_LT(grid.width * grid.resolution_m, 60.0);
}

TEST(DataMapCommandTest, SequenceWithoutReferenceOrFileExitsTwo) {
  testing::TempDir dir;
  const auto missing = RunCli({"data", "map", (dir / "none.log").string(), "-o", (dir / "m.yaml").string()});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_THAT(missing.err, HasSubstr("none.log"));
  // MRPT's sample rawlog (Debian mrpt-common) has odometry but no ground truth.
  const std::filesystem::path sample =
      "/usr/share/mrpt/datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog";
  if (!evaluator::RawlogSupported() || !std::filesystem::exists(sample)) {
    SLAMSWEEP_SKIP_OR_FAIL_IN_CI("no MRPT rawlog support or sample (Debian: libmrpt-obs-dev, mrpt-common)");
  }
  const auto run = RunCli({"data", "map", "mrpt-telecom", "-o", (dir / "m.yaml").string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("mrpt-telecom: the sequence has no reference trajectory"));
}

TEST(DataSimulateCommandTest, WritesFloorPlanSequenceAndTrajectories) {
  testing::TempDir dir;
  const auto run = RunCli({"data", "simulate", "-o", (dir / "sim").string(), "--scans", "40", "--seed", "3"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* file :
       {"floor_plan.yaml", "floor_plan.pgm", "sequence.log", "ground_truth.tum", "odometry.tum", "simulation.json"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / "sim" / file)) << file;
  }
  EXPECT_EQ(std::filesystem::exists(dir / "sim" / "sequence.rawlog"), evaluator::RawlogSupported());
  const evaluator::Trajectory truth = evaluator::ReadTum(dir / "sim" / "ground_truth.tum");
  const evaluator::Trajectory odometry = evaluator::ReadTum(dir / "sim" / "odometry.tum");
  EXPECT_EQ(truth.size(), 40u);
  EXPECT_EQ(odometry.size(), 40u);
  const auto info = RunCli({"data", "info", (dir / "sim" / "sequence.log").string(), "--json"});
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_EQ(nlohmann::json::parse(info.out).at("scans"), 40);
  const nlohmann::json spec = nlohmann::json::parse(Slurp(dir / "sim" / "simulation.json"));
  EXPECT_EQ(spec.at("noise_seed"), 3);
  // The same seed gives the same files.
  ASSERT_EQ(RunCli({"data", "simulate", "-o", (dir / "again").string(), "--scans", "40", "--seed", "3"}).exit_code, 0);
  EXPECT_EQ(Slurp(dir / "sim" / "sequence.log"), Slurp(dir / "again" / "sequence.log"));
}

}  // namespace
}  // namespace slamsweep
