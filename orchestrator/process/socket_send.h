#pragma once

#include <string_view>

namespace slamsweep::orchestrator::inline process {

/// Sends all of `text` on the socket `fd` (retrying after signals; no SIGPIPE when the other end is gone).
/// False when the other end has closed or the socket failed: the peer is gone.
bool SendAll(int fd, std::string_view text);

}  // namespace slamsweep::orchestrator::inline process
