// The relations clocks in the shipped catalog, checked on the shared logs.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "evaluator/formats/trajectory/relations_format.h"
#include "evaluator/sequence/carmen_sequence.h"
#include "evaluator/sequence/catalog.h"
#include "evaluator/sequence/relations_clock.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

const CatalogEntry& ShippedEntry(const std::string& name) {
  // Not __FILE__: compiler caches may make it relative to the build folder.
  static const Catalog catalog = ReadCatalog(std::filesystem::path(SLAMSWEEP_SOURCE_DIR) / "configs" / "datasets.yaml");
  return FindCatalogEntry(catalog, name);
}

Sequence RecordedRun(const std::filesystem::path& log) {
  CarmenSequenceOptions options;
  options.odometry = OdometryMode::kRecorded;
  return ReadCarmenSequence(log, options);
}

/// The offset a map (t_log = rate * t + offset) applies at relation time `t_s`.
double OffsetAt(double offset_s, double rate, double t_s) { return offset_s + (rate - 1.0) * t_s; }

double MiddleStamp(const Relations& relations) { return 0.5 * (relations.front().t1_s + relations.back().t1_s); }

// intel's readings carry the laser's clock (every relation stamp lies within 10 ms of one), so its
// stamp fit is exact: the scans' fit, which never reads a stamp pairing, must land on it.
TEST(RelationsClockDataTest, OnIntelTheScansFitLandsOnTheExactStampFit) {
  SLAMSWEEP_REQUIRE_SHARED(relations_path, "datasets/intel/intel.relations");
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");
  const Relations relations = ReadRelations(relations_path);
  const Sequence run = RecordedRun(log);
  const CatalogEntry& entry = ShippedEntry("intel");
  const double middle = MiddleStamp(relations);
  const double stamps = OffsetAt(entry.relations_offset_s, entry.relations_rate, middle);
  const SearchedClockFit fit = FitRelationsClockByScans(relations, run.scans, run.odometry_readings, stamps + 0.3);
  EXPECT_NEAR(OffsetAt(fit.offset_s, fit.rate, middle), stamps, 0.005);
  EXPECT_LT(fit.disagreement, fit.next_best_disagreement);
}

// fr079's reading stamps jitter, so its map comes from the scans; the odometry's turns put it 0.13 s
// early (the odometry lags the laser), which the catalog must not take.
TEST(RelationsClockDataTest, Fr079TakesTheScansFitNotTheLaggingOdometrysFit) {
  SLAMSWEEP_REQUIRE_SHARED(relations_path, "datasets/fr079/fr079.relations");
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/fr079/freiburg-079-corrected.log.gz");
  const Relations relations = ReadRelations(relations_path);
  const Sequence run = RecordedRun(log);
  const CatalogEntry& entry = ShippedEntry("fr079");
  const double middle = MiddleStamp(relations);
  const double catalog = OffsetAt(entry.relations_offset_s, entry.relations_rate, middle);
  const SearchedClockFit by_odometry = FitRelationsClockByOdometry(relations, run.odometry_readings);
  const double odometry = OffsetAt(by_odometry.offset_s, by_odometry.rate, middle);
  const SearchedClockFit by_scans = FitRelationsClockByScans(relations, run.scans, run.odometry_readings, odometry);
  EXPECT_NEAR(OffsetAt(by_scans.offset_s, by_scans.rate, middle), catalog, 0.002);
  EXPECT_NEAR(by_scans.rate, entry.relations_rate, 1e-6);
  EXPECT_GT(catalog - odometry, 0.1);
  EXPECT_LT(by_scans.disagreement, by_scans.next_best_disagreement);
}

}  // namespace
}  // namespace slamsweep::evaluator
