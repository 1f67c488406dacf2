// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// What a sweep is, written once into its work directory (sweep.json) so that every run of it,
/// here or as a Slurm task on another node, and every resume reads the same: the grid, the `wrc
/// run` options every run gets, what is extracted, and the speeds of the critical-speed scan.
///
/// The grid's keys are the run parameters (core/dynamics/run_parameter_table.hpp: speed, friction,
/// y0, ...), the profile and track options (wheel, rail, gauge, inclination, ...) and the run
/// options model, suspension, params, track, irregularities and swap_at: each key K is `wrc run
/// --K` ('_' written '-'), so a run of a grid point is `wrc run` with the fixed options and one
/// `--K VALUE` per key, parsed and checked by `wrc run`'s own option table.

#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/sweep/sweep_grid.hpp"
#include "protocol/run/run_command_codec.hpp"

namespace wrc::cli {

struct SweepDefinition {
  std::vector<sweep::GridAxis> axes;
  std::vector<std::string> run_options;  ///< `wrc run` options every run gets (after `--`)
  std::vector<std::string> extract;      ///< groups and summary paths, as given to --extract
  std::string critical_speeds;           ///< FROM:TO:STEP [m/s] of the critical-speed scan
  /// The runs on the bus's services (each on a wrc-dynamicsd of its own, the contact queries spread
  /// over the READY instances of its model) instead of in-process.
  bool bus = false;

  nlohmann::json to_json() const;
  /// @throws std::invalid_argument naming what is missing or wrong; source names the file.
  static SweepDefinition from_json(const nlohmann::json& j, const std::string& source);
  bool operator==(const SweepDefinition& other) const { return to_json() == other.to_json(); }
};

/// The unit of grid key key, "-" for a key without one (a profile, a file).
/// @throws UsageError naming the key and the keys a grid may have when key is none of them.
std::string grid_key_unit(const std::string& key);

/// Checks options meant for every run: `wrc run` options, none of those a sweep sets itself
/// (--summary, --history, --run-id, --in-process, --dynamics-instance), none that only the bus
/// knows (--lcm-url, --channel-prefix, ...) unless the runs are on the bus, none that is also a
/// grid key. @throws UsageError naming the option.
void check_run_options(const std::vector<std::string>& run_options, const std::vector<sweep::GridAxis>& axes,
                       bool bus);

/// The `wrc run` arguments of the run at values (one per axis): the fixed options, then --KEY VALUE.
std::vector<std::string> run_arguments(const SweepDefinition& definition, const std::vector<std::string>& values);

/// The run request of those arguments, parsed by `wrc run`'s option table, in-process (or on the
/// bus), named run_id; what `wrc run` would print about it (a lateral load set to 0 on a track)
/// goes to notes. @throws UsageError naming the option for a bad value, std::invalid_argument for
/// an invalid run.
protocol::RunRequest sweep_run_request(const std::vector<std::string>& arguments, const std::string& run_id,
                                       std::ostream& notes, bool bus = false);

}  // namespace wrc::cli
