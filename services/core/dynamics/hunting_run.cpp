// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/hunting_run.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/dynamics/wheelset_simulation.hpp"

namespace wrc {
namespace {

void require(bool ok, const char* name, double value, const char* range) {
  if (!ok)
    throw std::invalid_argument(std::string("hunting settings: ") + name + " = " + std::to_string(value) +
                                ", must be " + range);
}

// envelope_growth: 0 until the run holds two windows.
HuntingState judge(const CycleMeasurement& c, double envelope_growth, const HuntingSettings& s) {
  if (c.largest < s.centred_amplitude) return HuntingState::kCentred;
  if (c.cycles < 2) return HuntingState::kDecaying;  // no oscillation to measure yet (an aperiodic decay)
  const bool cycle_holds = std::abs(c.growth - 1.0) <= s.growth_tolerance;
  if (cycle_holds) return HuntingState::kLimitCycle;
  // The last cycles grow or shrink, but the envelope over the whole window holds: the cycles
  // differ from one another (irregular motion), the oscillation does not die out. A regular decay
  // or growth shows in the envelope as in the cycles.
  if (envelope_growth > 0 && std::abs(envelope_growth - 1.0) <= s.growth_tolerance) return HuntingState::kIrregular;
  return c.growth < 1.0 ? HuntingState::kDecaying : HuntingState::kGrowing;
}

}  // namespace

void HuntingSettings::validate() const {
  require(std::isfinite(settle_time) && settle_time > 0, "settle_time", settle_time, "> 0 [s]");
  require(std::isfinite(max_time) && max_time >= settle_time, "max_time", max_time, ">= settle_time [s]");
  require(std::isfinite(window) && window > 0 && window <= settle_time, "window", window,
          "in (0, settle_time] [s] (the start is no part of a cycle)");
  require(std::isfinite(check_period) && check_period > 0, "check_period", check_period, "> 0 [s]");
  require(std::isfinite(centred_amplitude) && centred_amplitude > 0, "centred_amplitude", centred_amplitude, "> 0 [m]");
  require(growth_tolerance > 0 && growth_tolerance < 1, "growth_tolerance", growth_tolerance, "in (0, 1)");
  require(flange_contact_angle > 0 && flange_contact_angle < M_PI / 2, "flange_contact_angle", flange_contact_angle,
          "in (0, pi/2) [rad]");
}

const char* hunting_state_name(HuntingState state) {
  switch (state) {
    case HuntingState::kCentred: return "centred";
    case HuntingState::kDecaying: return "decaying";
    case HuntingState::kLimitCycle: return "limit-cycle";
    case HuntingState::kGrowing: return "growing";
    case HuntingState::kIrregular: return "irregular";
    case HuntingState::kFailed: return "failed";
  }
  return "?";
}

void HuntingSamples::add(const WheelsetSnapshot& w) {
  t.push_back(w.t);
  y.push_back(w.y);
  yaw.push_back(w.yaw);
  angle.push_back(std::max(std::abs(w.wheels[0].contact_angle), std::abs(w.wheels[1].contact_angle)));
}

void judge_hunting(const HuntingSamples& s, double now, const HuntingSettings& settings, HuntingRun& result) {
  // The last window; when it holds fewer than 3 cycles (a slow oscillation: at low speed the
  // kinematic wavelength of some 5 m takes seconds) and the run is longer than twice the window,
  // the second half of the run instead, if that holds more.
  const CycleMeasurement window = measure_cycle(s.t, s.y, now - settings.window);
  double from = now - settings.window;
  result.cycle = window;
  if (window.cycles < 3 && now > 2 * settings.window) {
    const CycleMeasurement longer = measure_cycle(s.t, s.y, 0.5 * now);
    if (longer.cycles > window.cycles) {
      from = 0.5 * now;
      result.cycle = longer;
    }
  }
  result.yaw_amplitude = measure_cycle(s.t, s.yaw, from).amplitude;
  result.largest_contact_angle = 0;
  for (std::size_t i = 0; i < s.t.size(); ++i)
    if (s.t[i] >= from) result.largest_contact_angle = std::max(result.largest_contact_angle, s.angle[i]);
  result.flange_contact = result.largest_contact_angle > settings.flange_contact_angle;
  // The envelope of the last window against the window before it, per cycle of the last.
  result.envelope = half_range(s.t, s.y, now - settings.window, std::numeric_limits<double>::infinity());
  const double previous = half_range(s.t, s.y, now - 2 * settings.window, now - settings.window);
  result.envelope_growth = now - 2 * settings.window >= 0 && previous > 0 && window.cycles > 0
                               ? std::pow(result.envelope / previous, 1.0 / window.cycles)
                               : 0.0;
  result.state = judge(result.cycle, result.envelope_growth, settings);
}

bool follow_hunting(Simulation& simulation, const HuntingSamples& s, const HuntingSettings& settings,
                    HuntingRun& result) {
  settings.validate();
  auto measure = [&] { judge_hunting(s, simulation.time(), settings, result); };
  try {
    simulation.start();
  } catch (const std::exception& e) {
    result.state = HuntingState::kFailed;
    result.message = std::string("no consistent initial state: ") + e.what();
    return false;
  }
  // Settled: centred, or a constant amplitude at two successive judgements whose amplitudes agree
  // within the growth tolerance (a slow decay or growth of less than the tolerance per cycle
  // shows over the check period's cycles), or irregular after a judgement whose envelope held.
  double next_check = settings.settle_time;
  bool settled = false;
  double previous_amplitude = -1;
  bool envelope_held_before = false;
  while (simulation.advance()) {
    if (simulation.time() + 1e-12 < next_check) continue;
    next_check += settings.check_period;
    measure();
    if (result.state == HuntingState::kCentred) {
      settled = true;
      break;
    }
    if (result.state == HuntingState::kLimitCycle) {
      if (previous_amplitude > 0 &&
          std::abs(result.cycle.amplitude / previous_amplitude - 1.0) < settings.growth_tolerance) {
        settled = true;
        break;
      }
      previous_amplitude = result.cycle.amplitude;
    } else {
      previous_amplitude = -1;
    }
    // Irregular after a judgement whose envelope held too (irregular, or a cycle whose last three
    // agreed by chance): its cycles never agree for long, so waiting settles nothing more.
    if (result.state == HuntingState::kIrregular && envelope_held_before) {
      settled = true;
      break;
    }
    envelope_held_before = (result.state == HuntingState::kIrregular || result.state == HuntingState::kLimitCycle) &&
                           result.envelope_growth > 0 &&
                           std::abs(result.envelope_growth - 1.0) <= settings.growth_tolerance;
  }
  result.simulated_time = simulation.time();
  if (simulation.state() == RunState::kFailed) {
    measure();
    result.state = HuntingState::kFailed;
    result.message = simulation.message();
  } else if (!settled) {
    measure();
  }
  return true;
}

HuntingRun run_hunting(const RunSpec& base, double speed, const InitialState& start,
                       std::shared_ptr<ContactEvaluator> contact, double nominal_radius,
                       const HuntingSettings& settings) {
  settings.validate();
  if (!(std::isfinite(speed) && speed > 0))
    throw std::invalid_argument("run_hunting: speed = " + std::to_string(speed) + " m/s, must be > 0");
  RunSpec spec = base;
  spec.wheelset.speed = speed;
  spec.initial = start;
  spec.track = TrackLayout{};
  spec.irregularity = TrackIrregularity{};
  spec.integrator.t_end = settings.max_time;
  spec.integrator.output_period = 1e-3;

  HuntingRun result;
  result.speed = speed;
  result.start = start;
  HuntingSamples s;
  WheelsetSimulation simulation(spec, std::move(contact), nominal_radius);
  simulation.on_output([&](const WheelsetSnapshot& w) { s.add(w); });
  if (!follow_hunting(simulation, s, settings, result)) return result;
  const WheelsetSnapshot w = simulation.snapshot();
  result.end.y = w.y;
  result.end.yaw = w.yaw;
  result.end.y_dot = w.y_dot;
  result.end.yaw_dot = w.yaw_dot;
  result.end.spin_rate_offset = w.spin_rate - speed / nominal_radius;
  return result;
}

}  // namespace wrc
