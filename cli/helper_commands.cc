// The commands the core hands to a helper program (program.h), with the descriptions its help shows.
#include <array>

#include "cli/program.h"

namespace slamsweep::cli {
namespace {

constexpr std::string_view kMaps = "slamsweep-maps";
// A 2000 x 2000 map: 1 000 page faults instead of 7 000, a seventh less time (bench/cli).
constexpr std::string_view kHugePages = "glibc.malloc.hugetlb=1";
constexpr std::string_view kSweep = "slamsweep-sweep";

// The descriptions repeat those of the commands themselves; cli_test checks that they agree.
constexpr std::array<HelperCommand, 11> kHelperCommands = {{
    {"eval", "map", "occupied proportion, corners and enclosed areas (paper profile)", kMaps, false, kHugePages},
    {"eval", "map-compare", "an estimated map against a reference map: distances, F1, IoU", kMaps, false, kHugePages},
    {"", "vectorize", "trace obstacle borders and export polygons", kMaps, false, kHugePages},
    {"", "data", "inspect, convert, map and simulate sequences", kSweep},
    {"", "run", "run a sweep: every run in a worker process, results in OUTPUT", kSweep},
    {"", "merge", "combine result directories (shards of one sweep) into one", kSweep},
    {"", "report", "turn a sweep's output directory into a static HTML report", kSweep},
    {"", "history", "nightly history: record sweeps, compare them for regressions", kSweep},
    {"", "worker", "run one prepared run folder (started by `slamsweep run`)", kSweep, true},
    {"", "serve", "run submitted sweeps from one queue on a shared worker pool, with an HTTP API and a status page",
     kSweep},
    {"", "submit", "submit a sweep to `slamsweep serve`; --wait follows it like `run`", kSweep},
}};

}  // namespace

std::span<const HelperCommand> HelperCommands() { return kHelperCommands; }

}  // namespace slamsweep::cli
