#include "core/dynamics/wheelset_parameters.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/model_interface/query_validation.hpp"

namespace wrc {
namespace {

void require(bool ok, const char* name, double value, const char* rule) {
  if (ok) return;
  std::ostringstream msg;
  msg << name << " = " << value << " is invalid: " << rule;
  throw std::invalid_argument(msg.str());
}

void require_positive(const char* name, double value) {
  require(std::isfinite(value) && value > 0.0, name, value, "must be finite and > 0");
}

void require_non_negative(const char* name, double value) {
  require(std::isfinite(value) && value >= 0.0, name, value, "must be finite and >= 0");
}

void require_finite(const char* name, double value) { require(std::isfinite(value), name, value, "must be finite"); }

}  // namespace

PrimarySuspension PrimarySuspension::benchmark() {
  PrimarySuspension s;
  s.longitudinal_stiffness = 1.5e7;
  s.lateral_stiffness = 0.0;
  s.vertical_stiffness = 6.0e5;
  s.longitudinal_damping = 2.0e3;
  s.lateral_damping = 2.0e4;
  s.vertical_damping = 4.0e3;
  s.half_spacing = 1.0;
  return s;
}

void WheelsetParameters::validate() const {
  require_positive("mass", mass);
  require_positive("roll_inertia", roll_inertia);
  require_positive("yaw_inertia", yaw_inertia);
  require_positive("spin_inertia", spin_inertia);
  require_positive("speed", speed);
  require_finite("vertical_force", vertical_force);
  require_finite("lateral_force", lateral_force);
  require_non_negative("gravity", gravity);
  require(total_vertical_load() > 0.0, "vertical_force", vertical_force,
          "the total vertical load (with m g when include_gravity) must press the wheelset onto the track");
  const PrimarySuspension& s = suspension;
  require_non_negative("longitudinal_stiffness", s.longitudinal_stiffness);
  require_non_negative("lateral_stiffness", s.lateral_stiffness);
  require_non_negative("vertical_stiffness", s.vertical_stiffness);
  require_non_negative("longitudinal_damping", s.longitudinal_damping);
  require_non_negative("lateral_damping", s.lateral_damping);
  require_non_negative("vertical_damping", s.vertical_damping);
  require_positive("half_spacing", s.half_spacing);
  ContactQuery probe;  // the material and FASTSIM grid are checked by the contact models' one rule
  probe.material = material;
  probe.fastsim_elements = fastsim_elements;
  probe.fastsim_strips = fastsim_strips;
  probe.speed = speed;
  probe.pose.z = 0.46;
  probe.spin_rate = speed / 0.46;
  validate_contact_query(probe);
}

void InitialState::validate() const {
  require(std::isfinite(y) && std::abs(y) < 0.05, "y0", y, "must be finite with |y0| < 0.05 m");
  require(std::isfinite(yaw) && std::abs(yaw) < 0.06, "yaw0", yaw, "must be finite with |yaw0| < 0.06 rad");
  require_finite("y_dot0", y_dot);
  require_finite("yaw_dot0", yaw_dot);
  require_finite("spin_rate_offset", spin_rate_offset);
}

void IntegratorSettings::validate() const {
  require_positive("t_end", t_end);
  require(std::isfinite(relative_tolerance) && relative_tolerance > 0.0 && relative_tolerance < 0.1, "rtol",
          relative_tolerance, "must lie in (0, 0.1)");
  require_positive("position_tolerance", position_tolerance);
  require_positive("velocity_tolerance", velocity_tolerance);
  require_positive("max_step", max_step);
  require_positive("output_period", output_period);
  require(max_steps > 0, "max_steps", static_cast<double>(max_steps), "must be > 0");
}

void RunSpec::validate() const {
  wheelset.validate();
  initial.validate();
  integrator.validate();
}

}  // namespace wrc
