#include "orchestrator/process/run_to_exit.h"

#include <sys/wait.h>

#include <cerrno>
#include <stdexcept>
#include <system_error>

#include "orchestrator/process/process_spec.h"

namespace slamsweep::orchestrator::inline process {

ExitStatus RunToExit(const std::vector<std::string>& argv, const ChildStreams& streams) {
  if (!streams.OutputElsewhere()) {
    throw std::invalid_argument("RunToExit: stdout and stderr must be redirected");
  }
  ProcessSpec spec;
  spec.argv = argv;
  const SpawnResult spawned = SpawnChild(spec, streams);
  ExitStatus exit;
  if (!spawned.error.empty()) {
    exit.start_error = spawned.error;
    return exit;
  }
  int status = 0;
  while (::waitpid(spawned.pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::system_error(errno, std::generic_category(), "waitpid");
  }
  exit.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return exit;
}

}  // namespace slamsweep::orchestrator::inline process
