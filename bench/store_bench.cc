#include <benchmark/benchmark.h>

#include <filesystem>
#include <unistd.h>

#include "orchestrator/store/junit_xml.h"
#include "orchestrator/store/results_store.h"
#include "orchestrator/store/summary_json.h"
#include "orchestrator/store/validity_table.h"
#include "tests/orchestrator/store/store_test_util.h"

using namespace slamsweep::orchestrator;

static std::filesystem::path Fresh(const char* name) {
  auto dir = std::filesystem::temp_directory_path() / (std::string(name) + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

static void BM_RecordRun(benchmark::State& state) {
  const auto dir = Fresh("bm_record");
  ResultsStore store = ResultsStore::Open(dir / "results.sqlite");
  std::int64_t i = 0;
  for (auto _ : state) {
    // Appended, not operator+: GCC 12 at -O3 warns falsely (-Wrestrict) on "literal" + std::string.
    std::string id = "run-";
    id += std::to_string(i++);
    store.RecordRun(1, testing::MakeSpec(id), testing::MakeOkResult(id), std::string("runs/").append(id));
  }
  std::filesystem::remove_all(dir);
}
BENCHMARK(BM_RecordRun);

static void BM_RunsSummaryJunit(benchmark::State& state) {
  const auto dir = Fresh("bm_runs");
  ResultsStore store = ResultsStore::Open(dir / "results.sqlite");
  for (int i = 0; i < state.range(0); ++i) {
    std::string id = "run-";
    id += std::to_string(i);
    store.RecordRun(1, testing::MakeSpec(id, "a", std::string("s").append(std::to_string(i % 10))),
                    testing::MakeOkResult(id), std::string("runs/").append(id));
  }
  for (auto _ : state) {
    const auto runs = store.Runs();
    WriteSummaryJson(runs, ValidityStudyOf(runs), dir / "summary.json");
    WriteJUnit(runs, dir / "junit.xml");
  }
  std::filesystem::remove_all(dir);
}
BENCHMARK(BM_RunsSummaryJunit)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
