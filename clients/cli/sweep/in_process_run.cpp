// SPDX-License-Identifier: Apache-2.0
#include "cli/sweep/in_process_run.hpp"

#include <chrono>
#include <optional>

#include "core/dynamics/wheelset_simulation.hpp"
#include "core/vehicle_dynamics/vehicle_simulation.hpp"
#include "protocol/run/run_output_codec.hpp"

namespace wrc::cli {

run_summary_t run_in_process(const protocol::RunRequest& request) {
  const auto start = std::chrono::steady_clock::now();
  const auto geometry = std::make_shared<const WheelsetGeometry>(make_geometry(request.geometry));
  const auto wall = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  if (request.vehicle) {  // a vehicle of several bodies
    VehicleSimulation simulation(VehicleRunSpec{*request.vehicle, request.spec, std::nullopt},
                                 in_process_contact(request.model, geometry, request.spline_fit), request.geometry.track.nominal_radius);
    for (const protocol::ScheduledSwap& swap : request.swaps)
      simulation.schedule_swap(swap.t, in_process_contact(swap.model, geometry, request.spline_fit));
    simulation.start();
    simulation.run();
    run_summary_t summary = protocol::to_summary_message(simulation, request.run_id, 0, wall());
    if (summary.message.empty()) summary.message = simulation.start_note();  // as wrc-dynamicsd's
    return summary;
  }
  WheelsetSimulation simulation(request.spec, in_process_contact(request.model, geometry, request.spline_fit),
                                request.geometry.track.nominal_radius);
  for (const protocol::ScheduledSwap& swap : request.swaps)
    simulation.schedule_swap(swap.t, in_process_contact(swap.model, geometry, request.spline_fit));
  simulation.start();  // throws when no consistent initial state exists: the run never started
  simulation.run();    // a failure on the way ends the run (state failed, its message)
  return protocol::to_summary_message(simulation, request.run_id, 0, wall());
}

}  // namespace wrc::cli
