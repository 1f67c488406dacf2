// SPDX-License-Identifier: Apache-2.0
// wrc query: one contact query to a running contact service (wrc-contactd --model M) and its
// patches, one row per patch. The service is found by its heartbeat: a READY instance of model M
// that computes with the asked geometry (its heartbeat's geometry_key equals the key of the
// profile and track options, core/identity/geometry_key.hpp); with several, the smallest instance name
// is addressed, and when it does not answer, every other READY one at once (the first answer
// taken). When none is heard within kServiceDiscoveryTime (cli/service_starter.hpp), the
// query starts one (wrc-contactd from the build tree) in the background, waits for READY, asks it
// and stops it afterwards.

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bus/process/spawn_child.hpp"
#include "bus/process/stop_children.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/clock.hpp"
#include "bus/transport/request_client.hpp"
#include "cli/command.hpp"
#include "cli/grid_option.hpp"
#include "cli/options.hpp"
#include "cli/profile_options.hpp"
#include "cli/service_starter.hpp"
#include "core/geometry/geometry_spec.hpp"
#include "core/geometry/rigid_wheelset.hpp"
#include "core/geometry/wheelset_geometry.hpp"
#include "core/identity/geometry_key.hpp"
#include "core/model_interface/query_validation.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/numerics/number_text.hpp"
#include "protocol/contact/contact_query_codec.hpp"
#include "protocol/contact/contact_status.hpp"
#include "wrc/contact_query_t.hpp"
#include "wrc/contact_reply_t.hpp"

namespace wrc::cli {
namespace {

constexpr double kDefaultLoad = 154715.0 / 2.0;  // [N] per wheel: the benchmark's axle load shared by two wheels

// The option that sets a field of the query, nullptr for a field no option sets.
const char* query_option(QueryField field) {
  switch (field) {
    case QueryField::kPoseY: return "--y";
    case QueryField::kPoseZ: return "--z";
    case QueryField::kPoseRoll: return "--roll";
    case QueryField::kPoseYaw: return "--yaw";
    case QueryField::kSpinRate: return "--spin-rate";
    case QueryField::kSpeed: return "--speed";
    case QueryField::kNormalLoadLeft:
    case QueryField::kNormalLoadRight: return "--load";
    case QueryField::kFormulation: return "--formulation";
    case QueryField::kShearModulus: return "--shear-modulus";
    case QueryField::kPoissonRatio: return "--poisson";
    case QueryField::kFriction: return "--friction";
    case QueryField::kFastsimElements:
    case QueryField::kFastsimStrips: return "--grid";
    default: return nullptr;
  }
}

// The library's rule (core/model_interface/query_validation.hpp) on the query the options make,
// the one the service applies: UsageError "<option>: <value> is outside <range> [unit]" naming
// the option that breaks it (the library's own message for a field no option sets).
void check_query(const Options& o, const ContactQuery& query) {
  const std::optional<QueryViolation> violation = find_query_violation(query);
  if (!violation) return;
  const char* option = query_option(violation->rule.field);
  if (!option) {
    validate_contact_query(query);  // throws the library's message
    return;
  }
  const std::string value = o.has(option) ? o.text(option) : number_text(violation->value);
  throw UsageError(std::string(option) + ": " + value + " " + query_rule_breach(*violation));
}

// Height of the wheelset centre at which the closer wheel just touches its rail at (y, roll, yaw):
// the vertical gaps change one for one with z, so one evaluation at z = r0 gives it exactly.
double touching_height(const WheelsetGeometry& geometry, double y, double roll, double yaw) {
  WheelsetPose pose;
  pose.y = y;
  pose.roll = roll;
  pose.yaw = yaw;
  pose.z = geometry.track().nominal_radius;
  double gap = 1e300;
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    const auto point = geometry.common_point(side, pose);
    if (!point) {
      throw std::runtime_error("the " + std::string(side_name(side)) +
                               " wheel has no contact point with its rail at y = " + std::to_string(y) + " m");
    }
    gap = std::min(gap, point->distance);
  }
  return pose.z - gap;
}

// ---- output --------------------------------------------------------------------------------------


void print_patches(const wrc::contact_reply_t& reply, const std::string& format) {
  // Full precision for csv (machine reading), six significant digits for the aligned table.
  const int digits = format == "csv" ? 10 : 6;
  auto cell = [&](double v) { return number_text(v, digits); };
  const std::vector<std::string> header{"wheel", "s", "angle", "a", "b", "penetration", "normal_force", "fx", "fy",
                                        "mz", "xi_x", "xi_y", "spin", "rolling_radius", "s_rail", "x", "y", "z",
                                        "lateral_curvature_floored"};
  std::vector<std::vector<std::string>> rows;
  int floored = 0;
  for (const auto& result : reply.results) {
    for (const auto& p : result.patches) {
      floored += p.lateral_curvature_floored != 0;
      rows.push_back({p.wheel == wrc::contact_patch_t::LEFT ? "left" : "right", cell(p.s_wheel),
                      cell(p.contact_angle), cell(p.a), cell(p.b), cell(p.penetration), cell(p.normal_force),
                      cell(p.fx), cell(p.fy), cell(p.mz), cell(p.creepage_x), cell(p.creepage_y),
                      cell(p.spin_creepage), cell(p.rolling_radius), cell(p.s_rail), cell(p.wheel_point[0]),
                      cell(p.wheel_point[1]), cell(p.wheel_point[2]), p.lateral_curvature_floored ? "1" : "0"});
    }
  }
  std::ostringstream out;
  if (format == "csv") {
    for (std::size_t i = 0; i < header.size(); ++i) out << (i ? "," : "") << header[i];
    out << "\n";
    for (const auto& row : rows) {
      for (std::size_t i = 0; i < row.size(); ++i) out << (i ? "," : "") << row[i];
      out << "\n";
    }
  } else {
    std::vector<std::size_t> width(header.size());
    for (std::size_t i = 0; i < header.size(); ++i) {
      width[i] = header[i].size();
      for (const auto& row : rows) width[i] = std::max(width[i], row[i].size());
    }
    auto line = [&](const std::vector<std::string>& cells) {
      for (std::size_t i = 0; i < cells.size(); ++i) {
        out << (i ? "  " : "") << std::setw(static_cast<int>(width[i])) << cells[i];
      }
      out << "\n";
    };
    line(header);
    for (const auto& row : rows) line(row);
  }
  std::cout << out.str();
  if (floored > 0)
    std::cerr << "query: " << floored << " patch" << (floored > 1 ? "es" : "")
              << " in conformal contact (lateral_curvature_floored = 1: the lateral relative curvature was raised to "
                 "the floor, b/a beyond Kalker's table): Hertz does not hold there\n";
}

// ---- the command ---------------------------------------------------------------------------------

std::vector<OptionSpec> query_option_specs() {
  const ContactQuery defaults;
  std::vector<OptionSpec> specs{
      {"--model", true, "contact model: onepoint, interp, multipoint or spline", ""},
      {"--y", true, "lateral shift of the wheelset [m], > 0 towards the left rail", ""},
      {"--roll", true, "roll angle [rad], > 0 raises the left wheel", "0 (elastic without --z: rigid solution)"},
      {"--yaw", true, "yaw angle [rad], within +-" + shortest_number_text(kMaxValidatedYaw) + " (validated range)",
       shortest_number_text(defaults.pose.yaw)},
      {"--z", true, "height of the wheelset centre above the top-of-rail plane [m]",
       "rigid: closer wheel just touching; elastic: that minus --penetration"},
      {"--penetration", true, "elastic without --z: how far the centre is lowered below touching [m]", "1e-4",
          NumberRange{0.0, 0.01}},
      {"--load", true, "normal load per wheel, rigid formulation [N]", number_text(kDefaultLoad)},
      {"--formulation", true, "rigid (loads given) or elastic (forces from penetration)", "rigid"},
      {"--speed", true, "forward speed V [m/s]", shortest_number_text(defaults.speed)},
      {"--spin-rate", true, "angular velocity about the axle [rad/s]", "V/r0"},
      {"--shear-modulus", true, "shear modulus G [Pa]", shortest_number_text(defaults.material.shear_modulus)},
      {"--poisson", true, "Poisson's ratio [-]", shortest_number_text(defaults.material.poisson_ratio)},
      {"--friction", true, "friction coefficient mu [-]", shortest_number_text(defaults.material.friction)},
      grid_option_spec(),
      {"--timeout", true, "wait for the reply per attempt [s]", "1", NumberRange{1e-3, 600.0}},
      {"--retries", true, "re-sends after a timeout", "3", NumberRange{0, 100}},
      {"--instance", true, "address this instance (must be running)", "from the heartbeats"},
      {"--format", true, "csv or table", "csv"}};
  for (auto& spec : service_start_option_specs()) specs.push_back(spec);
  for (auto& spec : profile_option_specs()) specs.push_back(spec);
  return specs;
}

void print_query_help(const Options& o) {
  std::cout << o.help()
            << "\nSends one contact query to a service of model M and prints one row per contact patch:\n"
               "wheel,s,angle,a,b,penetration,normal_force,fx,fy,mz,xi_x,xi_y,spin,rolling_radius,s_rail,x,y,z,\n"
               "lateral_curvature_floored (1: conformal contact, the lateral curvature floored; Hertz does not hold)\n"
               "(a rolling, b lateral semi-axis; forces on the wheel in the contact frame; x,y,z the contact\n"
               "point on the wheel, track frame; SI units). The service is a READY instance of M heard on\n"
               "HEARTBEAT that computes with the same profiles and track (smallest instance name first); when\n"
               "none is heard within "
            << kServiceDiscoveryTime
            << " s one is started from the build tree and stopped afterwards.\n"
               "Rigid formulation: --load per wheel; z defaults to the height where the closer wheel just\n"
               "touches (positions only; the loads set the forces). Elastic: the forces follow from the\n"
               "penetration; without --z the rigid wheelset solution (both wheels touching; its roll unless\n"
               "--roll is given) is lowered by --penetration.\n";
}

// The query as the library takes it, checked by the library's rule before anything starts; the
// height (and the elastic roll) from the client's own geometry afterwards, and checked again.
ContactQuery library_query_from(const Options& o, const GeometrySpec& spec) {
  ContactQuery q;
  q.pose.y = o.required_number("--y");
  q.pose.yaw = o.number("--yaw");
  q.pose.roll = o.has("--roll") ? o.number("--roll") : 0.0;
  if (o.has("--z")) q.pose.z = o.number("--z");
  q.speed = o.number("--speed");
  if (o.has("--spin-rate")) q.spin_rate = o.number("--spin-rate");
  q.normal_load.fill(o.number("--load"));
  q.formulation = o.choice("--formulation", {"rigid", "elastic"}) == "elastic" ? ContactFormulation::kElastic
                                                                              : ContactFormulation::kRigid;
  q.material = {o.number("--shear-modulus"), o.number("--poisson"), o.number("--friction")};
  const FastsimGrid grid = grid_option(o, kMinFastsimGrid, kMaxFastsimGrid);
  q.fastsim_elements = grid.elements_per_strip;
  q.fastsim_strips = grid.strips;
  check_query(o, q);
  if (!o.has("--spin-rate")) q.spin_rate = q.speed / spec.track.nominal_radius;
  if (!o.has("--z")) {
    const WheelsetGeometry geometry = make_geometry(spec);
    if (q.formulation == ContactFormulation::kElastic && !o.has("--roll")) {
      const RigidContact rigid = RigidWheelsetSolver(geometry).solve(q.pose.y, q.pose.yaw);
      q.pose.roll = rigid.pose.roll;
      q.pose.z = rigid.pose.z;
    } else {
      q.pose.z = touching_height(geometry, q.pose.y, q.pose.roll, q.pose.yaw);
    }
    if (q.formulation == ContactFormulation::kElastic) q.pose.z -= o.number("--penetration");
  }
  check_query(o, q);
  return q;
}

// The service that answers, and what this command started for it (stopped when it ends).
struct QueryService {
  std::optional<bus::ServiceStatus> status;
  std::unique_ptr<StartedService> started;
  std::unique_ptr<StartedService> started_geometry;  // for a model whose data wrc-geometryd computes

  // Stops what was started; its logs go when the query was answered.
  void stop(bool answered) {
    for (auto* s : {&started_geometry, &started}) {
      if (!*s) continue;
      (*s)->stop();
      if (answered) std::filesystem::remove((*s)->log());
    }
  }
};

// A READY instance of model (the one named by --instance, which must run), one that is starting
// (waited for up to start_timeout [s]), or one started here.
QueryService find_or_start_service(CommandBus& session, const Options& o, const std::string& model,
                                   const GeometrySpec& spec, const std::string& key, double start_timeout) {
  const std::string wanted = o.text("--instance");
  QueryService found;
  std::optional<bus::ServiceStatus>& service = found.status;
  service = discover_service(*session.lcm, session.monitor, model, key, wanted, kServiceDiscoveryTime);
  if (!service && !wanted.empty()) {
    std::ostringstream msg;
    msg << "no READY instance '" << wanted << "' of model " << model << " with geometry_key " << key
        << " heard within " << kServiceDiscoveryTime << " s";
    throw std::runtime_error(msg.str());
  }
  if (!service && pick_service(session.monitor, model, key, "", false)) {
    std::cerr << "query: an instance of " << model << " is starting; waiting for it\n";
    handle_until(*session.lcm, bus::monotonic_seconds() + start_timeout,
                 [&] { return (service = pick_service(session.monitor, model, key, "", true)).has_value(); });
  }
  if (service) return found;
  const StartContext context = start_context_from(o, "query", "q" + std::to_string(::getpid()));
  if (contact_model_entry(model).needs_data)
    found.started_geometry =
        ensure_service(*session.lcm, session.monitor, context, "geometryd", "", "wrc-geometryd", {});
  std::vector<std::string> service_args{"--model", model};
  for (auto& a : geometry_arguments(spec)) service_args.push_back(a);
  const double t0 = bus::monotonic_seconds();
  found.started = ensure_service(*session.lcm, session.monitor, context, model, key, "wrc-contactd", service_args);
  service = pick_service(session.monitor, model, key, found.started ? context.instance : "", true);
  if (found.started)
    std::cerr << "query: " << model << " service " << context.instance << " READY after "
              << number_text(bus::monotonic_seconds() - t0) << " s\n";
  return found;
}

using QueryClient = bus::RequestClient<wrc::contact_query_t, wrc::contact_reply_t>;

// The query to its instance; when that one does not answer and no instance was named, to every
// other READY instance of the model at once (the first answer taken): the chosen one may be hung,
// gone, or named by a forged heartbeat.
bus::CallResult<wrc::contact_reply_t> call_with_failover(QueryClient& client, CommandBus& session,
                                                         wrc::contact_query_t& query, const bus::CallPolicy& policy,
                                                         bool instance_named) {
  auto result = client.call(query, policy);
  if (result || instance_named) return result;
  std::vector<wrc::contact_query_t> copies;
  for (const std::string& name : session.monitor.ready_instances(query.model, query.geometry_key,
                                                                 bus::monotonic_seconds())) {
    if (name == query.instance) continue;
    copies.push_back(query);
    copies.back().instance = name;
  }
  if (copies.empty()) return result;
  std::cerr << "query: no reply from " << query.model << " instance " << query.instance << "; asking the "
            << copies.size() << " other READY instance" << (copies.size() > 1 ? "s" : "") << "\n";
  const int first_attempts = result.attempts;
  result = client.call_any(copies.data(), copies.size(), policy);
  result.attempts += first_attempts;
  return result;
}

int run_query(const std::vector<std::string>& args) {
  const Options o("query", "--model M --y Y [options]", query_option_specs(), args);
  if (o.help_requested()) {
    print_query_help(o);
    return 0;
  }
  const std::string model = o.choice("--model", contact_model_names());
  if (model.empty()) throw UsageError("--model is required (onepoint, interp, multipoint or spline)");
  bus::CallPolicy policy;
  policy.timeout = o.number("--timeout");
  policy.retries = o.integer("--retries");
  const double start_timeout = o.number("--start-timeout");  // [s] checked before anything starts
  const std::string format = o.choice("--format", {"csv", "table"});
  const GeometrySpec spec = geometry_spec_from_options(o);
  const ContactQuery q = library_query_from(o, spec);
  wrc::contact_query_t query{};
  protocol::to_query_message({q}, query);
  query.model = model;
  query.geometry_key = geometry_key(spec);

  CommandBus session(o, "query");
  QueryService service = find_or_start_service(session, o, model, spec, query.geometry_key, start_timeout);
  query.instance = service.status->last.instance;
  const std::string client_id = bus::make_client_id("query");
  QueryClient client(*session.lcm, session.names.name(bus::channel::kContactQuery, model),
                     session.names.name(bus::channel::kContactReply, client_id),
                     bus::sender_name("wrc-query", client_id));
  const bool instance_named = !o.text("--instance").empty();
  const auto result = call_with_failover(client, session, query, policy, instance_named);
  service.stop(static_cast<bool>(result));  // an error status is in the reply, not in the log
  if (!result) {
    throw std::runtime_error("no reply from " + model + " instance " + query.instance +
                             (instance_named ? "" : " (nor from any other READY instance)") + " after " +
                             std::to_string(result.attempts) + " attempts of " + number_text(policy.timeout) + " s");
  }
  const wrc::contact_reply_t& reply = *result.reply;
  std::cerr << "query: " << model << " instance " << reply.instance << " answered in "
            << number_text(result.round_trip * 1e3) << " ms (compute " << number_text(reply.compute_time * 1e3) << " ms, "
            << result.attempts << " attempt" << (result.attempts > 1 ? "s" : "") << ")\n";
  if (reply.status != wrc::contact_reply_t::OK) {
    std::cerr << "query: " << protocol::contact_status_name(reply.status) << ": " << reply.message << "\n";
    return 1;
  }
  print_patches(reply, format);
  return 0;
}

const CommandRegistrar registrar{
    {"query", "one contact query to a contact service (started when none runs); one row per patch", run_query}};

}  // namespace
}  // namespace wrc::cli
