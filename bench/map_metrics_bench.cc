// Speed and memory of the paper-profile map metrics (evaluator/map) on 2000 x 2000 maps.
// Targets: the three metrics together under 150 ms on one core, and a peak memory under
// 5 x the float grid (80 MB) above the input grid.
//
//   map_metrics_bench                  Google Benchmark timings (one OpenCV thread); the counter
//                                      heap_peak_MB is the counted heap peak of one call.
//   map_metrics_bench --peak_rss       one call in a fresh process (as in a worker, which scores
//                                      one map): its time, page faults and resident-memory peak.
//   map_metrics_bench --repeat=N       N calls on the tiled map and nothing else, for counting
//                                      instructions with `perf stat` (the difference between two
//                                      N is the work of the calls, whatever the machine's load).
//
// Memory is measured two ways. (1) Counting: every operator new and every cv::Mat buffer
// (through a counting cv::MatAllocator installed as OpenCV's default) adds its usable size to
// one counter; the peak of that counter above its value before the call is heap_peak_MB. It
// misses OpenCV's small internal scratch buffers (filter row buffers). (2) --peak_rss: the
// kernel's resident high-water mark (VmHWM) is reset through /proc/self/clear_refs after the
// input is built and freed memory is returned (malloc_trim), so VmHWM - VmRSS before the call
// is everything the call touched.
#include <benchmark/benchmark.h>
#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <new>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <random>
#include <string>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/map_metrics/corner_count.h"
#include "evaluator/map_metrics/enclosed_areas.h"
#include "evaluator/map_metrics/occupied_proportion.h"
#include "evaluator/map_metrics/paper_metrics.h"

namespace {

std::atomic<std::int64_t> g_heap_bytes{0};
std::atomic<std::int64_t> g_heap_peak{0};

void CountAllocation(std::int64_t bytes) {
  const std::int64_t now = g_heap_bytes.fetch_add(bytes, std::memory_order_relaxed) + bytes;
  std::int64_t peak = g_heap_peak.load(std::memory_order_relaxed);
  while (now > peak && !g_heap_peak.compare_exchange_weak(peak, now, std::memory_order_relaxed)) {
  }
}

void* CountedMalloc(std::size_t size) {
  void* p = std::malloc(size == 0 ? 1 : size);
  if (p == nullptr) throw std::bad_alloc();
  CountAllocation(static_cast<std::int64_t>(malloc_usable_size(p)));
  return p;
}

void CountedFree(void* p) {
  if (p == nullptr) return;
  g_heap_bytes.fetch_sub(static_cast<std::int64_t>(malloc_usable_size(p)), std::memory_order_relaxed);
  std::free(p);
}

// cv::Mat buffers come from OpenCV's own allocator, not operator new: wrap the standard one.
class CountingMatAllocator : public cv::MatAllocator {
 public:
  cv::UMatData* allocate(int dims, const int* sizes, int type, void* data, std::size_t* step, cv::AccessFlag flags,
                         cv::UMatUsageFlags usage) const override {
    cv::UMatData* u = standard_->allocate(dims, sizes, type, data, step, flags, usage);
    if (u != nullptr) {
      u->currAllocator = this;  // so that the buffer is released through deallocate() below
      if (data == nullptr) CountAllocation(static_cast<std::int64_t>(u->size));
    }
    return u;
  }
  bool allocate(cv::UMatData* u, cv::AccessFlag flags, cv::UMatUsageFlags usage) const override {
    return standard_->allocate(u, flags, usage);
  }
  void deallocate(cv::UMatData* u) const override {
    if (u == nullptr) return;
    if ((u->flags & cv::UMatData::USER_ALLOCATED) == 0) {
      g_heap_bytes.fetch_sub(static_cast<std::int64_t>(u->size), std::memory_order_relaxed);
    }
    u->currAllocator = standard_;
    standard_->deallocate(u);
  }

 private:
  cv::MatAllocator* standard_ = cv::Mat::getStdAllocator();
};

}  // namespace

void* operator new(std::size_t size) { return CountedMalloc(size); }
void* operator new[](std::size_t size) { return CountedMalloc(size); }
void operator delete(void* p) noexcept { CountedFree(p); }
void operator delete[](void* p) noexcept { CountedFree(p); }
void operator delete(void* p, std::size_t) noexcept { CountedFree(p); }
void operator delete[](void* p, std::size_t) noexcept { CountedFree(p); }

namespace slamsweep::evaluator {
namespace {

constexpr int kSide = 2000;

OccupancyGrid FromPgmValue(const cv::Mat& image, int rows, int cols, bool tile) {
  OccupancyGrid grid(cols, rows, 0.05);  // unknown
  const int row0 = tile ? 0 : (rows - image.rows) / 2;
  const int col0 = tile ? 0 : (cols - image.cols) / 2;
  for (int row = 0; row < rows; ++row) {
    for (int col = 0; col < cols; ++col) {
      const int r = tile ? row % image.rows : row - row0;
      const int c = tile ? col % image.cols : col - col0;
      if (r < 0 || c < 0 || r >= image.rows || c >= image.cols) continue;
      const int v = image.at<unsigned char>(r, c);
      grid.at(row, col) = v == 205 ? OccupancyGrid::kUnknown : static_cast<float>(255 - v) / 255.0f;
    }
  }
  return grid;
}

cv::Mat TelecomPgm() {
  return cv::imread(std::string(SLAMSWEEP_SHARED_DIR) + "/reference/maps/telecom_icp.pgm", cv::IMREAD_UNCHANGED);
}

// Used when the shared folder is absent: a floor plan of 12 x 12 rooms of ~150 cells with
// 2-cell walls, doors in most walls, furniture and speckle inside, unknown outside a margin.
OccupancyGrid GeneratedFloorPlan() {
  OccupancyGrid map(kSide, kSide, 0.05);
  std::mt19937 random(11);
  auto fill = [&map](int row0, int col0, int rows, int cols, float p) {
    for (int r = std::max(row0, 0); r < std::min(row0 + rows, kSide); ++r) {
      for (int c = std::max(col0, 0); c < std::min(col0 + cols, kSide); ++c) map.at(r, c) = p;
    }
  };
  const int room = 150;
  const int first = 100;
  const int last = first + 12 * room;
  fill(first, first, last - first, last - first, 0.0f);
  for (int k = first; k <= last; k += room) {
    fill(k, first, 2, last - first + 2, 1.0f);
    fill(first, k, last - first + 2, 2, 1.0f);
  }
  for (int r = first; r < last; r += room) {
    for (int c = first; c < last; c += room) {
      if (random() % 4 != 0) fill(r, c + 30 + static_cast<int>(random() % 80), 2, 16, 0.0f);
      if (random() % 4 != 0) fill(r + 30 + static_cast<int>(random() % 80), c, 16, 2, 0.0f);
      for (int f = 0; f < 3; ++f) {
        fill(r + 10 + static_cast<int>(random() % 110), c + 10 + static_cast<int>(random() % 110),
             4 + static_cast<int>(random() % 20), 4 + static_cast<int>(random() % 20), 0.9f);
      }
    }
  }
  std::uniform_int_distribution<int> inside(first, last - 1);
  for (int i = 0; i < 40000; ++i) map.at(inside(random), inside(random)) = 0.7f;
  return map;
}

// telecom_icp (1500 x 1760) repeated to fill 2000 x 2000: structure over the whole map.
const OccupancyGrid& TelecomTiled() {
  static const OccupancyGrid grid = [] {
    const cv::Mat image = TelecomPgm();
    return image.empty() ? GeneratedFloorPlan() : FromPgmValue(image, kSide, kSide, true);
  }();
  return grid;
}

// telecom_icp centred in 2000 x 2000 unknown cells: a real map with a realistic unknown margin.
const OccupancyGrid& TelecomPadded() {
  static const OccupancyGrid grid = [] {
    const cv::Mat image = TelecomPgm();
    return image.empty() ? GeneratedFloorPlan() : FromPgmValue(image, kSide, kSide, false);
  }();
  return grid;
}

long MinorPageFaults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

template <typename Compute>
void RunMeasured(benchmark::State& state, Compute compute) {
  std::int64_t heap_peak_bytes = 0;
  const long faults_before = MinorPageFaults();
  for (auto _ : state) {
    const std::int64_t before = g_heap_bytes.load();
    g_heap_peak.store(before);
    compute();
    heap_peak_bytes = std::max(heap_peak_bytes, g_heap_peak.load() - before);
  }
  state.counters["heap_peak_MB"] = static_cast<double>(heap_peak_bytes) / 1e6;
  // Fresh memory costs a page fault per 4 KB page, which is expensive in a VM: worth seeing.
  state.counters["page_faults"] =
      benchmark::Counter(static_cast<double>(MinorPageFaults() - faults_before), benchmark::Counter::kAvgIterations);
}

void BM_PaperMetrics(benchmark::State& state, const OccupancyGrid& (*map)()) {
  const OccupancyGrid& grid = map();
  PaperMetrics metrics;
  RunMeasured(state, [&] {
    metrics = ComputePaperMetrics(grid);
    benchmark::DoNotOptimize(metrics.corners.corners);
  });
  state.counters["corners"] = static_cast<double>(metrics.corners.corners);
  state.counters["enclosed_areas"] = static_cast<double>(metrics.enclosed.enclosed_areas);
  state.counters["distinct_binarisations"] = metrics.enclosed.distinct_binarisations;
}
BENCHMARK_CAPTURE(BM_PaperMetrics, telecom_tiled, TelecomTiled)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PaperMetrics, telecom_padded, TelecomPadded)->Unit(benchmark::kMillisecond);

// The metrics on their own, to see where the time goes.
void BM_OccupiedProportion(benchmark::State& state) {
  const OccupancyGrid& grid = TelecomTiled();
  RunMeasured(state, [&] { benchmark::DoNotOptimize(ComputeOccupiedProportion(grid).occupied_cells); });
}
BENCHMARK(BM_OccupiedProportion)->Unit(benchmark::kMillisecond);

void BM_CornerCount(benchmark::State& state) {
  const OccupancyGrid& grid = TelecomTiled();
  RunMeasured(state, [&] { benchmark::DoNotOptimize(ComputeCornerCount(grid).corners); });
}
BENCHMARK(BM_CornerCount)->Unit(benchmark::kMillisecond);

void BM_EnclosedAreas(benchmark::State& state) {
  const OccupancyGrid& grid = TelecomTiled();
  RunMeasured(state, [&] { benchmark::DoNotOptimize(ComputeEnclosedAreas(grid).enclosed_areas); });
}
BENCHMARK(BM_EnclosedAreas)->Unit(benchmark::kMillisecond);

double CpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) * 1e-6;
}

std::int64_t StatusKilobytes(const char* field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::size_t length = std::strlen(field);
  while (std::getline(status, line)) {
    if (line.compare(0, length, field) == 0) return std::atoll(line.c_str() + length + 1);
  }
  return -1;
}

int PeakRss(const OccupancyGrid& (*map)(), const char* name) {
  const OccupancyGrid& grid = map();
  malloc_trim(0);
  const std::int64_t rss_before_kb = StatusKilobytes("VmRSS");
  std::ofstream clear_refs("/proc/self/clear_refs");
  clear_refs << "5" << std::flush;  // resets VmHWM to the current resident size
  const bool reset = clear_refs.good();
  const std::int64_t heap_before = g_heap_bytes.load();
  g_heap_peak.store(heap_before);
  const long faults_before = MinorPageFaults();
  const double cpu_before_s = CpuSeconds();
  const auto wall_before = std::chrono::steady_clock::now();
  const PaperMetrics metrics = ComputePaperMetrics(grid);
  const double wall_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall_before).count();
  const double cpu_ms = (CpuSeconds() - cpu_before_s) * 1e3;
  const long faults = MinorPageFaults() - faults_before;
  const std::int64_t hwm_kb = StatusKilobytes("VmHWM");
  std::printf(
      "%s: corners %lld, enclosed areas %lld; input grid %.1f MB; peak above input: RSS %.1f MB%s, "
      "counted heap %.1f MB; first call: %.1f ms wall, %.1f ms CPU, %ld page faults\n",
      name, static_cast<long long>(metrics.corners.corners), static_cast<long long>(metrics.enclosed.enclosed_areas),
      grid.cells.size() * 4.0 / 1e6, (hwm_kb - rss_before_kb) / 1e3,
      reset ? "" : " (VmHWM could not be reset: includes the input)", (g_heap_peak.load() - heap_before) / 1e6, wall_ms,
      cpu_ms, faults);
  return 0;
}

int Repeat(int calls) {
  const OccupancyGrid& grid = TelecomTiled();
  std::int64_t corners = 0;
  for (int i = 0; i < calls; ++i) corners += ComputePaperMetrics(grid).corners.corners;
  std::printf("%d calls, %lld corners\n", calls, static_cast<long long>(corners));
  return 0;
}

}  // namespace
}  // namespace slamsweep::evaluator

int main(int argc, char** argv) {
  // The Google Benchmark figures are the work of one call in a process that scores maps one
  // after another. glibc's defaults return freed memory to the kernel above a threshold that
  // moves with the sizes freed before, so whether a call faults its pages in anew depended on
  // the order of frees in the call before, not on the code measured (one reordering swung the
  // figure by 50 ms). Fixed thresholds make the heap stay. --peak_rss, a fresh process with
  // glibc's defaults, gives the first call's cost with every page fault included.
  const bool first_call_only = argc > 1 && std::strncmp(argv[1], "--peak_rss", 10) == 0;
  if (!first_call_only) {
    mallopt(M_MMAP_THRESHOLD, 64 << 20);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
  }
  static CountingMatAllocator counting_allocator;
  cv::Mat::setDefaultAllocator(&counting_allocator);
  cv::setNumThreads(1);  // the target is per core
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--peak_rss=tiled") == 0 || std::strcmp(argv[i], "--peak_rss") == 0) {
      return slamsweep::evaluator::PeakRss(slamsweep::evaluator::TelecomTiled, "telecom_tiled 2000 x 2000");
    }
    if (std::strcmp(argv[i], "--peak_rss=padded") == 0) {
      return slamsweep::evaluator::PeakRss(slamsweep::evaluator::TelecomPadded, "telecom_padded 2000 x 2000");
    }
    if (std::strncmp(argv[i], "--repeat=", 9) == 0) return slamsweep::evaluator::Repeat(std::atoi(argv[i] + 9));
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
