// Speed targets of the trajectory metrics (Release build, one core):
//   APE with se3 alignment on 1,000,000 poses < 1 s; RPE with a 1 m delta on 1,000,000 poses < 1 s.
// The trajectories are generated here: a 10 Hz, ~1 m/s wandering drive (reference) and a drifting,
// noisy, rigidly displaced copy with +-3 ms stamp jitter (estimate), so that association, alignment
// and pair selection all do real work.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "evaluator/trajectory_metrics/ape.h"
#include "evaluator/trajectory_metrics/association.h"
#include "evaluator/trajectory_metrics/rpe.h"

namespace slamsweep::evaluator {
namespace {

constexpr std::size_t kPoses = 1'000'000;

struct Pair {
  Trajectory reference;
  Trajectory estimate;
};

const Pair& Trajectories() {
  static const Pair pair = [] {
    std::mt19937_64 random(42);
    std::normal_distribution<double> noise_m(0.0, 0.02);
    std::normal_distribution<double> noise_rad(0.0, 0.002);
    std::uniform_real_distribution<double> jitter_s(-0.003, 0.003);
    const Eigen::Quaterniond offset_rotation(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()));
    const Eigen::Vector3d offset_translation(5.0, -3.0, 0.0);
    Pair out;
    out.reference.Reserve(kPoses);
    out.estimate.Reserve(kPoses);
    double x = 0.0;
    double y = 0.0;
    double yaw = 0.0;
    for (std::size_t i = 0; i < kPoses; ++i) {
      const double t = 0.1 * static_cast<double>(i);
      yaw += 0.02 * std::sin(0.01 * t) + 0.01 * std::sin(0.0007 * t);
      x += 0.1 * std::cos(yaw);
      y += 0.1 * std::sin(yaw);
      const Pose truth = Pose::Planar(x, y, yaw);
      out.reference.Add(t, truth);
      Pose estimate = Pose::Planar(x * 1.001 + noise_m(random), y + noise_m(random), yaw + noise_rad(random));
      estimate.position = offset_rotation * estimate.position + offset_translation;
      estimate.orientation = offset_rotation * estimate.orientation;
      out.estimate.Add(t + jitter_s(random), estimate);
    }
    return out;
  }();
  return pair;
}

void BM_Associate(benchmark::State& state) {
  const Pair& data = Trajectories();
  for (auto _ : state) {
    benchmark::DoNotOptimize(Associate(data.reference, data.estimate, AssociationOptions{}));
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kPoses));
}
BENCHMARK(BM_Associate)->Unit(benchmark::kMillisecond);

void BM_ApeSe3(benchmark::State& state) {
  const Pair& data = Trajectories();
  ApeOptions options;
  options.alignment.mode = AlignmentMode::kSe3;
  const Ape ape(options);
  for (auto _ : state) {
    const MetricResult result = ape.Compute(data.reference, data.estimate);
    benchmark::DoNotOptimize(result.statistics.rmse);
    state.counters["pairs"] = static_cast<double>(result.pairs);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kPoses));
}
BENCHMARK(BM_ApeSe3)->Unit(benchmark::kMillisecond);

void BM_RpeOneMetre(benchmark::State& state) {
  const Pair& data = Trajectories();
  RpeOptions options;
  options.delta = 1.0;
  options.delta_unit = DeltaUnit::kMeters;
  const Rpe rpe(options);
  for (auto _ : state) {
    const MetricResult result = rpe.Compute(data.reference, data.estimate);
    benchmark::DoNotOptimize(result.statistics.rmse);
    state.counters["rpe_pairs"] = static_cast<double>(result.statistics.n);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kPoses));
}
BENCHMARK(BM_RpeOneMetre)->Unit(benchmark::kMillisecond);

void BM_RpeOneMetreAllPairs(benchmark::State& state) {
  const Pair& data = Trajectories();
  RpeOptions options;
  options.delta = 1.0;
  options.delta_unit = DeltaUnit::kMeters;
  options.all_pairs = true;
  const Rpe rpe(options);
  for (auto _ : state) {
    const MetricResult result = rpe.Compute(data.reference, data.estimate);
    benchmark::DoNotOptimize(result.statistics.rmse);
    state.counters["rpe_pairs"] = static_cast<double>(result.statistics.n);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kPoses));
}
BENCHMARK(BM_RpeOneMetreAllPairs)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace slamsweep::evaluator

BENCHMARK_MAIN();
