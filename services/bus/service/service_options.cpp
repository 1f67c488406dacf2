// SPDX-License-Identifier: Apache-2.0
#include "bus/service/service_options.hpp"

#include <cctype>
#include <optional>
#include <stdexcept>

#include "bus/service/heartbeat_publisher.hpp"
#include "core/numerics/number_text.hpp"
#include "options/options.hpp"

namespace wrc::bus {

void check_instance_name(const std::string& option, const std::string& name) {
  bool ok = !name.empty() && name.size() <= 24;
  for (char c : name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-');
  if (!ok) throw std::invalid_argument(option + ": '" + name + "' must be 1-24 letters, digits, '_' or '-'");
}

namespace {
double parse_period(const std::string& text) {
  const std::optional<double> value = finite_number(text);
  if (!value || !(*value >= kMinHeartbeatPeriod) || !(*value <= kMaxHeartbeatPeriod)) {
    throw std::invalid_argument("--heartbeat-period: '" + text + "' is not a number in [0.01, 10] s");
  }
  return *value;
}


/// The options every service shares, in the order --help lists them.
std::vector<OptionSpec> service_option_specs() {
  return {
      {"--lcm-url", true, "LCM URL", "LCM's own, udpm ttl=0, or $LCM_DEFAULT_URL"},
      {"--channel-prefix", true, "prefix of every channel, P.HEARTBEAT etc.", "none"},
      {"--instance", true, "instance name, unique per model on the bus", "0"},
      {"--heartbeat-period", true, "heartbeat period [s]", "0.5"},
      {"--bus-key", true, "file of the bus key messages are signed with", "$WRC_BUS_KEY, else ~/.config/wrc/bus.key"},
  };
}
}  // namespace

ServiceOptions ServiceOptions::parse(int argc, const char* const* argv) {
  const std::vector<std::string> args(argv + (argc > 0 ? 1 : 0), argv + (argc > 0 ? argc : 0));
  // The service's own options are not known here: they, and every argument not starting with --,
  // pass on to the service's parser. Given twice, the last one wins (`wrc launch --lcm-url U`
  // appends to the launch profile's line).
  ParseRules rules;
  rules.unknown = Unknown::kPassedOn;
  rules.repeated = Repeated::kLastWins;
  const std::string program = argc > 0 && argv[0] != nullptr ? std::string(argv[0]) : std::string("service");
  const Options parsed = [&] {
    try {
      return Options::for_program(program, "[options]", service_option_specs(), args, rules);
    } catch (const UsageError& e) {
      throw std::invalid_argument(e.what());
    }
  }();
  ServiceOptions options;
  options.help = parsed.help_requested();
  options.lcm_url = parsed.text("--lcm-url");
  options.channel_prefix = parsed.text("--channel-prefix");
  options.bus_key = parsed.text("--bus-key");
  if (parsed.has("--instance")) {
    options.instance = parsed.text("--instance");
    check_instance_name("--instance", options.instance);
  }
  if (parsed.has("--heartbeat-period")) options.heartbeat_period = parse_period(parsed.text("--heartbeat-period"));
  options.rest = parsed.passed_on();
  return options;
}

std::string ServiceOptions::help_text() { return Options::option_lines(service_option_specs()); }

}  // namespace wrc::bus
