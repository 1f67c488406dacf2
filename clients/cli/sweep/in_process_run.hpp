// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A run of `wrc run`'s request in this process, without the bus: the geometry, the contact model
/// evaluated here (the spline model fitted here, as `wrc run --in-process` has wrc-dynamicsd do),
/// the scheduled swaps, and the simulation to its end (the lone wheelset's, or with a vehicle of
/// several bodies the vehicle's), summarised as wrc-dynamicsd summarises it.
/// What a sweep's runs are: independent processes that share no bus and no service, so any number
/// run side by side on one machine or on a cluster's nodes.

#include <memory>
#include <string>

#include "cli/in_process_contact.hpp"
#include "protocol/run/run_command_codec.hpp"
#include "wrc/run_summary_t.hpp"

namespace wrc::cli {

/// Runs request to its end (finished, or failed with the simulation's message) and returns its
/// summary, wall_time the run's own [s]. @throws what building the geometry, the contact or the
/// simulation throws (an invalid request; the run never started).
run_summary_t run_in_process(const protocol::RunRequest& request);

}  // namespace wrc::cli
