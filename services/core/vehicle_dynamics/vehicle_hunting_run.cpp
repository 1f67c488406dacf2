// SPDX-License-Identifier: Apache-2.0
#include "core/vehicle_dynamics/vehicle_hunting_run.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace wrc {
namespace {

bool same_state(const InitialState& a, const InitialState& b) {
  return a.y == b.y && a.yaw == b.yaw && a.y_dot == b.y_dot && a.yaw_dot == b.yaw_dot &&
         a.spin_rate_offset == b.spin_rate_offset;
}

// The ends of a runner's runs, each with the whole vehicle's state there.
struct RunEnds {
  std::vector<std::pair<InitialState, VehicleStart>> ends;
  const VehicleStart* find(const InitialState& lateral) const {
    for (const auto& [end, vehicle] : ends)
      if (same_state(end, lateral)) return &vehicle;
    return nullptr;
  }
};

HuntingRun run_vehicle_hunting(const VehicleRunSpec& base, double speed, const InitialState& start,
                               const std::shared_ptr<ContactEvaluator>& contact, double nominal_radius,
                               const HuntingSettings& settings, RunEnds& ends) {
  if (!(std::isfinite(speed) && speed > 0))
    throw std::invalid_argument("vehicle hunting run: speed = " + std::to_string(speed) + " m/s, must be > 0");
  VehicleRunSpec spec = base;
  spec.run.wheelset.speed = speed;
  spec.run.track = TrackLayout{};
  spec.run.irregularity = TrackIrregularity{};
  spec.run.integrator.t_end = settings.max_time;
  spec.run.integrator.output_period = 1e-3;
  spec.run.initial = InitialState{};
  if (const VehicleStart* continued = ends.find(start))
    spec.start = *continued;
  else {
    spec.start.reset();
    spec.run.initial.y = start.y;
    spec.run.initial.yaw = start.yaw;
    spec.run.initial.y_dot = start.y_dot;  // refused unless 0: a fresh start is at rest
    spec.run.initial.yaw_dot = start.yaw_dot;
    spec.run.initial.spin_rate_offset = start.spin_rate_offset;
  }
  HuntingRun result;
  result.speed = speed;
  result.start = start;
  HuntingSamples s;
  VehicleSimulation simulation(spec, contact, nominal_radius);
  simulation.on_output([&](const VehicleSnapshot& v) { s.add(simulation.wheelset_snapshot(v, 0)); });
  if (!follow_hunting(simulation, s, settings, result)) return result;
  VehicleStart whole = simulation.continuation();
  const WheelsetSnapshot w = simulation.wheelset_snapshot(simulation.snapshot(), 0);
  result.end.y = w.y;
  result.end.yaw = w.yaw;
  result.end.y_dot = w.y_dot;
  result.end.yaw_dot = w.yaw_dot;
  result.end.spin_rate_offset = w.spin_rate - speed / nominal_radius;
  ends.ends.emplace_back(result.end, std::move(whole));
  return result;
}

}  // namespace

HuntingRunner vehicle_hunting_runner(VehicleRunSpec base, std::shared_ptr<ContactEvaluator> contact,
                                     double nominal_radius, HuntingSettings settings) {
  settings.validate();
  auto ends = std::make_shared<RunEnds>();
  return [base = std::move(base), contact = std::move(contact), nominal_radius, settings, ends](
             double speed, const InitialState& start) {
    return run_vehicle_hunting(base, speed, start, contact, nominal_radius, settings, *ends);
  };
}

}  // namespace wrc
