#include "cli/run_outputs.hpp"

#include <fstream>
#include <iomanip>
#include <stdexcept>

#include "cli/table_json.hpp"
#include "core/dynamics/run_counter_table.hpp"
#include "core/dynamics/run_parameter_table.hpp"
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
  j["final_state"] = {{"y", s.y},
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
  j["wall_time"] = s.wall_time;
  j["counters"] = table_json(run_counter_table(), protocol::from_stats_message(s.stats));
  nlohmann::json swaps = nlohmann::json::array();
  for (std::size_t k = 0; k < s.swap_times.size(); ++k)
    swaps.push_back({{"t", s.swap_times[k]}, {"model", s.swap_models[k]}});
  j["swaps"] = swaps;
  j["parameters"] = table_json(run_parameter_table(), request.spec);
  j["track_layout"] = layout_json(request.spec.track, request.spec.wheelset.speed, request.spec.wheelset.gravity,
                                  s.t_end);
  j["irregularities"] = irregularity_json(request.spec.irregularity);
  return j;
}

void write_summary(const std::string& path, const nlohmann::json& summary) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot write the summary");
  out << summary.dump(2) << "\n";
  if (!out) throw std::runtime_error(path + ": write error");
}

void write_history(const std::string& path, const std::map<double, wheelset_state_t>& history) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot write the history");
  out << "t,y,z,roll,yaw,y_dot,z_dot,roll_dot,yaw_dot,spin_rate,s_left,s_right,angle_left,angle_right,"
         "normal_force_left,normal_force_right,model\n";
  out << std::setprecision(17);
  for (const auto& [t, m] : history) {
    out << m.t << ',' << m.y << ',' << m.z << ',' << m.roll << ',' << m.yaw << ',' << m.y_dot << ',' << m.z_dot << ','
        << m.roll_dot << ',' << m.yaw_dot << ',' << m.spin_rate << ',' << m.s_wheel[0] << ',' << m.s_wheel[1] << ','
        << m.contact_angle[0] << ',' << m.contact_angle[1] << ',' << m.normal_force[0] << ',' << m.normal_force[1]
        << ',' << m.model << '\n';
  }
  if (!out) throw std::runtime_error(path + ": write error");
}

}  // namespace wrc::cli
