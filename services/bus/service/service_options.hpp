// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The command-line options every service process shares:
/// `--lcm-url URL`, `--channel-prefix P`, `--instance NAME`, `--heartbeat-period S`,
/// `--bus-key FILE`, `--help`.
/// Options a service defines itself (e.g. `--model`) are passed through in `rest`. Parsed by the
/// one option parser of wrc (options/options.hpp, Unknown::kPassedOn); given twice, the last
/// one wins (`wrc launch --lcm-url U` appends to a launch profile's line).

#include <string>
#include <vector>

namespace wrc::bus {

/// Checks an instance name given to option: 1-24 letters, digits, '_' or '-'; throws
/// std::invalid_argument naming option and the name otherwise.
void check_instance_name(const std::string& option, const std::string& name);

/// Parsed common service options.
struct ServiceOptions {
  std::string lcm_url;           ///< LCM URL; empty = LCM's default (or $LCM_DEFAULT_URL)
  std::string channel_prefix;    ///< channel prefix; empty = none
  std::string instance = "0";    ///< instance name, unique per model on one bus
  double heartbeat_period = 0.5; ///< [s] heartbeat period
  std::string bus_key;           ///< bus key file; empty = $WRC_BUS_KEY or the default (bus/auth/bus_key.hpp)
  bool help = false;             ///< --help was given
  std::vector<std::string> rest; ///< arguments not consumed here, in order

  /// Parses argv[1..]. Throws std::invalid_argument with a one-line message naming the bad
  /// option or value (missing value, period not in [kMinHeartbeatPeriod, kMaxHeartbeatPeriod] = [0.01, 10] s, bad instance name).
  static ServiceOptions parse(int argc, const char* const* argv);
  /// Help text of the common options, one line each (from the table).
  static std::string help_text();
};

}  // namespace wrc::bus
