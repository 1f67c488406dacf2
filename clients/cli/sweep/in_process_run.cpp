// SPDX-License-Identifier: Apache-2.0
#include "cli/sweep/in_process_run.hpp"

#include <chrono>
#include <optional>
#include <string>

#include "core/dynamics/wheelset_simulation.hpp"
#include "core/vehicle_dynamics/vehicle_simulation.hpp"
#include "protocol/run/run_output_codec.hpp"

namespace wrc::cli {

run_summary_t run_in_process(const protocol::RunRequest& request) {
  const auto start = std::chrono::steady_clock::now();
  const auto geometry = std::make_shared<const WheelsetGeometry>(make_geometry(request.geometry));
  const auto contact = [&](const std::string& model) { return in_process_contact(model, geometry, request.spline_fit); };
  const double r0 = request.geometry.track.nominal_radius;
  // The swaps, the start (it throws when no consistent initial state exists: the run never
  // started) and the run (a failure on the way ends it: state failed, its message), then the summary.
  const auto run = [&](auto& simulation) {
    for (const protocol::ScheduledSwap& swap : request.swaps) simulation.schedule_swap(swap.t, contact(swap.model));
    simulation.start();
    simulation.run();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return protocol::to_summary_message(simulation, request.run_id, 0, wall);
  };
  if (!request.vehicle) {
    WheelsetSimulation simulation(request.spec, contact(request.model), r0);
    return run(simulation);
  }
  VehicleSimulation simulation(VehicleRunSpec{*request.vehicle, request.spec, std::nullopt}, contact(request.model), r0);
  run_summary_t summary = run(simulation);
  if (summary.message.empty()) summary.message = simulation.start_note();  // as wrc-dynamicsd's
  return summary;
}

}  // namespace wrc::cli
