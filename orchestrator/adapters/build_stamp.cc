#include "orchestrator/adapters/build_stamp.h"

#include <map>
#include <string>

#include "evaluator/core/input_error.h"
#include "orchestrator/adapters/program_identity.h"
#include "orchestrator/build_identity/file_digest.h"
#include "orchestrator/build_identity/revision.h"

namespace slamsweep::orchestrator::inline adapters {

void StampBuildIdentity(std::vector<RunSpec>& runs) {
  std::map<std::string, std::string> digests;
  for (RunSpec& run : runs) {
    try {
      run.build.slamsweep_revision = std::string(SlamsweepRevision());
      run.build.program_files.clear();
      for (const std::filesystem::path& file : ProgramFilesOf(run.algorithm)) {
        auto [found, inserted] = digests.try_emplace(file.string());
        if (inserted) found->second = Sha256OfFile(file);
        run.build.program_files[file.string()] = found->second;
      }
      run.seeding = SeedingOf(run.algorithm);
    } catch (const evaluator::InputError& error) {
      throw evaluator::InputError("algorithm '" + run.algorithm.name + "': " + error.what());
    }
  }
}

}  // namespace slamsweep::orchestrator::inline adapters
