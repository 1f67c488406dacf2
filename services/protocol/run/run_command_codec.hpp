// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The START command of a run and its library counterpart: RunRequest (model, geometry, the
/// RunSpec, the contact client's timeouts, the scheduled swaps) <-> run_command_t, and the names of
/// the run states. No transport here.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/dynamics/wheelset_simulation.hpp"
#include "core/geometry/geometry_spec.hpp"
#include "core/spline/spline_fit_options.hpp"
#include "core/vehicle/vehicle_description.hpp"
#include "wrc/run_command_t.hpp"

namespace wrc::protocol {

/// Most swaps a run may schedule (run_command_t.num_scheduled_swaps; `wrc run --swap-at`).
inline constexpr std::size_t kMaxScheduledSwaps = 1000;

/// A swap at a given simulated time.
struct ScheduledSwap {
  double t = 0;       ///< [s]
  std::string model;  ///< model to swap to
};

/// Everything a START command says.
struct RunRequest {
  std::string run_id;
  std::string model;
  std::string instance;           ///< contact model instance (empty: spread over every READY one)
  std::string dynamics_instance;  ///< wrc-dynamicsd instance to run it (empty: any that hears it)
  GeometrySpec geometry;
  bool in_process = false;
  RunSpec spec;
  double contact_timeout = 0.2;  ///< [s] per attempt
  int contact_retries = 3;       ///< [-] re-sends per attempt round
  double contact_wait = 10.0;    ///< [s] how long a run waits for a (restarted) contact service
  std::vector<ScheduledSwap> swaps;
  /// A vehicle of several bodies (docs/vehicle.md), run on the vehicle's equations: its masses,
  /// loads and elements replace spec.wheelset's and its suspension; none: the lone wheelset.
  std::optional<VehicleDescription> vehicle;
  /// The fit of the spline model when the dynamics evaluates it itself (in_process); the spline
  /// services fit with their own.
  SplineFitOptions spline_fit;
};

/// Name of a run_status_t state code, as the summary JSON and the logs write it ("idle",
/// "running", "finished", "failed", "stopped"; "unknown" for any other code).
const char* run_state_name(std::int8_t state);

/// The START command of request (header, request_id are the caller's).
run_command_t to_message(const RunRequest& request);
/// @throws std::invalid_argument naming the first invalid field (unknown model, NaN, range, more
/// than kMaxScheduledSwaps swaps).
RunRequest from_message(const run_command_t& command);

}  // namespace wrc::protocol
