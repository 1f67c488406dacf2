#pragma once
/// @file
/// `wrc run`'s options and the run request they describe: the run's own (--model, --summary,
/// --params, --suspension, --swap-at, --history, --in-process, --run-id), one per entry of the
/// run request table (protocol/run/run_request_table.hpp: every run parameter and the contact
/// client's settings, defaults and rules the table's), the service start and profile options.

#include <string>
#include <vector>

#include "cli/options.hpp"
#include "protocol/run/run_command_codec.hpp"

namespace wrc::cli {

/// Every option of `wrc run`, in --help order.
std::vector<OptionSpec> run_option_specs();

/// The request of parsed options: the benchmark (RunSpec{}), then --params, then the options.
/// @throws UsageError naming the option, std::invalid_argument for an invalid parameter file or run.
protocol::RunRequest run_request_from(const Options& options);

/// Scheduled swaps of --swap-at "T:M[,T2:M2...]", times increasing within (0, t_end) [s].
std::vector<protocol::ScheduledSwap> parse_swaps(const std::string& text, double t_end);

}  // namespace wrc::cli
