// SPDX-License-Identifier: Apache-2.0
#include "bus/process/shutdown_signal.hpp"

#include <csignal>

namespace wrc::bus {

namespace {
volatile std::sig_atomic_t g_requested = 0;
volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_shutdown_signal(int sig) {
  g_requested = 1;
  g_signal = sig;
}
}  // namespace

void ShutdownSignal::install() {
  struct sigaction action {};
  action.sa_handler = on_shutdown_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;  // no SA_RESTART: interrupt blocking waits
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool ShutdownSignal::requested() { return g_requested != 0; }
int ShutdownSignal::signal_number() { return g_signal; }
void ShutdownSignal::request() { g_requested = 1; }
void ShutdownSignal::reset() {
  g_requested = 0;
  g_signal = 0;
}

}  // namespace wrc::bus
