// Speed of handout steps 1-3 (threshold, border tracing, polygons) on 4000 x 4000 maps.
// Target: Vectorize under 200 ms per map.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstddef>
#include <opencv2/imgcodecs.hpp>
#include <random>
#include <string>

#include "evaluator/borders/border_tracing.h"
#include "evaluator/borders/threshold.h"
#include "evaluator/borders/vector_map.h"
#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::evaluator {
namespace {

constexpr int kSide = 4000;

// The real ICP map (1500 x 1760 cells) tiled to 4000 x 4000; 205 = unknown, p = (255 - v) / 255.
// Empty when the shared file is missing.
const OccupancyGrid& TiledTelecom() {
  static const OccupancyGrid grid = [] {
    const cv::Mat image =
        cv::imread(std::string(SLAMSWEEP_SHARED_DIR) + "/reference/maps/telecom_icp.pgm", cv::IMREAD_UNCHANGED);
    if (image.empty() || image.type() != CV_8UC1) return OccupancyGrid{};
    OccupancyGrid tiled(kSide, kSide, 0.05);
    for (int row = 0; row < kSide; ++row) {
      const unsigned char* source = image.ptr<unsigned char>(row % image.rows);
      for (int col = 0; col < kSide; ++col) {
        const int v = source[col % image.cols];
        tiled.at(row, col) = v == 205 ? OccupancyGrid::kUnknown : static_cast<float>(255 - v) / 255.0f;
      }
    }
    return tiled;
  }();
  return grid;
}

// A synthetic building: 25 x 25 rooms of ~160 cells with 3-cell walls, a door in most walls,
// furniture blocks and sensor clutter (scattered single cells and short streaks) inside, the
// outside unknown, and soft (p = 0.6) wall ends where a real SLAM map blurs.
const OccupancyGrid& SyntheticBuilding() {
  static const OccupancyGrid grid = [] {
    OccupancyGrid map(kSide, kSide, 0.05, {}, 0.0f);
    std::mt19937 random(7);
    std::uniform_int_distribution<int> any(0, kSide - 1);
    const int room = 160;
    auto fill = [&map](int row0, int col0, int rows, int cols, float p) {
      for (int r = std::max(row0, 0); r < std::min(row0 + rows, kSide); ++r) {
        for (int c = std::max(col0, 0); c < std::min(col0 + cols, kSide); ++c) map.at(r, c) = p;
      }
    };
    fill(0, 0, kSide, 100, OccupancyGrid::kUnknown);
    fill(0, 0, 100, kSide, OccupancyGrid::kUnknown);
    for (int k = 100; k < kSide; k += room) {
      fill(k, 100, 3, kSide - 100, 1.0f);  // horizontal wall
      fill(100, k, kSide - 100, 3, 1.0f);  // vertical wall
    }
    for (int r = 100; r + room < kSide; r += room) {
      for (int c = 100; c + room < kSide; c += room) {
        if (random() % 5 != 0) fill(r, c + 40 + static_cast<int>(random() % 60), 3, 18, 0.0f);  // door north
        if (random() % 5 != 0) fill(r + 40 + static_cast<int>(random() % 60), c, 18, 3, 0.0f);  // door west
        for (int f = 0; f < 3; ++f) {                                                           // furniture
          fill(r + 10 + static_cast<int>(random() % 120), c + 10 + static_cast<int>(random() % 120),
               5 + static_cast<int>(random() % 20), 5 + static_cast<int>(random() % 20), 0.9f);
        }
      }
    }
    for (int i = 0; i < 200000; ++i) map.at(any(random), any(random)) = 1.0f;  // speckle
    for (int i = 0; i < 20000; ++i) fill(any(random), any(random), 1, 2 + static_cast<int>(random() % 8), 0.8f);
    for (int i = 0; i < 20000; ++i) fill(any(random), any(random), 2, 2, 0.6f);
    return map;
  }();
  return grid;
}

void ReportCounters(benchmark::State& state, const VectorMap& map) {
  state.counters["obstacles"] = static_cast<double>(map.obstacle_count);
  state.counters["holes"] = static_cast<double>(map.hole_count);
  state.counters["vertices"] = static_cast<double>(map.vertex_count);
  state.counters["border_km"] = map.border_length_m / 1000.0;
  state.counters["vector_MB"] = static_cast<double>(map.vector_bytes) / 1e6;
  state.counters["raster_MB"] = static_cast<double>(map.raster_bytes) / 1e6;
}

void BM_VectorizeTelecomTiled(benchmark::State& state) {
  const OccupancyGrid& grid = TiledTelecom();
  if (grid.cells.empty()) {
    state.SkipWithError("telecom_icp.pgm missing under SLAMSWEEP_SHARED_DIR/reference/maps");
    return;
  }
  const VectorizeOptions options{static_cast<double>(state.range(0)), 1.0};
  VectorMap map;
  for (auto _ : state) {
    map = Vectorize(grid, options);
    benchmark::DoNotOptimize(map.vertex_count);
  }
  ReportCounters(state, map);
}
BENCHMARK(BM_VectorizeTelecomTiled)->Arg(75)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

void BM_VectorizeSyntheticBuilding(benchmark::State& state) {
  const OccupancyGrid& grid = SyntheticBuilding();
  const VectorizeOptions options{static_cast<double>(state.range(0)), 1.0};
  VectorMap map;
  for (auto _ : state) {
    map = Vectorize(grid, options);
    benchmark::DoNotOptimize(map.vertex_count);
  }
  ReportCounters(state, map);
}
BENCHMARK(BM_VectorizeSyntheticBuilding)->Arg(75)->Arg(0)->Unit(benchmark::kMillisecond);

// The parts on their own, to see where the time goes.
void BM_ThresholdOnly(benchmark::State& state) {
  const OccupancyGrid& grid = SyntheticBuilding();
  for (auto _ : state) benchmark::DoNotOptimize(Threshold(grid, 75.0).cells.data());
}
BENCHMARK(BM_ThresholdOnly)->Unit(benchmark::kMillisecond);

void BM_TraceBordersOnly(benchmark::State& state) {
  const BinaryGrid binary = Threshold(SyntheticBuilding(), 75.0);
  std::size_t borders = 0;
  for (auto _ : state) {
    const BorderTracing tracing = TraceBorders(binary);  // includes copying the 16 MB grid
    borders = tracing.borders.size();
    benchmark::DoNotOptimize(borders);
  }
  state.counters["borders"] = static_cast<double>(borders);
}
BENCHMARK(BM_TraceBordersOnly)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace slamsweep::evaluator

BENCHMARK_MAIN();
