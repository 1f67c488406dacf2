// SPDX-License-Identifier: Apache-2.0
#include "cli/log_cleanup.hpp"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <mutex>

namespace wrc::cli {
namespace {

constexpr std::size_t kMaxPath = 1024;

// Fixed storage the handler can read without allocating: a slot is readable once `used` is set.
struct Slot {
  char path[kMaxPath];
  std::atomic<bool> used{false};
};
Slot slots[kMaxRemovedOnSignal];
std::mutex registry_mutex;  // registration only; the handler takes no lock
bool installed = false;

void remove_and_reraise(int signal_number) {
  for (Slot& slot : slots)
    if (slot.used.load()) ::unlink(slot.path);
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

void install_once() {
  if (installed) return;
  installed = true;
  for (int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) {
    struct sigaction current {};
    if (::sigaction(s, nullptr, &current) != 0 || current.sa_handler != SIG_DFL) continue;
    struct sigaction action {};
    action.sa_handler = remove_and_reraise;
    sigemptyset(&action.sa_mask);
    ::sigaction(s, &action, nullptr);
  }
}

}  // namespace

void remove_on_signal(const std::string& path) {
  if (path.empty() || path.size() >= kMaxPath) return;
  std::lock_guard<std::mutex> lock(registry_mutex);
  install_once();
  for (Slot& slot : slots) {
    if (slot.used.load()) continue;
    std::memcpy(slot.path, path.c_str(), path.size() + 1);
    slot.used.store(true);
    return;
  }
}

void keep_on_signal(const std::string& path) {
  std::lock_guard<std::mutex> lock(registry_mutex);
  for (Slot& slot : slots)
    if (slot.used.load() && path == slot.path) slot.used.store(false);
}

}  // namespace wrc::cli
