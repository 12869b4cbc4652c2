#include "orchestrator/build_identity/revision.h"

#include "slamsweep_revision.h"

namespace slamsweep::orchestrator {

std::string_view SlamsweepRevision() { return SLAMSWEEP_REVISION; }

}  // namespace slamsweep::orchestrator
