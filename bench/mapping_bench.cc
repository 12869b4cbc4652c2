// Speed targets of evaluator/mapping (see the "Sequences" issue):
// - 5,000 scans x 360 beams into a 2000 x 2000 map in under 1 s on one core;
// - the 50 stage maps of an animation in at most 3 x the time of the final map alone.
// Two workloads, both mapped into a fixed 2000 x 2000 grid of 0.05 m cells:
// - fr079: the real Freiburg building 079 log (4,791 scans x 360 beams, mean return ~2.7 m),
//   read from the shared datasets folder;
// - halls: 5,000 scans x 360 beams simulated in a generated ~100 x 100 m floor plan of large
//   halls, spread evenly along the tour, so that beams are about three times as long (harder).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/occupancy_mapping/occupancy_mapper.h"
#include "evaluator/sequence/carmen_sequence.h"
#include "evaluator/occupancy_mapping/scan_beams.h"
#include "evaluator/simulation/floor_plan.h"
#include "evaluator/simulation/laser_simulator.h"
#include "evaluator/simulation/path_generator.h"

namespace slamsweep::evaluator {
namespace {

constexpr int kMapCells = 2000;
constexpr double kResolutionM = 0.05;
constexpr std::size_t kStageCount = 50;

struct Workload {
  std::vector<LaserScan> scans;
  std::vector<Pose> poses;
  std::vector<PlacedScan> placed;
  OccupancyMapperOptions options;
  double mean_beam_cells = 0.0;
  std::string error;
};

// Places the scans in a 2000 x 2000 extent centred on the robot's path and measures the mean
// length of a traced beam.
void Finish(Workload& w) {
  w.placed = PlaceScans(w.scans, w.poses);
  double min_x = 1e300, max_x = -1e300, min_y = 1e300, max_y = -1e300;
  for (const Pose& pose : w.poses) {
    min_x = std::min(min_x, pose.position.x());
    max_x = std::max(max_x, pose.position.x());
    min_y = std::min(min_y, pose.position.y());
    max_y = std::max(max_y, pose.position.y());
  }
  const double half_m = 0.5 * kMapCells * kResolutionM;
  w.options.resolution_m = kResolutionM;
  w.options.fixed_extent =
      GridExtent{GridOrigin{std::floor((0.5 * (min_x + max_x) - half_m) / kResolutionM) * kResolutionM,
                            std::floor((0.5 * (min_y + max_y) - half_m) / kResolutionM) * kResolutionM, 0.0},
                 kMapCells, kMapCells};
  double cells = 0.0;
  std::size_t beams = 0;
  for (const LaserScan& scan : w.scans) {
    for (float range : scan.ranges_m) {
      cells += UseBeam(scan, range, w.options.max_range_m, w.options.no_return_range_m).length_m / kResolutionM;
      ++beams;
    }
  }
  w.mean_beam_cells = cells / static_cast<double>(beams);
}

// The real fr079 log through the project's own CARMEN reader; the corrected poses place the scans.
Workload LoadFr079() {
  Workload w;
  const std::filesystem::path path =
      std::filesystem::path(SLAMSWEEP_SHARED_DIR) / "datasets/fr079/freiburg-079-corrected.log.gz";
  try {
    Sequence sequence = ReadCarmenSequence(path);
    w.scans = std::move(sequence.scans);
    w.poses = sequence.reference ? sequence.reference->poses() : sequence.odometry.poses();
  } catch (const InputError& error) {
    w.error = error.what();
    return w;
  }
  Finish(w);
  return w;
}

Workload SimulateHalls() {
  FloorPlanOptions plan_options;
  plan_options.rooms_per_side = 8;
  plan_options.room_width_m = 12.0;
  plan_options.room_depth_m = 46.0;
  plan_options.corridor_width_m = 4.0;
  plan_options.clutter_per_room = 12;
  plan_options.clutter_max_size_m = 1.5;
  const FloorPlan plan = GenerateFloorPlan(plan_options);
  const Trajectory tour = FollowWaypoints(TourWaypoints(plan), PathOptions{});
  Workload w;
  const LaserOptions laser;  // 360 beams over 360 degrees, 20 m
  constexpr std::size_t kScans = 5000;
  for (std::size_t k = 0; k < kScans; ++k) {
    const std::size_t index = k * (tour.size() - 1) / (kScans - 1);
    w.poses.push_back(tour.poses()[index]);
    w.scans.push_back(SimulateScan(plan.grid, w.poses.back(), tour.stamps_s()[index], laser));
  }
  Finish(w);
  return w;
}

const Workload& Fr079() {
  static const Workload workload = LoadFr079();
  return workload;
}

const Workload& Halls() {
  static const Workload workload = SimulateHalls();
  return workload;
}

const Workload* Get(benchmark::State& state, bool real) {
  const Workload& w = real ? Fr079() : Halls();
  if (!w.error.empty()) {
    state.SkipWithError(w.error.c_str());
    return nullptr;
  }
  return &w;
}

void SetCounters(benchmark::State& state, const Workload& w) {
  state.counters["scans"] = static_cast<double>(w.scans.size());
  state.counters["beams_per_scan"] = static_cast<double>(w.scans.front().BeamCount());
  state.counters["mean_beam_cells"] = w.mean_beam_cells;
}

void FinalMap(benchmark::State& state, bool real, bool fixed_extent) {
  const Workload* w = Get(state, real);
  if (w == nullptr) return;
  OccupancyMapperOptions options = w->options;
  if (!fixed_extent) options.fixed_extent.reset();
  const OccupancyMapper mapper(options);
  for (auto _ : state) {
    OccupancyGrid map = mapper.Build(w->placed);
    benchmark::DoNotOptimize(map.cells.data());
  }
  SetCounters(state, *w);
}

void StageMaps(benchmark::State& state, bool real) {
  const Workload* w = Get(state, real);
  if (w == nullptr) return;
  const OccupancyMapper mapper(w->options);
  const std::vector<std::size_t> ends = EvenlySpacedStages(w->placed.size(), kStageCount);
  for (auto _ : state) {
    float checksum = 0.0f;
    mapper.RenderStages(w->placed, ends,
                        [&](const MapStage& stage) { checksum += stage.grid.cells[stage.grid.cells.size() / 2]; });
    benchmark::DoNotOptimize(checksum);
  }
  SetCounters(state, *w);
  state.counters["stages"] = static_cast<double>(ends.size());
}

void BM_FinalMap_Fr079_2000x2000(benchmark::State& state) { FinalMap(state, true, true); }
void BM_StageMaps50_Fr079_2000x2000(benchmark::State& state) { StageMaps(state, true); }
void BM_FinalMap_Fr079_ComputedExtent(benchmark::State& state) { FinalMap(state, true, false); }
void BM_FinalMap_Halls_2000x2000(benchmark::State& state) { FinalMap(state, false, true); }
void BM_StageMaps50_Halls_2000x2000(benchmark::State& state) { StageMaps(state, false); }

BENCHMARK(BM_FinalMap_Fr079_2000x2000)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_StageMaps50_Fr079_2000x2000)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_FinalMap_Fr079_ComputedExtent)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_FinalMap_Halls_2000x2000)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_StageMaps50_Halls_2000x2000)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace
}  // namespace slamsweep::evaluator

BENCHMARK_MAIN();
