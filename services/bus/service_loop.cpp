#include "bus/service_loop.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <iostream>
#include <stdexcept>

#include "bus/clock.hpp"
#include "bus/shutdown_signal.hpp"

namespace wrc::bus {

std::unique_ptr<lcm::LCM> open_lcm(const std::string& url) {
  auto lcm = std::make_unique<lcm::LCM>(url);
  if (!lcm->good()) {
    throw std::runtime_error("cannot open LCM at '" + (url.empty() ? std::string("default URL") : url) +
                             "' (is there a multicast route? see `ip route`)");
  }
  return lcm;
}

void ServiceLoop::report_load(double period_elapsed) {
  ServiceLoad load;
  double busy = 0.0;
  for (LoadSource* source : sources_) {
    source->add_load(load);
    busy += source->take_busy_time();
  }
  load.max_queue = max_queue_;
  load.busy_fraction = period_elapsed > 0.0 ? std::min(1.0, busy / period_elapsed) : 0.0;
  heartbeat_.set_load(load);
  max_queue_ = 0;
}

int ServiceLoop::run() {
  double period_start = monotonic_seconds();
  report_load(0.0);
  heartbeat_.set_state(wrc::heartbeat_t::READY);
  int exit_code = 0;
  int consecutive_errors = 0;
  while (!ShutdownSignal::requested()) {
    const double wait = std::min(max_wait_, heartbeat_.seconds_until_due());
    int rc = lcm_.handleTimeout(static_cast<int>(std::ceil(wait * 1e3)));
    if (rc > 0) {
      // drain what is already queued without waiting; the burst length measures the queue
      int burst = 0;
      while (!ShutdownSignal::requested() && (rc = lcm_.handleTimeout(0)) > 0) ++burst;
      max_queue_ = std::max(max_queue_, burst);
    }
    if (rc < 0 && !ShutdownSignal::requested() && errno != EINTR) {
      if (++consecutive_errors >= 10) {
        std::cerr << "service loop: LCM handle failed 10 times in a row, stopping\n";
        exit_code = 1;
        break;
      }
    } else {
      consecutive_errors = 0;
    }
    if (idle_hook_) idle_hook_();
    if (heartbeat_.seconds_until_due() <= 0.0) {
      const double now = monotonic_seconds();
      report_load(now - period_start);
      period_start = now;
      heartbeat_.tick();
    }
  }
  report_load(monotonic_seconds() - period_start);
  heartbeat_.set_state(wrc::heartbeat_t::DRAINING);
  return exit_code;
}

}  // namespace wrc::bus
