#include "core/dynamics/run_parameters_file.hpp"

#include <sys/stat.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace wrc {
namespace {

constexpr std::size_t kMaxFileBytes = 1u << 20;

}  // namespace

const std::vector<RunParameter>& run_parameter_table() {
  static const std::vector<RunParameter> table{
      {"mass", "kg", "wheelset mass", RunParameterKind::kNumber, [](const RunSpec& s) { return s.wheelset.mass; },
       [](RunSpec& s, double v) { s.wheelset.mass = v; }},
      {"roll_inertia", "kg m^2", "I_xx about the roll axis", RunParameterKind::kNumber, [](const RunSpec& s) { return s.wheelset.roll_inertia; },
       [](RunSpec& s, double v) { s.wheelset.roll_inertia = v; }},
      {"yaw_inertia", "kg m^2", "I_zz about the vertical axis", RunParameterKind::kNumber, [](const RunSpec& s) { return s.wheelset.yaw_inertia; },
       [](RunSpec& s, double v) { s.wheelset.yaw_inertia = v; }},
      {"spin_inertia", "kg m^2", "I_yy about the axle", RunParameterKind::kNumber, [](const RunSpec& s) { return s.wheelset.spin_inertia; },
       [](RunSpec& s, double v) { s.wheelset.spin_inertia = v; }},
      {"speed", "m/s", "constant forward speed", RunParameterKind::kNumber, [](const RunSpec& s) { return s.wheelset.speed; },
       [](RunSpec& s, double v) { s.wheelset.speed = v; }},
      {"vertical_force", "N", "external vertical load, downward", RunParameterKind::kNumber, [](const RunSpec& s) { return s.wheelset.vertical_force; },
       [](RunSpec& s, double v) { s.wheelset.vertical_force = v; }},
      {"lateral_force", "N", "external lateral load, towards +y (left rail)", RunParameterKind::kNumber, [](const RunSpec& s) { return s.wheelset.lateral_force; },
       [](RunSpec& s, double v) { s.wheelset.lateral_force = v; }},
      {"include_gravity", "-", "true: m g acts on top of vertical_force", RunParameterKind::kBoolean,
       [](const RunSpec& s) { return s.wheelset.include_gravity ? 1.0 : 0.0; },
       [](RunSpec& s, double v) { s.wheelset.include_gravity = v != 0.0; }},
      {"gravity", "m/s^2", "g", RunParameterKind::kNumber, [](const RunSpec& s) { return s.wheelset.gravity; },
       [](RunSpec& s, double v) { s.wheelset.gravity = v; }},
      {"longitudinal_stiffness", "N/m", "per axle box (yaw restraint 2 k_x b^2)", RunParameterKind::kNumber, [](const RunSpec& s) { return s.wheelset.suspension.longitudinal_stiffness; },
       [](RunSpec& s, double v) { s.wheelset.suspension.longitudinal_stiffness = v; }},
      {"lateral_stiffness", "N/m", "per axle box", RunParameterKind::kNumber, [](const RunSpec& s) { return s.wheelset.suspension.lateral_stiffness; },
       [](RunSpec& s, double v) { s.wheelset.suspension.lateral_stiffness = v; }},
      {"vertical_stiffness", "N/m", "per axle box (roll restraint 2 k_z b^2)", RunParameterKind::kNumber, [](const RunSpec& s) { return s.wheelset.suspension.vertical_stiffness; },
       [](RunSpec& s, double v) { s.wheelset.suspension.vertical_stiffness = v; }},
      {"longitudinal_damping", "N s/m", "per axle box", RunParameterKind::kNumber, [](const RunSpec& s) { return s.wheelset.suspension.longitudinal_damping; },
       [](RunSpec& s, double v) { s.wheelset.suspension.longitudinal_damping = v; }},
      {"lateral_damping", "N s/m", "per axle box", RunParameterKind::kNumber, [](const RunSpec& s) { return s.wheelset.suspension.lateral_damping; },
       [](RunSpec& s, double v) { s.wheelset.suspension.lateral_damping = v; }},
      {"vertical_damping", "N s/m", "per axle box", RunParameterKind::kNumber, [](const RunSpec& s) { return s.wheelset.suspension.vertical_damping; },
       [](RunSpec& s, double v) { s.wheelset.suspension.vertical_damping = v; }},
      {"half_spacing", "m", "lateral distance of each axle box from the centre", RunParameterKind::kNumber, [](const RunSpec& s) { return s.wheelset.suspension.half_spacing; },
       [](RunSpec& s, double v) { s.wheelset.suspension.half_spacing = v; }},
      {"shear_modulus", "Pa", "G of wheel and rail", RunParameterKind::kNumber, [](const RunSpec& s) { return s.wheelset.material.shear_modulus; },
       [](RunSpec& s, double v) { s.wheelset.material.shear_modulus = v; }},
      {"poisson_ratio", "-", "nu", RunParameterKind::kNumber, [](const RunSpec& s) { return s.wheelset.material.poisson_ratio; },
       [](RunSpec& s, double v) { s.wheelset.material.poisson_ratio = v; }},
      {"friction", "-", "Coulomb friction coefficient mu", RunParameterKind::kNumber, [](const RunSpec& s) { return s.wheelset.material.friction; },
       [](RunSpec& s, double v) { s.wheelset.material.friction = v; }},
      {"fastsim_elements", "-", "FASTSIM elements per strip", RunParameterKind::kInteger,
       [](const RunSpec& s) { return static_cast<double>(s.wheelset.fastsim_elements); },
       [](RunSpec& s, double v) { s.wheelset.fastsim_elements = static_cast<int>(v); }},
      {"fastsim_strips", "-", "FASTSIM strips", RunParameterKind::kInteger,
       [](const RunSpec& s) { return static_cast<double>(s.wheelset.fastsim_strips); },
       [](RunSpec& s, double v) { s.wheelset.fastsim_strips = static_cast<int>(v); }},
      {"y0", "m", "initial lateral shift", RunParameterKind::kNumber, [](const RunSpec& s) { return s.initial.y; },
       [](RunSpec& s, double v) { s.initial.y = v; }},
      {"yaw0", "rad", "initial yaw angle", RunParameterKind::kNumber, [](const RunSpec& s) { return s.initial.yaw; },
       [](RunSpec& s, double v) { s.initial.yaw = v; }},
      {"y_dot0", "m/s", "initial lateral velocity", RunParameterKind::kNumber, [](const RunSpec& s) { return s.initial.y_dot; },
       [](RunSpec& s, double v) { s.initial.y_dot = v; }},
      {"yaw_dot0", "rad/s", "initial yaw rate", RunParameterKind::kNumber, [](const RunSpec& s) { return s.initial.yaw_dot; },
       [](RunSpec& s, double v) { s.initial.yaw_dot = v; }},
      {"spin_rate_offset", "rad/s", "initial spin rate minus speed / r0", RunParameterKind::kNumber, [](const RunSpec& s) { return s.initial.spin_rate_offset; },
       [](RunSpec& s, double v) { s.initial.spin_rate_offset = v; }},
      {"t_end", "s", "simulated end time", RunParameterKind::kNumber, [](const RunSpec& s) { return s.integrator.t_end; },
       [](RunSpec& s, double v) { s.integrator.t_end = v; }},
      {"rtol", "-", "relative tolerance", RunParameterKind::kNumber, [](const RunSpec& s) { return s.integrator.relative_tolerance; },
       [](RunSpec& s, double v) { s.integrator.relative_tolerance = v; }},
      {"position_tolerance", "m, rad", "absolute tolerance of y, z, roll, yaw", RunParameterKind::kNumber, [](const RunSpec& s) { return s.integrator.position_tolerance; },
       [](RunSpec& s, double v) { s.integrator.position_tolerance = v; }},
      {"velocity_tolerance", "m/s, rad/s", "absolute tolerance of the rates", RunParameterKind::kNumber, [](const RunSpec& s) { return s.integrator.velocity_tolerance; },
       [](RunSpec& s, double v) { s.integrator.velocity_tolerance = v; }},
      {"max_step", "s", "largest step", RunParameterKind::kNumber, [](const RunSpec& s) { return s.integrator.max_step; },
       [](RunSpec& s, double v) { s.integrator.max_step = v; }},
      {"max_steps", "-", "steps before the run fails", RunParameterKind::kInteger,
       [](const RunSpec& s) { return static_cast<double>(s.integrator.max_steps); },
       [](RunSpec& s, double v) { s.integrator.max_steps = static_cast<long>(v); }},
      {"output_period", "s", "simulated time between output samples", RunParameterKind::kNumber, [](const RunSpec& s) { return s.integrator.output_period; },
       [](RunSpec& s, double v) { s.integrator.output_period = v; }},
  };
  return table;
}

void apply_run_parameters(const std::string& text, const std::string& source, RunSpec& spec) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::invalid_argument(source + ": not valid JSON: " + e.what());
  }
  if (!doc.is_object()) throw std::invalid_argument(source + ": the parameter file must hold one JSON object");
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    const std::string& key = it.key();
    const RunParameter* entry = nullptr;
    for (const RunParameter& p : run_parameter_table())
      if (key == p.key) entry = &p;
    if (!entry) {
      std::string known;
      for (const RunParameter& p : run_parameter_table()) known += std::string(known.empty() ? "" : ", ") + p.key;
      throw std::invalid_argument(source + ": " + key + ": unknown parameter (known: " + known + ")");
    }
    if (entry->kind == RunParameterKind::kBoolean) {
      if (!it->is_boolean()) throw std::invalid_argument(source + ": " + key + ": must be true or false");
      entry->set(spec, it->get<bool>() ? 1.0 : 0.0);
      continue;
    }
    if (!it->is_number()) throw std::invalid_argument(source + ": " + key + ": must be a number");
    const double v = it->get<double>();
    if (entry->kind == RunParameterKind::kInteger && !(std::isfinite(v) && v == std::floor(v) && std::abs(v) < 1e12))
      throw std::invalid_argument(source + ": " + key + ": " + std::to_string(v) + " is not a whole number");
    entry->set(spec, v);
  }
  try {
    spec.validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(source + ": " + e.what());
  }
}

void apply_run_parameter_file(const std::string& path, RunSpec& spec) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw std::runtime_error(path + ": cannot read the parameter file");
  if (!S_ISREG(st.st_mode)) throw std::invalid_argument(path + ": not a regular file");
  if (static_cast<std::size_t>(st.st_size) > kMaxFileBytes)
    throw std::invalid_argument(path + ": " + std::to_string(st.st_size) + " bytes, more than a parameter file has");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) throw std::runtime_error(path + ": read error");
  apply_run_parameters(text.str(), path, spec);
}

std::string run_parameter_text(const RunSpec& spec) {
  std::ostringstream out;
  out.precision(17);
  out << "{\n";
  const auto& table = run_parameter_table();
  for (std::size_t k = 0; k < table.size(); ++k) {
    const RunParameter& p = table[k];
    out << "  \"" << p.key << "\": ";
    if (p.kind == RunParameterKind::kBoolean) {
      out << (p.get(spec) != 0.0 ? "true" : "false");
    } else if (p.kind == RunParameterKind::kInteger) {
      out << static_cast<long long>(p.get(spec));
    } else {
      char buf[64];
      const auto written = std::to_chars(buf, buf + sizeof buf, p.get(spec));  // shortest exact form
      out << std::string(buf, written.ptr);
    }
    out << (k + 1 < table.size() ? "," : "") << "  // [" << p.unit << "] " << p.description << "\n";
  }
  out << "}\n";
  return out.str();
}

}  // namespace wrc
