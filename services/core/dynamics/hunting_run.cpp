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

// Whether an envelope's growth per cycle (0: not measured) holds within the tolerance.
bool envelope_holds(double envelope_growth, const HuntingSettings& s) {
  return envelope_growth > 0 && std::abs(envelope_growth - 1.0) <= s.growth_tolerance;
}

HuntingState judge(const CycleMeasurement& c, double envelope_growth, const HuntingSettings& s) {
  if (c.largest < s.centred_amplitude) return HuntingState::kCentred;
  if (c.cycles < 2) return HuntingState::kDecaying;  // no oscillation to measure yet (an aperiodic decay)
  if (std::abs(c.growth - 1.0) <= s.growth_tolerance) return HuntingState::kLimitCycle;
  // The last cycles grow or shrink, but the envelope holds against the window before: the cycles
  // differ from one another (irregular motion), the oscillation does not die out. A regular decay
  // or growth shows in the envelope as in the cycles.
  if (envelope_holds(envelope_growth, s)) return HuntingState::kIrregular;
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
  // the second half of the run instead, if that holds more. Samples after now do not count.
  constexpr int kPeriods = 3;
  const double end = std::nextafter(now, std::numeric_limits<double>::infinity());
  const CycleMeasurement window = measure_cycle(s.t, s.y, now - settings.window, kPeriods, end);
  double from = now - settings.window;
  result.cycle = window;
  if (window.cycles < 3 && now > 2 * settings.window) {
    const CycleMeasurement longer = measure_cycle(s.t, s.y, 0.5 * now, kPeriods, end);
    if (longer.cycles > window.cycles) {
      from = 0.5 * now;
      result.cycle = longer;
    }
  }
  result.yaw_amplitude = measure_cycle(s.t, s.yaw, from, kPeriods, end).amplitude;
  result.largest_contact_angle = 0;
  for (std::size_t i = 0; i < s.t.size(); ++i)
    if (s.t[i] >= from && s.t[i] <= now) result.largest_contact_angle = std::max(result.largest_contact_angle, s.angle[i]);
  result.flange_contact = result.largest_contact_angle > settings.flange_contact_angle;
  // The envelope, the largest cycle of the last window, against the window before it, per period
  // of the last window elapsed.
  result.envelope = window.largest_amplitude;
  const double previous =
      measure_cycle(s.t, s.y, now - 2 * settings.window, kPeriods, now - settings.window).largest_amplitude;
  const double periods = window.period > 0 ? settings.window / window.period : 0.0;
  result.envelope_growth = now >= 2 * settings.window - 1e-9 && previous > 0 && result.envelope > 0 && periods > 0
                               ? std::pow(result.envelope / previous, 1.0 / periods)
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
  // shows over the check period's cycles), or irregular with its envelope held over a window.
  double next_check = settings.settle_time;
  bool settled = false;
  double previous_amplitude = -1;
  // Judgements in a row whose envelope held, and how many span a window (both ends included).
  int held_judgements = 0;
  const int judgements_over_a_window = static_cast<int>(std::ceil(settings.window / settings.check_period - 1e-9)) + 1;
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
    // Irregular, its envelope held at every judgement over a whole window (irregular, or a cycle
    // whose last three agreed by chance): its cycles never agree for long, so waiting settles
    // nothing more.
    const bool held = (result.state == HuntingState::kIrregular || result.state == HuntingState::kLimitCycle) &&
                      envelope_holds(result.envelope_growth, settings);
    held_judgements = held ? held_judgements + 1 : 0;
    if (result.state == HuntingState::kIrregular && held_judgements >= judgements_over_a_window) {
      settled = true;
      break;
    }
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
