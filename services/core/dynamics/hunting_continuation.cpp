// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/hunting_continuation.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace wrc {

void ContinuationSettings::validate() const {
  run.validate();
  small_disturbance.validate();
  large_disturbance.validate();
  if (!(std::isfinite(speed_tolerance) && speed_tolerance > 0))
    throw std::invalid_argument("continuation settings: speed_tolerance = " + std::to_string(speed_tolerance) +
                                " m/s, must be > 0");
  if (!(std::isfinite(persisting_amplitude) && persisting_amplitude >= 0))
    throw std::invalid_argument("continuation settings: persisting_amplitude = " +
                                std::to_string(persisting_amplitude) + " m, must be >= 0");
}

HuntingRunner hunting_runner(RunSpec base, std::shared_ptr<ContactEvaluator> contact, double nominal_radius,
                             HuntingSettings settings) {
  return [base = std::move(base), contact = std::move(contact), nominal_radius, settings](double speed,
                                                                                        const InitialState& start) {
    return run_hunting(base, speed, start, contact, nominal_radius, settings);
  };
}

HuntingDiagram trace_hunting(const std::vector<double>& speeds, const HuntingRunner& run,
                             const ContinuationSettings& settings,
                             const std::function<void(const char* branch, const HuntingRun&)>& progress) {
  settings.validate();
  if (speeds.size() < 2)
    throw std::invalid_argument("trace_hunting: " + std::to_string(speeds.size()) + " speeds, need at least 2");
  for (std::size_t i = 1; i < speeds.size(); ++i)
    if (!(speeds[i] > speeds[i - 1]))
      throw std::invalid_argument("trace_hunting: speeds not ascending at " + std::to_string(speeds[i]) + " m/s");
  auto persists = [&](const HuntingRun& r) { return r.persists() && r.amplitude() >= settings.persisting_amplitude; };
  auto report = [&](const char* branch, const HuntingRun& r) {
    if (progress) progress(branch, r);
  };
  HuntingDiagram d;
  for (double v : speeds) {
    d.centred.push_back(run(v, settings.small_disturbance));
    report("centred", d.centred.back());
  }
  // Ramp-down: each speed from the previous run's end, while the cycle persists.
  InitialState start = settings.large_disturbance;
  std::optional<HuntingRun> last_persisting;
  double collapse = 0;
  bool collapsed = false;
  for (auto v = speeds.rbegin(); v != speeds.rend(); ++v) {
    d.ramp_down.push_back(run(*v, start));
    const HuntingRun& r = d.ramp_down.back();
    report("ramp-down", r);
    if (r.state == HuntingState::kFailed) break;
    if (!persists(r)) {
      collapsed = last_persisting.has_value();
      collapse = r.speed;
      break;
    }
    last_persisting = r;
    start = r.end;
  }
  if (!collapsed) return d;  // the cycle never existed, failed, or persisted down to the lowest speed
  // Bisection between the last persisting speed (its end state carried down) and the collapse.
  HuntingRun upper = *last_persisting;
  double lower = collapse;
  while (upper.speed - lower > settings.speed_tolerance) {
    const double mid = 0.5 * (upper.speed + lower);
    d.refinement.push_back(run(mid, upper.end));
    const HuntingRun& r = d.refinement.back();
    report("refinement", r);
    if (r.state == HuntingState::kFailed) break;
    if (persists(r))
      upper = r;
    else
      lower = mid;
  }
  d.critical.found = true;
  d.critical.speed = upper.speed;
  d.critical.collapsed_at = lower;
  d.critical.cycle = upper;
  return d;
}

UnstableCycle unstable_cycle(const HuntingRunner& run, double speed, double decays_from, double grows_from,
                             int iterations) {
  if (!(grows_from > decays_from))
    throw std::invalid_argument("unstable_cycle: grows_from = " + std::to_string(grows_from) +
                                " m must be above decays_from = " + std::to_string(decays_from) + " m");
  if (iterations < 1) throw std::invalid_argument("unstable_cycle: iterations = " + std::to_string(iterations));
  UnstableCycle u;
  u.speed = speed;
  u.decaying_start = decays_from;
  u.growing_start = grows_from;
  for (int i = 0; i < iterations; ++i) {
    const double mid = 0.5 * (u.decaying_start + u.growing_start);
    HuntingRun r = run(speed, InitialState{mid, 0, 0, 0, 0});
    ++u.runs;
    const bool decays = r.state == HuntingState::kCentred ||
                        (r.state != HuntingState::kFailed && r.state != HuntingState::kIrregular && r.cycle.growth < 1.0);
    if (decays) {
      u.decaying_start = mid;
      u.run = std::move(r);
    } else {
      u.growing_start = mid;
    }
  }
  return u;
}

}  // namespace wrc
