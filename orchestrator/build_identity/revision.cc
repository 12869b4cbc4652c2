#include "orchestrator/build_identity/revision.h"

#include "slamsweep_revision.h"

namespace slamsweep::orchestrator::inline build_identity {

std::string_view SlamsweepRevision() { return SLAMSWEEP_REVISION; }

}  // namespace slamsweep::orchestrator::inline build_identity
