#include "orchestrator/process/socket_send.h"

#include <sys/socket.h>

#include <cerrno>
#include <cstddef>

namespace slamsweep::orchestrator::inline process {

bool SendAll(int fd, std::string_view text) {
  std::size_t sent = 0;
  while (sent < text.size()) {
    const ssize_t n = ::send(fd, text.data() + sent, text.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    sent += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace slamsweep::orchestrator::inline process
