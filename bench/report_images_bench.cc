// Speed of the report's artwork: plots (one gnuplot process for many plots), map-building GIFs,
// thumbnails and trajectory overlays. Inputs are synthetic, made once in a temporary folder.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <random>
#include <string>
#include <vector>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/formats/map/map_server_format.h"
#include "evaluator/formats/trajectory/tum_format.h"
#include "report/images/stages_gif.h"
#include "report/images/thumbnail.h"
#include "report/images/trajectory_overlay.h"
#include "report/plots/metric_plot.h"

namespace {

namespace fs = std::filesystem;
using namespace slamsweep;

fs::path WorkDir() {
  static const fs::path dir = [] {
    fs::path path = fs::temp_directory_path() / ("slamsweep-report-images-bench-" + std::to_string(::getpid()));
    fs::create_directories(path);
    return path;
  }();
  return dir;
}

/// A 1000 x 1000 map of rooms being explored: stage k shows the part within a radius that grows
/// with k, as a SLAM run's stage maps do; walls carry a little noise, like real scans.
cv::Mat StageMap(int stage, int stages) {
  cv::Mat map(1000, 1000, CV_8UC1, cv::Scalar(205));
  const int radius = 80 + 420 * (stage + 1) / stages;
  cv::circle(map, {500, 500}, radius, cv::Scalar(254), cv::FILLED);
  std::mt19937 random(static_cast<unsigned>(stage));
  for (int wall = 100; wall < 1000; wall += 150) {
    for (int t = 0; t < 1000; ++t) {
      const int jitter = static_cast<int>(random() % 3) - 1;
      if (std::hypot(wall - 500, t - 500) < radius) map.at<uchar>(t, wall + jitter) = 0;
      if (std::hypot(t - 500, wall - 500) < radius) map.at<uchar>(wall + jitter, t) = 0;
    }
  }
  return map;
}

const std::vector<fs::path>& StagePaths() {
  static const std::vector<fs::path> paths = [] {
    std::vector<fs::path> result;
    for (int k = 0; k < 24; ++k) {
      result.push_back(WorkDir() / ("stage_" + std::to_string(k) + ".png"));
      cv::imwrite(result.back().string(), StageMap(k, 24));
    }
    return result;
  }();
  return paths;
}

void BM_MetricPlots50x20(benchmark::State& state) {
  std::vector<report::MetricPlotJob> jobs;
  std::mt19937 random(1);
  std::lognormal_distribution<double> value(-1.0, 0.5);
  for (int p = 0; p < 50; ++p) {
    // Built whole rather than assigned field by field: GCC 12 at -O3 warns falsely (-Wrestrict)
    // on assigning a short literal to a std::string member here.
    report::MetricPlot plot{.title = "metric " + std::to_string(p), .y_label = std::string(1, 'm'), .series = {}};
    for (int a = 0; a < 4; ++a) {
      report::MetricSeries series{"algorithm-" + std::to_string(a), {}};
      for (int i = 0; i < 5; ++i) series.values.push_back(value(random));
      plot.series.push_back(series);
    }
    jobs.push_back({plot, WorkDir() / ("plot_" + std::to_string(p) + ".png")});
  }
  for (auto _ : state) report::WriteMetricPlots(jobs);
  state.counters["plots_per_s"] = benchmark::Counter(50.0 * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_MetricPlots50x20)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();

void BM_StagesGif100x24(benchmark::State& state) {
  const auto& stages = StagePaths();
  std::size_t bytes = 0;
  for (auto _ : state) {
    for (int g = 0; g < 100; ++g) {
      const fs::path gif = WorkDir() / ("map_" + std::to_string(g) + ".gif");
      report::WriteStagesGif(stages, gif, {});
      bytes = fs::file_size(gif);
    }
  }
  state.counters["gif_bytes"] = static_cast<double>(bytes);
  state.counters["gifs_per_s"] = benchmark::Counter(100.0 * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_StagesGif100x24)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

void BM_Thumbnail(benchmark::State& state) {
  const fs::path map = StagePaths().back();
  for (auto _ : state) report::WriteThumbnail(map, WorkDir() / "thumb.png", 240);
}
BENCHMARK(BM_Thumbnail)->Unit(benchmark::kMillisecond);

void BM_TrajectoryOverlay(benchmark::State& state) {
  // The last stage as a map_server map (0.05 m cells) and a 2,000-pose loop with its reference.
  const cv::Mat image = StageMap(23, 24);
  evaluator::OccupancyGrid grid(1000, 1000, 0.05, {-25.0, -25.0, 0.0});
  for (int r = 0; r < 1000; ++r) {
    for (int c = 0; c < 1000; ++c) {
      const uchar v = image.at<uchar>(r, c);
      grid.at(r, c) = v == 205 ? evaluator::OccupancyGrid::kUnknown : v == 0 ? 1.0f : 0.0f;
    }
  }
  evaluator::WriteMapServer(grid, WorkDir() / "map.yaml");
  evaluator::Trajectory estimate;
  evaluator::Trajectory reference;
  for (int i = 0; i < 2000; ++i) {
    const double a = i * 2.0 * M_PI / 2000.0;
    estimate.Add(i * 0.1, evaluator::Pose::Planar(15.0 * std::cos(a), 15.0 * std::sin(a), a));
    reference.Add(i * 0.1, evaluator::Pose::Planar(3.0 + 15.5 * std::cos(a + 0.2), 1.0 + 14.5 * std::sin(a + 0.2), a));
  }
  evaluator::WriteTum(estimate, WorkDir() / "estimate.tum");
  evaluator::WriteTum(reference, WorkDir() / "reference.tum");
  for (auto _ : state) {
    report::WriteTrajectoryOverlay(WorkDir() / "map.yaml", WorkDir() / "estimate.tum", WorkDir() / "reference.tum",
                                   WorkDir() / "overlay.png", {});
  }
}
BENCHMARK(BM_TrajectoryOverlay)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::error_code ignored;
  fs::remove_all(WorkDir(), ignored);
  return 0;
}
