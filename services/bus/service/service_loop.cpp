// SPDX-License-Identifier: Apache-2.0
#include "bus/service/service_loop.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <exception>
#include <iostream>
#include <stdexcept>
#include <string>

#include "bus/auth/bus_auth.hpp"
#include "bus/process/shutdown_signal.hpp"
#include "bus/transport/clock.hpp"
#include "bus/transport/lcm_url.hpp"
#include "bus/transport/lcm_wait.hpp"

namespace wrc::bus {

std::unique_ptr<lcm::LCM> open_lcm(const std::string& url, const std::string& bus_key_option) {
  load_bus_key(bus_key_option);
  const std::string effective = effective_lcm_url(url);
  auto lcm = std::make_unique<lcm::LCM>(effective);
  if (!lcm->good()) {
    throw std::runtime_error("cannot open LCM at '" + (effective.empty() ? std::string("default URL") : effective) +
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

void ServiceLoop::check_identity(double now) {
  const auto holder = duplicates_.older_holder(now);
  if (holder.has_value() == duplicate_) return;
  duplicate_ = holder.has_value();
  for (LoadSource* source : sources_) source->set_serving(!duplicate_);
  if (duplicate_) {
    const std::string why = duplicates_.refusal(*holder);
    std::cerr << heartbeat_.identity().program << "/" << heartbeat_.identity().instance << ": refusing to serve: " << why
              << "\n";
    heartbeat_.set_state(wrc::heartbeat_t::DUPLICATE, why);
  } else {
    std::cerr << heartbeat_.identity().program << "/" << heartbeat_.identity().instance
              << ": the older holder of the name is gone; serving\n";
    heartbeat_.set_state(wrc::heartbeat_t::READY);
  }
}

bool ServiceLoop::listen(double seconds) {
  const double end = monotonic_seconds() + seconds;
  for (double left = seconds; left > 0.0 && !ShutdownSignal::requested(); left = end - monotonic_seconds()) {
    if (handle_any(inboxes_, static_cast<int>(std::ceil(std::min(left, max_wait_) * 1e3))) < 0 && errno != EINTR) {
      return false;
    }
    heartbeat_.tick();
  }
  return true;
}

void ServiceLoop::run_idle_hook() {
  // No exception of the service's own work ends the process: it is logged (at most once per
  // second, with the count of those not logged) and the loop goes on serving and heartbeating.
  std::string failure;
  try {
    idle_hook_();
    return;
  } catch (const std::exception& e) {
    failure = e.what();
  } catch (...) {
    failure = "unknown exception";
  }
  ++idle_failures_;
  const double now = monotonic_seconds();
  if (now < next_idle_failure_log_) return;
  std::cerr << "service loop: the service's periodic work failed: " << failure;
  if (idle_failures_ > 1) std::cerr << " (" << idle_failures_ << " failures so far)";
  std::cerr << "; the service goes on\n";
  next_idle_failure_log_ = now + 1.0;
}

int ServiceLoop::run() {
  heartbeat_.start_keeper(kMaxBusyLoop);
  if (!listen(1.1 * heartbeat_.period())) {
    std::cerr << "service loop: LCM failed while listening for other instances, stopping\n";
    heartbeat_.set_state(wrc::heartbeat_t::DRAINING);
    return 1;
  }
  double period_start = monotonic_seconds();
  report_load(0.0);
  if (duplicates_.older_holder(period_start)) {
    check_identity(period_start);
  } else {
    heartbeat_.set_state(wrc::heartbeat_t::READY);
  }
  int exit_code = 0;
  int consecutive_errors = 0;
  while (!ShutdownSignal::requested()) {
    const double wait = std::min(max_wait_, heartbeat_.seconds_until_due());
    int rc = handle_any(inboxes_, static_cast<int>(std::ceil(wait * 1e3)));
    if (rc > 0) {
      // drain what is already queued without waiting; the burst length measures the queue
      int burst = 0;
      while (!ShutdownSignal::requested() && (rc = handle_any(inboxes_, 0)) > 0) ++burst;
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
    if (idle_hook_) run_idle_hook();
    if (const double now = monotonic_seconds(); now >= next_identity_check_) {
      check_identity(now);
      next_identity_check_ = now + 0.25 * heartbeat_.period();  // heartbeats come once a period
    }
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
