// `slamsweep merge DIR... -o DIR`: one result directory from the shards of a sweep run on several machines.
#include <fmt/format.h>

#include "cli/command.h"
#include "orchestrator/store/merge.h"
#include "orchestrator/sweep/output_lock.h"

namespace slamsweep::cli {
namespace {

struct MergeOptions {
  std::vector<std::string> inputs;
  std::string output;
  bool no_report = false;
};

void Merge(const MergeOptions& options, const Streams& streams) {
  std::vector<std::filesystem::path> inputs(options.inputs.begin(), options.inputs.end());
  const std::filesystem::path output = options.output;
  // The merged directory is written like a sweep's: nobody else may write it meanwhile.
  orchestrator::OutputLock lock(output);
  const orchestrator::MergeReport report = orchestrator::MergeResultDirs(inputs, output);
  streams.out << fmt::format("merged {} inputs into {}: {} runs added, {} duplicates, {} conflicts\n", inputs.size(),
                             output.string(), report.runs_added, report.duplicates, report.conflicts.size());
  for (const std::string& conflict : report.conflicts) streams.err << "slamsweep: warning: " << conflict << "\n";
  if (!options.no_report) WriteSweepReport(output, streams);
}

}  // namespace

void RegisterMergeCommand(CLI::App& app, const Streams& streams) {
  auto options = std::make_shared<MergeOptions>();
  CLI::App* command = app.add_subcommand("merge", "combine result directories (shards of one sweep) into one");
  command->add_option("DIR", options->inputs, "result directories written by `slamsweep run`")->required();
  command->add_option("-o,--output", options->output, "merged result directory")->required();
  command->add_flag("--no-report", options->no_report, "do not write the HTML report");
  command->callback([options, &streams] { Merge(*options, streams); });
}

}  // namespace slamsweep::cli
