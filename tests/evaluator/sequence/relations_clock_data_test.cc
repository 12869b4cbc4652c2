// The relations clocks in the shipped catalog, checked on the shared logs.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "evaluator/formats/trajectory/relations_format.h"
#include "evaluator/sequence/carmen_sequence.h"
#include "evaluator/catalog/catalog.h"
#include "evaluator/sequence/relations_clock.h"
#include "evaluator/trajectory_metrics/relations_metric.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

const CatalogEntry& ShippedEntry(const std::string& name) {
  // Not __FILE__: compiler caches may make it relative to the build folder.
  static const Catalog catalog = ReadCatalog(std::filesystem::path(SLAMSWEEP_SOURCE_DIR) / "configs" / "datasets.yaml");
  return FindCatalogEntry(catalog, name);
}

/// A catalog log read with its recorded odometry, its relations on their own clock, and the catalog's
/// map of that clock as the offset at the relations' middle stamp.
struct ClockCase {
  Relations relations;
  Sequence run;
  const CatalogEntry* entry = nullptr;
  double middle_s = 0.0;
  double catalog_offset_s = 0.0;
};

/// The offset a map (t_log = rate * t + offset) applies at relation time `t_s`.
double OffsetAt(double offset_s, double rate, double t_s) { return offset_s + (rate - 1.0) * t_s; }

ClockCase LoadClockCase(const std::string& name, const std::filesystem::path& log,
                        const std::filesystem::path& relations_path) {
  ClockCase loaded;
  loaded.relations = ReadRelations(relations_path);
  CarmenSequenceOptions options;
  options.odometry = OdometryMode::kRecorded;
  loaded.run = ReadCarmenSequence(log, options);
  loaded.entry = &ShippedEntry(name);
  loaded.middle_s = 0.5 * (loaded.relations.front().t1_s + loaded.relations.back().t1_s);
  loaded.catalog_offset_s = OffsetAt(loaded.entry->relations_offset_s, loaded.entry->relations_rate, loaded.middle_s);
  return loaded;
}

// intel's readings carry the laser's clock (every relation stamp lies within 10 ms of one), so its
// stamp fit is exact: the scans' fit, which never reads a stamp pairing, must land on it.
TEST(RelationsClockDataTest, OnIntelTheScansFitLandsOnTheExactStampFit) {
  SLAMSWEEP_REQUIRE_SHARED(relations_path, "datasets/intel/intel.relations");
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");
  const ClockCase intel = LoadClockCase("intel", log, relations_path);
  const double stamps = intel.catalog_offset_s;
  const SearchedClockFit fit =
      FitRelationsClockByScans(intel.relations, intel.run.scans, intel.run.odometry_readings, stamps + 0.3);
  EXPECT_NEAR(OffsetAt(fit.offset_s, fit.rate, intel.middle_s), stamps, 0.005);
  EXPECT_LT(fit.disagreement, fit.next_best_disagreement);
}

/// The relations error (m) of `path` with the relations mapped by t_log = rate * t + offset.
double RelationsErrorM(const Trajectory& path, const Relations& relations, double offset_s, double rate) {
  Relations mapped = relations;
  for (Relation& relation : mapped) {
    relation.t1_s = rate * relation.t1_s + offset_s;
    relation.t2_s = rate * relation.t2_s + offset_s;
  }
  return RelationsMetric(RelationsOptions{}).Compute(path, mapped).translation_abs_mean_m;
}

// fr079's reading stamps jitter, so its map comes from the scans; the odometry's turns put it 0.13 s
// early (the odometry lags the laser), which the catalog must not take.
TEST(RelationsClockDataTest, Fr079TakesTheScansFitNotTheLaggingOdometrysFit) {
  SLAMSWEEP_REQUIRE_SHARED(relations_path, "datasets/fr079/fr079.relations");
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/fr079/freiburg-079-corrected.log.gz");
  const ClockCase fr079 = LoadClockCase("fr079", log, relations_path);
  const double catalog = fr079.catalog_offset_s;
  const SearchedClockFit by_odometry = FitRelationsClockByOdometry(fr079.relations, fr079.run.odometry_readings);
  const double odometry = OffsetAt(by_odometry.offset_s, by_odometry.rate, fr079.middle_s);
  const SearchedClockFit by_scans =
      FitRelationsClockByScans(fr079.relations, fr079.run.scans, fr079.run.odometry_readings, odometry);
  EXPECT_NEAR(OffsetAt(by_scans.offset_s, by_scans.rate, fr079.middle_s), catalog, 0.002);
  EXPECT_NEAR(by_scans.rate, fr079.entry->relations_rate, 1e-6);
  EXPECT_GT(catalog - odometry, 0.1);
  EXPECT_LT(by_scans.disagreement, by_scans.next_best_disagreement);
  // A check from outside the fit: the corrected log, which no fit reads, agrees with the relations
  // better under the catalog's map than under the odometry's (measured: 0.059 against 0.093 m).
  ASSERT_TRUE(fr079.run.reference.has_value());
  EXPECT_LT(RelationsErrorM(*fr079.run.reference, fr079.relations, fr079.entry->relations_offset_s,
                            fr079.entry->relations_rate),
            0.8 * RelationsErrorM(*fr079.run.reference, fr079.relations, by_odometry.offset_s, by_odometry.rate));
}

}  // namespace
}  // namespace slamsweep::evaluator
