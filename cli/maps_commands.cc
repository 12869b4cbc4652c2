// The commands of `slamsweep-maps`: scoring and converting one map (OpenCV, libpng).
#include "cli/program.h"

namespace slamsweep::cli {

void RegisterMapsCommands(CommandLine& line) {
  RegisterEvalMapCommand(line.Eval(), line.streams);
  RegisterEvalMapCompareCommand(line.Eval(), line.streams);
  RegisterVectorizeCommand(line.app, line.streams);
}

}  // namespace slamsweep::cli
