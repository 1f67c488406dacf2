// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/wheelset_parameters.hpp"

#include <sstream>
#include <stdexcept>

#include "core/dynamics/run_parameter_table.hpp"

namespace wrc {

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

// Each member's rule is its table's (core/dynamics/run_parameter_table.cpp); what is left here
// are the rules between members.
void WheelsetParameters::validate() const {
  validate_parameters(wheelset_parameter_table(), *this);
  if (!(total_vertical_load() > 0.0)) {
    std::ostringstream msg;
    msg << "vertical_force = " << vertical_force
        << " is invalid: the total vertical load (with m g when include_gravity) must press the wheelset onto the track";
    throw std::invalid_argument(msg.str());
  }
}

void InitialState::validate() const { validate_parameters(initial_state_table(), *this); }

void IntegratorSettings::validate() const {
  validate_parameters(integrator_settings_table(), *this);
  // Every output sample goes out on WHEELSET_STATE (in batches) and is a history line: a period far below the
  // steps (1e-300 s) would have one step emit samples for ever.
  if (!(t_end / output_period <= static_cast<double>(kMaxOutputSamples))) {
    std::ostringstream msg;
    msg << "output_period = " << output_period << " s gives " << t_end / output_period << " output samples up to t_end = "
        << t_end << " s, more than " << kMaxOutputSamples << ": choose a longer output_period";
    throw std::invalid_argument(msg.str());
  }
}

void RunSpec::validate() const {
  wheelset.validate();
  initial.validate();
  integrator.validate();
}

}  // namespace wrc
