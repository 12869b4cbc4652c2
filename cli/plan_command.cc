// `slamsweep plan CONFIG [--shard i/N] [--only-...] [--json]`: what a sweep would run, without running it.
#include <memory>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/command.h"
#include "cli/sweep_loading.h"
#include "orchestrator/matrix/plan_listing.h"

namespace slamsweep::cli {

void RegisterPlanCommand(CLI::App& app, const Streams& streams) {
  struct Options {
    std::string config_path;
    MatrixSelection selection;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand("plan", "list the runs of a sweep file (validates it; runs nothing)");
  command->add_option("CONFIG", options->config_path, "sweep file (YAML)")->required();
  AddMatrixSelectionOptions(*command, options->selection);
  command->add_flag("--json", options->json, "print one JSON array of run.json objects");
  command->callback([options, streams] {
    // The same loading as `run`, so the plan shows exactly what run would start.
    const LoadedSweep sweep = LoadSweep(options->config_path, options->selection, /*install_missing_roster=*/true);
    streams.err << orchestrator::OdometryIsReferenceWarnings(sweep.runs);
    if (options->json) {
      streams.out << orchestrator::PlanJson(sweep.runs).dump(2) << "\n";
    } else {
      streams.out << orchestrator::FormatPlan(sweep.runs);
    }
  });
}

}  // namespace slamsweep::cli
