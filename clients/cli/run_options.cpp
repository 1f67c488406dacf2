// SPDX-License-Identifier: Apache-2.0
#include "cli/run_options.hpp"

#include <unistd.h>

#include <algorithm>
#include <sstream>

#include "bus/auth/message_auth.hpp"
#include "bus/service/service_options.hpp"
#include "bus/transport/guarded_subscription.hpp"
#include "cli/profile_options.hpp"
#include "cli/service_starter.hpp"
#include "core/dynamics/run_parameter_table.hpp"
#include "core/dynamics/run_parameters_file.hpp"
#include "core/dynamics/single_wheelset_vehicle.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/track/track_irregularity_file.hpp"
#include "core/track/track_layout_file.hpp"
#include "core/vehicle/vehicle_file.hpp"
#include "options/fit_options.hpp"
#include "options/parameter_options.hpp"
#include "protocol/run/run_command_codec.hpp"
#include "protocol/run/run_request_table.hpp"

namespace wrc::cli {

std::vector<protocol::ScheduledSwap> parse_swaps(const std::string& text, double t_end) {
  // The run command's limit (protocol/run/run_command_codec.hpp), here rather than at the service.
  const std::size_t count = static_cast<std::size_t>(std::count(text.begin(), text.end(), ',')) + 1;
  if (count > protocol::kMaxScheduledSwaps)
    throw UsageError("--swap-at: " + std::to_string(count) + " swaps, more than the limit of " +
                     std::to_string(protocol::kMaxScheduledSwaps));
  std::vector<protocol::ScheduledSwap> swaps;
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ',')) {
    const auto colon = item.find(':');
    if (colon == std::string::npos) throw UsageError("--swap-at: '" + item + "' is not T:MODEL");
    protocol::ScheduledSwap s;
    s.t = parse_finite(item.substr(0, colon), "--swap-at");
    s.model = item.substr(colon + 1);
    contact_model_entry(s.model);
    if (!(s.t > (swaps.empty() ? 0.0 : swaps.back().t) && s.t < t_end))
      throw UsageError("--swap-at: times must increase within (0, t_end): '" + item + "'");
    swaps.push_back(s);
  }
  return swaps;
}

void zero_lateral_load_unless_given(const Options& o, WheelsetParameters& wheelset, const std::string& why,
                                    std::ostream& notes) {
  if (o.has("--lateral-force") || wheelset.lateral_force == 0.0) return;
  notes << "lateral load: " << wheelset.lateral_force << " N of the parameters set to 0 (" << why << ")\n";
  wheelset.lateral_force = 0.0;
}

std::vector<OptionSpec> wheelset_source_option_specs() {
  return {
      {"--params", true, "run parameter file (JSON, docs/dynamics.md); options override it", "the benchmark"},
      {"--vehicle", true,
       "vehicle file (JSON, docs/vehicle.md) of one wheelset on the track: its masses, inertias, loads and "
       "axle boxes replace the parameters'; options override it",
       "the benchmark's wheelset"},
      {"--suspension", true, "benchmark or none (free but for the constant speed)", "benchmark"},
  };
}

void refuse_options_a_vehicle_gives(const Options& o) {
  // The run parameters a vehicle file gives for each of its wheelsets and bodies.
  static constexpr const char* kVehicleKeys[] = {
      "mass",           "roll_inertia",           "yaw_inertia",       "spin_inertia",       "vertical_force",
      "lateral_force",  "longitudinal_stiffness", "lateral_stiffness", "vertical_stiffness", "longitudinal_damping",
      "lateral_damping", "vertical_damping",      "half_spacing"};
  if (o.has("--suspension")) throw UsageError("--suspension and --vehicle both give the suspension: leave one out");
  for (const auto& p : wheelset_parameter_table())
    for (const char* key : kVehicleKeys)
      if (std::string(p.key) == key && o.has(p.option_name()))
        throw UsageError(p.option_name() + ": a vehicle of several bodies takes it from its file (--vehicle)");
}

void apply_wheelset_sources(const Options& o, RunSpec& spec, std::ostream& notes,
                            std::optional<VehicleDescription>* several_bodies) {
  if (o.has("--params")) apply_run_parameter_file(o.text("--params"), spec);
  if (o.has("--vehicle")) {
    if (o.has("--suspension")) throw UsageError("--suspension and --vehicle both give the suspension: leave one out");
    const std::string path = o.text("--vehicle");
    VehicleDescription vehicle;
    try {
      vehicle = read_vehicle_file(path);
      if (several_bodies && vehicle.bodies.size() > 1) {
        refuse_options_a_vehicle_gives(o);
        notes << "vehicle: '" << vehicle.name << "' (" << path << "), " << vehicle.bodies.size() << " bodies, "
              << vehicle.elements.size() << " elements\n";
        *several_bodies = std::move(vehicle);
        return;  // --suspension was refused above
      }
      apply_single_wheelset(vehicle, spec.wheelset);
    } catch (const std::invalid_argument& e) {
      throw UsageError("--vehicle: " + path + ": " + e.what());
    }
    notes << "vehicle: '" << vehicle.name << "' (" << path << "), one wheelset on the track\n";
  }
  if (!o.has("--suspension")) return;
  spec.wheelset.suspension = o.choice("--suspension", {"benchmark", "none"}) == "none" ? PrimarySuspension::none()
                                                                                       : PrimarySuspension::benchmark();
}

std::vector<OptionSpec> run_option_specs() {
  std::vector<OptionSpec> specs{
      {"--model", true, "contact model to start with: onepoint, interp, multipoint or spline", ""},
      {"--summary", true, "write the run summary here (JSON)", ""},
      {"--swap-at", true,
       "swap the model at the first step at or after simulated times: T:M[,T2:M2...], at most " +
           std::to_string(protocol::kMaxScheduledSwaps),
       "none"},
      {"--history", true, "write the state at every output period here (CSV)", "none"},
      {"--in-process", false, "the dynamics evaluates the contact model itself (comparison only)", ""},
      {"--track", true, "track layout file (JSON: straights, transitions, curves with cant; docs/track.md)",
       "straight, level track"},
      {"--irregularities", true,
       "track irregularities file (CSV: s [m] and alignment, vertical_level, cross_level, gauge in m or mm; "
       "wrc irregularities writes one from a published spectrum; docs/track.md)",
       "none"},
      {"--run-id", true, "name of the run", "run-<pid>"},
      {"--dynamics-instance", true,
       "the wrc-dynamicsd instance to run it (started under this name when none is READY); "
       "several runs at once need one each",
       "any that runs"},
  };
  const std::vector<OptionSpec> sources = wheelset_source_option_specs();
  specs.insert(specs.begin() + 2, sources.begin(), sources.end());
  for (auto& spec : parameter_option_specs(protocol::run_request_table(), protocol::RunRequest{})) specs.push_back(spec);
  for (auto& spec : service_start_option_specs()) specs.push_back(spec);
  for (auto& spec : profile_option_specs()) specs.push_back(spec);
  for (auto& spec : spline_model_fit_option_specs()) specs.push_back(spec);
  return specs;
}

protocol::RunRequest run_request_from(const Options& o, std::ostream& notes) {
  protocol::RunRequest request;
  request.model = o.choice("--model", contact_model_names());
  if (request.model.empty()) throw UsageError("--model is required (onepoint, interp, multipoint or spline)");
  RunSpec& spec = request.spec;
  apply_wheelset_sources(o, spec, notes, &request.vehicle);
  apply_parameter_options(protocol::run_request_table(), o, request);
  spec.validate();  // the rules between parameters (the total vertical load)
  if (o.has("--track")) {
    spec.track = read_track_layout_file(o.text("--track"));
    // On a curve the benchmark's lateral load would add to the centrifugal force (a vehicle's
    // loads are its file's).
    if (!request.vehicle) zero_lateral_load_unless_given(o, spec.wheelset, kTrackLateralLoadReason, notes);
  }
  if (o.has("--irregularities")) spec.irregularity = read_track_irregularity_file(o.text("--irregularities"));
  if (o.has("--swap-at")) {
    request.swaps = parse_swaps(o.text("--swap-at"), spec.integrator.t_end);
  }
  request.in_process = o.has("--in-process");
  // The spline model's fit: the dynamics fits it itself with it (--in-process), or asks the spline
  // services fitted with it (their key says which fit they serve; wrc run starts one when none is
  // READY).
  request.spline_fit = fit_options_from(o);
  request.run_id = o.text("--run-id", "run-" + std::to_string(::getpid()));
  if (o.has("--dynamics-instance")) {
    request.dynamics_instance = o.text("--dynamics-instance");
    try {
      bus::check_instance_name("--dynamics-instance", request.dynamics_instance);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
  }
  request.geometry = geometry_spec_from_options(o);
  // The run command carries the layout and the irregularities: it must fit what a service accepts.
  const std::size_t bytes =
      static_cast<std::size_t>(protocol::to_message(request).getEncodedSize()) + bus::MessageAuth::kTrailerBytes;
  if (bytes > bus::kDefaultMaxMessageBytes)
    throw UsageError("the run command would be " + std::to_string(bytes) + " bytes, more than the " +
                     std::to_string(bus::kDefaultMaxMessageBytes) +
                     " a service accepts: use fewer track layout segments or irregularity samples");
  return request;
}

}  // namespace wrc::cli
