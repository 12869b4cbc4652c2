// `slamsweep data ...`: sequences in, SLAM-ready inputs out.
#include "cli/command.h"

namespace slamsweep::cli {

void RegisterDataCommands(CLI::App& app, const Streams& streams) {
  CLI::App* data = app.add_subcommand("data", "inspect, convert, map and simulate sequences");
  data->require_subcommand(1);
  (void)streams;
}

}  // namespace slamsweep::cli
