// One map scale: the paper's map metrics count cells (a 1-cell Gaussian, corners 10 cells apart,
// areas of at least 4 cells), so a map is scored on evaluation.map_resolution_m cells whatever cell
// size its program wrote. The same floor mapped at 0.05 m (most programs) and at 0.1 m (tinySLAM and
// vinySLAM) must then score the same corners and enclosed areas.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

#include "evaluator/map_metrics/paper_metrics.h"
#include "evaluator/map_compare/map_resample.h"
#include "evaluator/occupancy_mapping/occupancy_mapper.h"
#include "evaluator/simulation/simulated_sequence.h"
#include "orchestrator/worker/run_metrics.h"

namespace slamsweep::orchestrator {
namespace {

namespace ev = slamsweep::evaluator;

double Metric(const RunMetrics& metrics, const std::string& name) {
  for (const FlatMetric& metric : metrics.metrics) {
    if (metric.metric == name && metric.statistic == "value") return metric.value.value();
  }
  ADD_FAILURE() << "no " << name;
  return NAN;
}

/// A simulated floor's clean scans mapped at the true poses, at `resolution_m`: the same map as two
/// programs that differ only in their cell size would write it.
ev::OccupancyGrid FloorMap(std::uint64_t floor_seed, double resolution_m) {
  ev::SimulationOptions simulation;
  simulation.floor_plan.seed = floor_seed;
  simulation.range_noise = {0.0, 0.0, 0.0};
  const ev::SimulatedSequence floor = ev::SimulateSequence(simulation);
  ev::OccupancyMapperOptions options;
  options.resolution_m = resolution_m;
  return ev::OccupancyMapper(options).Build(floor.scans, floor.ground_truth).grid;
}

// Tolerance: corners within 5 % (at least 2), enclosed areas within 1. Measured on floors 1-3 when
// this was written: corners 40/39, 41/42, 41/42 and enclosed areas 3/2, 1/1, 2/2 (0.05 m map / 0.1 m
// map). Each on its own cells, as before one scale, the 0.05 m maps scored 68, 78 and 76 corners.
TEST(MapScaleTest, TheSameFloorWrittenAtFiveAndTenCentimetresScoresTheSame) {
  EvaluationOptions evaluation;
  evaluation.map_resolution_m = 0.1;  // the coarser map's scale: a finer one cannot add detail
  for (std::uint64_t seed : {1, 2, 3}) {
    const ev::OccupancyGrid fine = FloorMap(seed, 0.05);
    const ev::OccupancyGrid coarse = FloorMap(seed, 0.1);
    MetricInputs fine_inputs, coarse_inputs;
    fine_inputs.map = &fine;
    coarse_inputs.map = &coarse;
    const RunMetrics at_fine = ComputeRunMetrics(evaluation, fine_inputs);
    const RunMetrics at_coarse = ComputeRunMetrics(evaluation, coarse_inputs);
    const double corners_fine = Metric(at_fine, "corners"), corners_coarse = Metric(at_coarse, "corners");
    const double enclosed_fine = Metric(at_fine, "enclosed_areas"),
                 enclosed_coarse = Metric(at_coarse, "enclosed_areas");
    std::cout << "[ scale ] floor " << seed << ": corners " << corners_fine << " / " << corners_coarse
              << ", enclosed areas " << enclosed_fine << " / " << enclosed_coarse << "\n";
    EXPECT_LE(std::abs(corners_fine - corners_coarse), std::max(2.0, 0.05 * corners_coarse)) << "floor " << seed;
    EXPECT_LE(std::abs(enclosed_fine - enclosed_coarse), 1.0) << "floor " << seed;
    EXPECT_EQ(at_fine.details["paper_map"]["resolution_m"], 0.1);
    EXPECT_EQ(at_fine.details["paper_map"]["map_resolution_m"], 0.05);
  }
}

TEST(MapScaleTest, AMapScoredOnFinerCellsThanItWasWrittenAtSaysSo) {
  const ev::OccupancyGrid coarse = FloorMap(1, 0.1);
  MetricInputs inputs;
  inputs.map = &coarse;
  const RunMetrics metrics = ComputeRunMetrics({}, inputs);  // map_resolution_m 0.05
  ASSERT_FALSE(metrics.warnings.empty());
  EXPECT_NE(metrics.warnings.front().find("paper_map: the map's 0.1 m cells are scored on 0.05 m cells"),
            std::string::npos)
      << metrics.warnings.front();
  EXPECT_EQ(metrics.details["paper_map"]["resolution_m"], 0.05);
}

TEST(ResampleKeepingProbabilitiesTest, GreyLevelsAndOneCellWallsSurvive) {
  ev::OccupancyGrid grid(4, 2, 0.1, {1.0, 2.0, 0.0}, 0.2f);
  grid.at(0, 1) = 0.7f;
  grid.at(1, 3) = ev::OccupancyGrid::kUnknown;
  const ev::OccupancyGrid fine = ev::ResampleKeepingProbabilities(grid, 0.05);
  ASSERT_EQ(fine.width, 8);
  ASSERT_EQ(fine.height, 4);
  EXPECT_EQ(fine.origin.x_m, 1.0);
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 8; ++c) EXPECT_EQ(fine.at(r, c), grid.at(r / 2, c / 2)) << r << "," << c;
  }
  // Back to 0.1 m: each cell the highest of its four, the grid as it was.
  const ev::OccupancyGrid back = ev::ResampleKeepingProbabilities(fine, 0.1);
  EXPECT_EQ(back.cells, grid.cells);
  // A one-cell wall of a 0.05 m map stays a wall at 0.1 m.
  ev::OccupancyGrid wall(6, 6, 0.05, {}, 0.0f);
  for (int r = 0; r < 6; ++r) wall.at(r, 3) = 1.0f;
  const ev::OccupancyGrid coarse = ev::ResampleKeepingProbabilities(wall, 0.1);
  for (int r = 0; r < 3; ++r) EXPECT_EQ(coarse.at(r, 1), 1.0f);
  EXPECT_EQ(coarse.at(0, 0), 0.0f);
  EXPECT_EQ(ev::ResampleKeepingProbabilities(wall, 0.05).cells, wall.cells);
}

}  // namespace
}  // namespace slamsweep::orchestrator
