#include <memory>
#include <string>

#include "orchestrator/adapters/adapter.h"
#include "orchestrator/adapters/command_adapter.h"
#include "orchestrator/adapters/mrpt_adapters.h"
#include "orchestrator/adapters/odometry_adapter.h"
#include "orchestrator/adapters/program_identity.h"
#include "orchestrator/adapters/roster_adapter.h"

namespace slamsweep::orchestrator::inline adapters {

std::vector<std::filesystem::path> Adapter::ProgramReads(const RunSpec& /*spec*/) const { return {}; }

std::unique_ptr<Adapter> MakeAdapter(std::string_view name) {
  if (name == "mrpt-icp-slam") return std::make_unique<IcpSlamAdapter>();
  if (name == "mrpt-rbpf-slam") return std::make_unique<RbpfSlamAdapter>();
  if (name == "command") return std::make_unique<CommandAdapter>();
  if (name == "odometry") return std::make_unique<OdometryAdapter>();
  if (const RosterAlgorithm* algorithm = FindRosterAlgorithm(name)) return std::make_unique<RosterAdapter>(*algorithm);
  ThrowUnknownAdapter(name);
}

}  // namespace slamsweep::orchestrator::inline adapters
