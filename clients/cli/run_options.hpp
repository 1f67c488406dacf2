// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// `wrc run`'s options and the run request they describe: the run's own (--model, --summary,
/// --params, --vehicle, --suspension, --swap-at, --history, --in-process, --run-id), one per entry of the
/// run request table (protocol/run/run_request_table.hpp: every run parameter and the contact
/// client's settings, defaults and rules the table's), the service start and profile options.

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "cli/options.hpp"
#include "core/dynamics/wheelset_parameters.hpp"
#include "core/vehicle/vehicle_description.hpp"
#include "protocol/run/run_command_codec.hpp"

namespace wrc::cli {

/// --params, --vehicle and --suspension: where a wheelset's parameters come from before the
/// parameter options (`wrc run`, `wrc sweep`, `wrc stability`, `wrc bifurcation`).
std::vector<OptionSpec> wheelset_source_option_specs();
/// spec's parameters from --params (the run parameter file), then its wheelset's from --vehicle (a
/// vehicle file of one wheelset on the track, apply_single_wheelset(); a line to notes says which),
/// then --suspension. The parameter options come after, in each caller. With several_bodies, a
/// vehicle file of several bodies goes there instead (the vehicle's equations run it; the options
/// it gives are refused, refuse_options_a_vehicle_gives()).
/// @throws UsageError for --vehicle with --suspension or a vehicle file that is bad or (without
///         several_bodies) more than one wheelset on the track, naming the file;
///         std::invalid_argument for a bad parameter file.
void apply_wheelset_sources(const Options& options, RunSpec& spec, std::ostream& notes,
                            std::optional<VehicleDescription>* several_bodies = nullptr);

/// The one rule for a vehicle of several bodies: its file gives every wheelset's and body's mass,
/// inertias, loads and suspension, so --suspension and those parameter options (--mass,
/// --vertical-force, ...) are refused, naming the option.
void refuse_options_a_vehicle_gives(const Options& options);

/// Every option of `wrc run`, in --help order.
std::vector<OptionSpec> run_option_specs();

/// The one rule for a lateral load a command does not want from the parameters (`wrc stability`,
/// `wrc bifurcation`, `wrc run --track`): unless --lateral-force is on the command line (its value,
/// 0 or not, is kept), a non-zero lateral load of the parameters (the benchmark's, or a --params
/// file's: only the command-line option counts as explicit) is set to 0, and notes gets the line
/// "lateral load: <F> N of the parameters set to 0 (<why>)". Nothing happens to a load already 0.
void zero_lateral_load_unless_given(const Options& options, WheelsetParameters& wheelset, const std::string& why,
                                    std::ostream& notes);

/// Why `wrc run --track` sets the parameters' lateral load to 0 (zero_lateral_load_unless_given).
inline constexpr const char* kTrackLateralLoadReason =
    "a track layout's curves load the wheelset with their centrifugal force; --lateral-force F keeps a load";

/// The request of parsed options: the benchmark (RunSpec{}), then --params, --vehicle and
/// --suspension (apply_wheelset_sources), then the options; with
/// --track and without --lateral-force the parameters' lateral load is set to 0
/// (zero_lateral_load_unless_given, its line to notes).
/// @throws UsageError naming the option, std::invalid_argument for an invalid parameter file or run.
protocol::RunRequest run_request_from(const Options& options, std::ostream& notes);

/// Scheduled swaps of --swap-at "T:M[,T2:M2...]", times increasing within (0, t_end) [s].
std::vector<protocol::ScheduledSwap> parse_swaps(const std::string& text, double t_end);

}  // namespace wrc::cli
