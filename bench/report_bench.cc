// Speed target of `slamsweep report`: the report of 1,000 runs in under 30 s on 2 cores.
// The sweep is synthetic (tests/report/fixture_sweep): 10 algorithms x 10 sequences x 10
// iterations, each run with a 40 x 30 map, 3 stage maps and trajectories; images are made by the
// standard artwork (gnuplot, giflib) with 2 jobs.
#include <benchmark/benchmark.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <memory>
#include <string>

#include "report/html/standard_artwork.h"
#include "report/html/write_report.h"
#include "tests/report/fixture_sweep.h"

namespace {

namespace fs = std::filesystem;
using slamsweep::report::testing::FixtureRun;
using slamsweep::report::testing::MakeRun;

// Wraps the standard artwork and sums the time spent in each kind of image (over all threads),
// so the figure says where the time goes.
class TimedArtwork final : public slamsweep::report::Artwork {
 public:
  explicit TimedArtwork(std::unique_ptr<Artwork> inner) : inner_(std::move(inner)) {}
  void Plots(const std::vector<slamsweep::report::PlotRequest>& plots) override {
    Timed(plots_us, [&] { inner_->Plots(plots); });
  }
  void ScatterPlots(const std::vector<slamsweep::report::ScatterPlotJob>& plots) override {
    Timed(plots_us, [&] { inner_->ScatterPlots(plots); });
  }
  void Figures(const std::vector<slamsweep::report::FigureJob>& figures) override {
    Timed(plots_us, [&] { inner_->Figures(figures); });
  }
  void StagesGif(const std::vector<fs::path>& stages, const fs::path& gif,
                 const slamsweep::report::GifSettings& settings) override {
    Timed(gifs_us, [&] { inner_->StagesGif(stages, gif, settings); });
  }
  void StagesGifFromAnimation(const fs::path& animation, const fs::path& gif,
                              const slamsweep::report::GifSettings& settings) override {
    Timed(gifs_us, [&] { inner_->StagesGifFromAnimation(animation, gif, settings); });
  }
  void Thumbnail(const fs::path& map, const fs::path& png, int max_side_px) override {
    Timed(thumbnails_us, [&] { inner_->Thumbnail(map, png, max_side_px); });
  }
  void TrajectoryOverlay(const fs::path& map_yaml, const fs::path& estimate, const fs::path& reference,
                         const fs::path& png, const slamsweep::report::OverlaySettings& settings) override {
    Timed(overlays_us, [&] { inner_->TrajectoryOverlay(map_yaml, estimate, reference, png, settings); });
  }
  std::atomic<long long> plots_us{0}, gifs_us{0}, thumbnails_us{0}, overlays_us{0};

 private:
  template <typename F>
  static void Timed(std::atomic<long long>& total, F&& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    total += std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start).count();
  }
  std::unique_ptr<Artwork> inner_;
};

const fs::path& SweepDir(int runs) {
  static const fs::path dir = [runs] {
    const fs::path path = fs::temp_directory_path() / ("slamsweep_report_bench_" + std::to_string(runs));
    fs::remove_all(path);
    std::vector<FixtureRun> fixture;
    for (int i = 0; i < runs; ++i) {
      FixtureRun run =
          MakeRun("algorithm" + std::to_string(i % 10), "sequence" + std::to_string((i / 10) % 10), i / 100);
      run.ok = i % 17 != 0;
      run.with_reference = (i / 10) % 10 < 7;
      if (run.with_reference) run.ape_rmse_m = 0.1 + 0.001 * (i % 37);
      run.occupied_ratio = 0.05 + 0.0001 * (i % 13);
      run.corners = 10 + i % 7;
      run.enclosed_areas = i % 3;
      run.log = std::string(200, 'x') + "\n";
      fixture.push_back(run);
    }
    slamsweep::report::testing::WriteFixtureSweep(path, fixture);
    return path;
  }();
  return dir;
}

void BM_Report(benchmark::State& state) {
  const int runs = static_cast<int>(state.range(0));
  const bool images = state.range(1) != 0;
  const fs::path& sweep = SweepDir(runs);
  std::unique_ptr<TimedArtwork> artwork;
  if (images) {
    if (auto standard = slamsweep::report::MakeStandardArtwork())
      artwork = std::make_unique<TimedArtwork>(std::move(standard));
  }
  slamsweep::report::ReportOptions options;
  options.artwork = artwork.get();
  options.jobs = 2;
  for (auto _ : state) {
    const auto summary =
        slamsweep::report::WriteReport(sweep, sweep.parent_path() / (sweep.filename().string() + "_out"), options);
    benchmark::DoNotOptimize(summary.pages);
    state.counters["images"] = static_cast<double>(summary.images);
    state.counters["images_missing"] = static_cast<double>(summary.images_missing);
  }
  state.counters["runs"] = runs;
  if (artwork) {
    state.counters["plots_s"] = artwork->plots_us / 1e6;
    state.counters["gifs_s"] = artwork->gifs_us / 1e6;
    state.counters["thumbs_s"] = artwork->thumbnails_us / 1e6;
    state.counters["overlays_s"] = artwork->overlays_us / 1e6;
  }
}
BENCHMARK(BM_Report)->Args({1000, 1})->Args({1000, 0})->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
