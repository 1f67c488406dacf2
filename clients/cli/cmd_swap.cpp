// SPDX-License-Identifier: Apache-2.0
// wrc swap: hot swap of the contact model of the runs on the bus (CONTACT_SELECT). The selection
// is republished for a second so that it survives packet loss; the dynamics acts on a new
// selection number once, at its next step boundary.
#include <iostream>
#include <string>
#include <vector>

#include "bus/auth/bus_auth.hpp"
#include "bus/auth/signed_publish.hpp"
#include "bus/service/service_loop.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/clock.hpp"
#include "bus/transport/header_stamper.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/service_starter.hpp"
#include "core/models/contact_model_factory.hpp"
#include "wrc/contact_select_t.hpp"

namespace wrc::cli {
namespace {

constexpr int kRepeats = 5;           // [-] copies of the selection
constexpr double kRepeatPeriod = 0.2; // [s] between copies

int run_swap(const std::vector<std::string>& args) {
  const std::vector<OptionSpec> specs{
      {"--run-id", true, "only this run", "every run on the bus"},
      {"--instance", true, "address this instance of the model", "any"},
      {"--channel-prefix", true, "channel prefix of the simulation", "none"},
      {"--lcm-url", true, "LCM URL", "LCM's default"},
      {"--bus-key", true, "bus key file", "$WRC_BUS_KEY, else ~/.config/wrc/bus.key"}};
  const Options o("swap", "MODEL [options]", specs, args, Positional::kAllowed);
  if (o.help_requested()) {
    std::cout << o.help()
              << "\nSwitches the contact model of running wheelset runs to MODEL (onepoint, interp, multipoint,\n"
                 "spline) at their next step boundary. A run whose new service is not on the bus keeps its\n"
                 "model and says why in its status and summary.\n";
    return 0;
  }
  if (o.positional().size() != 1) throw UsageError("swap: give exactly one MODEL (onepoint, interp, multipoint, spline)");
  const std::string model = o.positional().front();
  contact_model_entry(model);
  const bus::ChannelNames names(o.text("--channel-prefix"));
  bus::prepare_bus_key(o.text("--bus-key"), "swap");
  auto lcm = bus::open_lcm(o.text("--lcm-url"));
  contact_select_t select{};
  select.seq = bus::wall_utime();  // later selections have larger numbers
  select.run_id = o.text("--run-id");
  select.model = model;
  select.instance = o.text("--instance");
  bus::HeaderStamper stamper(bus::sender_name("wrc-swap", model));
  for (int k = 0; k < kRepeats; ++k) {
    stamper.stamp(select.header);
    bus::publish_signed(*lcm, names.name(bus::channel::kContactSelect), select);
    handle_until(*lcm, bus::monotonic_seconds() + kRepeatPeriod, [] { return false; });
  }
  std::cerr << "swap: asked every run" << (select.run_id.empty() ? "" : " " + select.run_id) << " to use " << model
            << "\n";
  return 0;
}

const CommandRegistrar registrar{{"swap", "hot swap of the contact model of the running runs", run_swap}};

}  // namespace
}  // namespace wrc::cli
