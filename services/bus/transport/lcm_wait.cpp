// SPDX-License-Identifier: Apache-2.0
#include "bus/transport/lcm_wait.hpp"

#include <poll.h>

#include <cerrno>

namespace wrc::bus {

int handle_any(const std::vector<Inbox>& inboxes, int timeout_ms) {
  if (inboxes.size() == 1) return inboxes.front().handle_timeout(timeout_ms);
  std::vector<pollfd> fds;
  fds.reserve(inboxes.size());
  for (const Inbox& inbox : inboxes) fds.push_back({inbox.fileno(), POLLIN, 0});
  const int ready = ::poll(fds.data(), fds.size(), timeout_ms);
  if (ready <= 0) return ready;
  int handled = 0;
  for (std::size_t k = 0; k < fds.size(); ++k) {
    if ((fds[k].revents & (POLLIN | POLLERR | POLLHUP)) == 0) continue;
    const int rc = inboxes[k].handle_timeout(0);
    if (rc < 0) return -1;
    handled += rc;
  }
  return handled;
}

}  // namespace wrc::bus
