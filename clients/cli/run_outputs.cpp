// SPDX-License-Identifier: Apache-2.0
#include "cli/run_outputs.hpp"

#include <fstream>
#include <iomanip>
#include <stdexcept>
#include <vector>

#include "cli/table_json.hpp"
#include "core/dynamics/run_counter_table.hpp"
#include "core/dynamics/run_parameter_table.hpp"
#include "core/dynamics/wheel_output.hpp"
#include "core/track/track_irregularity.hpp"
#include "core/track/track_layout.hpp"
#include "protocol/run/run_output_codec.hpp"

namespace wrc::cli {
namespace {

// The layout the run went along: its length, the distance travelled and, per curve, where it
// starts, its radius, direction and cant, its balanced speed and the cant deficiency at the run's
// speed (docs/track.md).
nlohmann::json layout_json(const TrackLayout& layout, double speed, double g, double t_end) {
  nlohmann::json j;
  j["length"] = layout.length();
  j["cant_base"] = layout.cant_base();
  j["distance_travelled"] = speed * t_end;
  nlohmann::json curves = nlohmann::json::array();
  double s = 0.0;
  for (const TrackSegment& segment : layout.segments()) {
    if (segment.kind == TrackSegmentKind::kCurve)
      curves.push_back({{"s_start", s},
                        {"length", segment.length},
                        {"radius", segment.radius},
                        {"direction", segment.left ? "left" : "right"},
                        {"cant", segment.cant},
                        {"balanced_speed", TrackLayout::balanced_speed(segment, layout.cant_base(), g)},
                        {"cant_deficiency", TrackLayout::cant_deficiency(segment, layout.cant_base(), speed, g)}});
    s += segment.length;
  }
  j["curves"] = curves;
  return j;
}

// The irregularities the run went over: their range and, per channel, rms and largest |value|
// (null without irregularities).
nlohmann::json irregularity_json(const TrackIrregularity& irregularity) {
  if (irregularity.empty()) return nullptr;
  nlohmann::json j;
  j["s_start"] = irregularity.distances().front();
  j["s_end"] = irregularity.distances().back();
  j["samples"] = irregularity.distances().size();
  for (IrregularityChannel c : kIrregularityChannels)
    j[irregularity_channel_name(c)] = {{"rms", irregularity.rms(c)}, {"max_abs", irregularity.max_abs(c)}};
  return j;
}

// A wheelset's final state (run_summary_t's or wheelset_summary_t's fields).
template <class Summary>
nlohmann::json final_state_json(const Summary& s) {
  return {{"y", s.y},
          {"z", s.z},
          {"roll", s.roll},
          {"yaw", s.yaw},
          {"y_dot", s.y_dot},
          {"z_dot", s.z_dot},
          {"roll_dot", s.roll_dot},
          {"yaw_dot", s.yaw_dot},
          {"spin_rate", s.spin_rate},
          {"normal_force_left", s.normal_force[0]},
          {"normal_force_right", s.normal_force[1]},
          {"s_wheel_left", s.s_wheel[0]},
          {"s_wheel_right", s.s_wheel[1]}};
}

// {"max", "t", "distance"} of one maximum.
nlohmann::json maximum_json(const run_maximum_t& m) { return {{"max", m.value}, {"t", m.t}, {"distance", m.distance}}; }

nlohmann::json per_wheel_json(const run_maximum_t (&m)[2]) {
  return {{"left", maximum_json(m[0])}, {"right", maximum_json(m[1])}};
}

// The maxima of what engineers read off a wheelset's run (wheelset: run_summary_t's or
// wheelset_summary_t's fields), where they occurred and their limits (docs/run-quantities.md;
// Nadal's from the run, the same for every wheelset), with the unit of every key.
template <class Wheelset>
nlohmann::json run_quantities_json(const Wheelset& s, const run_summary_t& run, double friction) {
  nlohmann::json j;
  j["units"] = {{"t", "s"},
                {"distance", "m"},
                {"y_over_q", "-"},
                {"y_over_q_2m", "-"},
                {"nadal_limit", "-"},
                {"flange_angle", "rad"},
                {"friction", "-"},
                {"track_shift_force", "N"},
                {"track_shift_force_2m", "N"},
                {"prudhomme_limit", "N"},
                {"axle_load", "N"},
                {"wear_number", "N"},
                {"max_pressure", "Pa"}};
  j["y_over_q"] = per_wheel_json(s.max_y_over_q);
  j["y_over_q_2m"] = per_wheel_json(s.max_y_over_q_2m);
  j["nadal_limit"] = run.nadal_limit;
  j["flange_angle"] = run.flange_angle;
  j["friction"] = friction;
  j["track_shift_force"] = maximum_json(s.max_track_shift_force);
  j["track_shift_force_2m"] = maximum_json(s.max_track_shift_force_2m);
  j["prudhomme_limit"] = s.prudhomme_limit;
  j["axle_load"] = s.axle_load;
  j["wear_number"] = per_wheel_json(s.max_wear_number);
  j["max_pressure"] = per_wheel_json(s.max_pressure);
  return j;
}

// A vehicle run's vehicle, each of its wheelsets' final state and run quantities, and each car
// body's and frame's largest accelerations (gravity not included, in its track frame), in the
// order of the vehicle file (the summary's final_state and run_quantities are its first
// wheelset's).
nlohmann::json vehicle_json(const run_summary_t& s, const VehicleDescription& vehicle, double friction) {
  nlohmann::json wheelsets = nlohmann::json::array();
  for (const wheelset_summary_t& w : s.wheelsets)
    wheelsets.push_back({{"name", w.name},
                         {"final_state", final_state_json(w)},
                         {"run_quantities", run_quantities_json(w, s, friction)}});
  // Each car body's and frame's largest accelerations.
  nlohmann::json accelerations = nlohmann::json::array();
  for (const body_summary_t& b : s.bodies)
    accelerations.push_back({{"name", b.name},
                             {"lateral", maximum_json(b.max_lateral_acceleration)},
                             {"vertical", maximum_json(b.max_vertical_acceleration)}});
  return {{"name", vehicle.name},
          {"bodies", vehicle.bodies.size()},
          {"elements", vehicle.elements.size()},
          {"wheelsets", wheelsets},
          {"accelerations", accelerations},
          {"units", {{"accelerations", "m/s^2"}, {"t", "s"}, {"distance", "m"}}}};
}

// One column of the history CSV: its name, unit and value in a state message.
struct HistoryColumn {
  const char* name;
  const char* unit;
  double (*value)(const wheelset_state_t&);
};

#define WRC_HISTORY_COLUMN(name, unit, expression) \
  HistoryColumn { name, unit, [](const wheelset_state_t& m) -> double { return expression; } }
// The left [0] and right [1] entries of a per-wheel field, "<name>_left" and "<name>_right".
#define WRC_WHEEL_COLUMNS(name, unit, field) \
  WRC_HISTORY_COLUMN(name "_left", unit, m.field[0]), WRC_HISTORY_COLUMN(name "_right", unit, m.field[1])

// Every numeric column, in file order (the model's name follows them).
const std::vector<HistoryColumn>& history_columns() {
  static const std::vector<HistoryColumn> columns{
      WRC_HISTORY_COLUMN("t", "s", m.t),
      WRC_HISTORY_COLUMN("y", "m", m.y),
      WRC_HISTORY_COLUMN("z", "m", m.z),
      WRC_HISTORY_COLUMN("roll", "rad", m.roll),
      WRC_HISTORY_COLUMN("yaw", "rad", m.yaw),
      WRC_HISTORY_COLUMN("y_dot", "m/s", m.y_dot),
      WRC_HISTORY_COLUMN("z_dot", "m/s", m.z_dot),
      WRC_HISTORY_COLUMN("roll_dot", "rad/s", m.roll_dot),
      WRC_HISTORY_COLUMN("yaw_dot", "rad/s", m.yaw_dot),
      WRC_HISTORY_COLUMN("spin_rate", "rad/s", m.spin_rate),
      WRC_WHEEL_COLUMNS("s", "m", s_wheel),
      WRC_WHEEL_COLUMNS("angle", "rad", contact_angle),
      WRC_WHEEL_COLUMNS("normal_force", "N", normal_force),
      WRC_HISTORY_COLUMN("distance", "m", m.x),
      WRC_WHEEL_COLUMNS("lateral_force", "N", lateral_force),
      WRC_WHEEL_COLUMNS("vertical_force", "N", vertical_force),
      WRC_HISTORY_COLUMN("y_over_q_left", "-", y_over_q(m.lateral_force[0], m.vertical_force[0])),
      WRC_HISTORY_COLUMN("y_over_q_right", "-", y_over_q(m.lateral_force[1], m.vertical_force[1])),
      WRC_HISTORY_COLUMN("nadal_limit", "-", m.nadal_limit),
      WRC_HISTORY_COLUMN("track_shift_force", "N", track_shift_force(m.lateral_force[0], m.lateral_force[1])),
      WRC_HISTORY_COLUMN("prudhomme_limit", "N", m.prudhomme_limit),
      WRC_WHEEL_COLUMNS("creep_force_x", "N", creep_force_x),
      WRC_WHEEL_COLUMNS("creep_force_y", "N", creep_force_y),
      WRC_WHEEL_COLUMNS("wear_number", "N", wear_number),
      WRC_WHEEL_COLUMNS("max_pressure", "Pa", max_pressure),
      WRC_HISTORY_COLUMN("wheelset", "-", m.wheelset),
  };
  return columns;
}

#undef WRC_WHEEL_COLUMNS
#undef WRC_HISTORY_COLUMN

}  // namespace

nlohmann::json summary_json(const run_summary_t& s, const protocol::RunRequest& request, const std::string& key) {
  nlohmann::json j;
  j["run_id"] = s.run_id;
  j["state"] = protocol::run_state_name(s.state);
  j["message"] = s.message;
  j["model"] = s.model;
  j["initial_model"] = request.model;
  j["formulation"] = s.formulation;
  j["in_process"] = request.in_process;
  j["geometry_key"] = key;
  j["t_end"] = s.t_end;
  j["final_state"] = final_state_json(s);
  j["wall_time"] = s.wall_time;
  j["counters"] = table_json(run_counter_table(), protocol::from_stats_message(s.stats));
  nlohmann::json swaps = nlohmann::json::array();
  for (std::size_t k = 0; k < s.swap_times.size(); ++k)
    swaps.push_back({{"t", s.swap_times[k]}, {"model", s.swap_models[k]}});
  j["swaps"] = swaps;
  // Which contact service instances answered the queries over the bus, and how many each.
  nlohmann::json instances = nlohmann::json::object();
  for (std::size_t k = 0; k < s.query_instances.size() && k < s.instance_queries.size(); ++k)
    instances[s.query_instances[k]] = s.instance_queries[k];
  j["query_instances"] = instances;
  j["parameters"] = table_json(run_parameter_table(), request.spec);
  j["run_quantities"] = run_quantities_json(s, s, request.spec.wheelset.material.friction);
  j["track_layout"] = layout_json(request.spec.track, request.spec.wheelset.speed, request.spec.wheelset.gravity,
                                  s.t_end);
  j["irregularities"] = irregularity_json(request.spec.irregularity);
  if (request.vehicle) j["vehicle"] = vehicle_json(s, *request.vehicle, request.spec.wheelset.material.friction);
  return j;
}

void write_summary(const std::string& path, const nlohmann::json& summary) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot write the summary");
  out << summary.dump(2) << "\n";
  if (!out) throw std::runtime_error(path + ": write error");
}

void write_history(const std::string& path, const StateHistory& history) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot write the history");
  for (const HistoryColumn& c : history_columns()) out << c.name << " [" << c.unit << "],";
  out << "model [-]\n";
  out << std::setprecision(17);
  for (const auto& [when, m] : history) {
    for (const HistoryColumn& c : history_columns()) out << c.value(m) << ',';
    out << m.model << '\n';
  }
  if (!out) throw std::runtime_error(path + ": write error");
}

}  // namespace wrc::cli
