#pragma once

#include <string_view>

namespace slamsweep::orchestrator::inline build_identity {

/// This slamsweep's revision: "<version>+<git describe --always --dirty>" of the checkout it was
/// built from (cmake/WriteRevision.cmake), "<version>+<version>-nogit" outside git. Part of every
/// run's build identity: a new slamsweep never silently reuses results an older one computed.
std::string_view SlamsweepRevision();

}  // namespace slamsweep::orchestrator::inline build_identity
