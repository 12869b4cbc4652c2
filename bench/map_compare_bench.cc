// Goal: a 2000 x 2000 map pair compared in under 50 ms on one core.
#include <benchmark/benchmark.h>

#include <random>

#include "evaluator/map_compare/map_compare.h"

namespace {

using slamsweep::evaluator::OccupancyGrid;

/// A 2000 x 2000 floor of rooms: walls every 100 cells with doors, free elsewhere, unknown border.
OccupancyGrid Rooms(double shift_m) {
  OccupancyGrid grid(2000, 2000, 0.05, {shift_m, 0.0, 0.0});
  for (int r = 50; r < 1950; ++r) {
    for (int c = 50; c < 1950; ++c) {
      const bool wall = (r % 100 == 0 && c % 100 > 20) || (c % 100 == 0 && r % 100 > 20);
      grid.at(r, c) = wall ? 1.0f : 0.0f;
    }
  }
  return grid;
}

void BM_CompareMaps2000(benchmark::State& state) {
  const OccupancyGrid reference = Rooms(0.0);
  const OccupancyGrid estimate = Rooms(0.1);
  slamsweep::evaluator::MapCompareOptions options;
  for (auto _ : state) benchmark::DoNotOptimize(slamsweep::evaluator::CompareMaps(estimate, reference, options));
}
BENCHMARK(BM_CompareMaps2000)->Unit(benchmark::kMillisecond);

void BM_CompareMaps2000WithIcp(benchmark::State& state) {
  const OccupancyGrid reference = Rooms(0.0);
  const OccupancyGrid estimate = Rooms(0.1);
  slamsweep::evaluator::MapCompareOptions options;
  options.refine_with_icp = true;
  for (auto _ : state) benchmark::DoNotOptimize(slamsweep::evaluator::CompareMaps(estimate, reference, options));
}
BENCHMARK(BM_CompareMaps2000WithIcp)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
