// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/run_parameter_table.hpp"

#include "core/geometry/wheelset_geometry.hpp"
#include "core/model_interface/query_validation.hpp"

namespace wrc {
namespace {

template <class T>
void append(std::vector<T>& to, const std::vector<T>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

const std::vector<Parameter<PrimarySuspension>>& suspension_table() {
  using S = PrimarySuspension;
  static const std::vector<Parameter<S>> table{
      member_parameter<S>({"longitudinal_stiffness", nullptr, "N/m", "per axle box (yaw restraint 2 k_x b^2)",
                           ParameterKind::kNumber, kNonNegative}, &S::longitudinal_stiffness),
      member_parameter<S>({"lateral_stiffness", nullptr, "N/m", "per axle box", ParameterKind::kNumber, kNonNegative},
                          &S::lateral_stiffness),
      member_parameter<S>({"vertical_stiffness", nullptr, "N/m", "per axle box (roll restraint 2 k_z b^2)",
                           ParameterKind::kNumber, kNonNegative}, &S::vertical_stiffness),
      member_parameter<S>({"longitudinal_damping", nullptr, "N s/m", "per axle box", ParameterKind::kNumber,
                           kNonNegative}, &S::longitudinal_damping),
      member_parameter<S>({"lateral_damping", nullptr, "N s/m", "per axle box", ParameterKind::kNumber, kNonNegative},
                          &S::lateral_damping),
      member_parameter<S>({"vertical_damping", nullptr, "N s/m", "per axle box", ParameterKind::kNumber, kNonNegative},
                          &S::vertical_damping),
      member_parameter<S>({"half_spacing", nullptr, "m", "lateral distance of each axle box from the centre",
                           ParameterKind::kNumber, kPositive}, &S::half_spacing),
  };
  return table;
}

// The contact models' one rule for the material (core/model_interface/query_validation.hpp).
const std::vector<Parameter<ContactMaterial>>& material_table() {
  using M = ContactMaterial;
  static const std::vector<Parameter<M>> table{
      member_parameter<M>({"shear_modulus", nullptr, "Pa", "G of wheel and rail", ParameterKind::kNumber,
                           {0.0, Bound::kOpen, kMaxShearModulus, Bound::kClosed}}, &M::shear_modulus),
      member_parameter<M>({"poisson_ratio", nullptr, "-", "nu", ParameterKind::kNumber,
                           {kMinPoissonRatio, Bound::kOpen, kMaxPoissonRatio, Bound::kOpen}}, &M::poisson_ratio),
      member_parameter<M>({"friction", nullptr, "-", "Coulomb friction coefficient mu", ParameterKind::kNumber,
                           closed(0.0, kMaxFriction)}, &M::friction),
  };
  return table;
}

}  // namespace

const std::vector<Parameter<WheelsetParameters>>& wheelset_parameter_table() {
  using W = WheelsetParameters;
  static const std::vector<Parameter<W>> table = [] {
    std::vector<Parameter<W>> t{
        member_parameter<W>({"mass", nullptr, "kg", "wheelset mass", ParameterKind::kNumber, kPositive}, &W::mass),
        member_parameter<W>({"roll_inertia", nullptr, "kg m^2", "I_xx about the roll axis", ParameterKind::kNumber,
                             kPositive}, &W::roll_inertia),
        member_parameter<W>({"yaw_inertia", nullptr, "kg m^2", "I_zz about the vertical axis", ParameterKind::kNumber,
                             kPositive}, &W::yaw_inertia),
        member_parameter<W>({"spin_inertia", nullptr, "kg m^2", "I_yy about the axle", ParameterKind::kNumber,
                             kPositive}, &W::spin_inertia),
        member_parameter<W>({"speed", nullptr, "m/s", "constant forward speed", ParameterKind::kNumber,
                             {0.0, Bound::kOpen, kMaxSpeed, Bound::kClosed}}, &W::speed),
        member_parameter<W>({"vertical_force", nullptr, "N", "external vertical load, downward"}, &W::vertical_force),
        member_parameter<W>({"lateral_force", nullptr, "N", "external lateral load, towards +y (left rail)"},
                            &W::lateral_force),
        member_parameter<W>({"include_gravity", nullptr, "-", "true: m g acts on top of vertical_force"},
                            &W::include_gravity),
        member_parameter<W>({"gravity", nullptr, "m/s^2",
                             "g, > 0: the load acts as a weight along the apparent gravity (V^2 kappa / g)",
                             ParameterKind::kNumber, kPositive}, &W::gravity),
    };
    append(t, lift_parameters(suspension_table(), &W::suspension));
    append(t, lift_parameters(material_table(), &W::material));
    const ParameterRange grid = closed(kMinFastsimGrid, kMaxFastsimGrid);
    t.push_back(member_parameter<W>({"fastsim_elements", nullptr, "-", "FASTSIM elements per strip",
                                     ParameterKind::kInteger, grid}, &W::fastsim_elements));
    t.push_back(member_parameter<W>({"fastsim_strips", nullptr, "-", "FASTSIM strips", ParameterKind::kInteger, grid},
                                    &W::fastsim_strips));
    // Open at both ends: Nadal's limit needs a flange between the tread (0) and vertical (pi/2).
    t.push_back(member_parameter<W>({"flange_angle", nullptr, "rad",
                                     "largest flange angle of the wheel, for Nadal's Y/Q limit (S1002: 70 deg)",
                                     ParameterKind::kNumber, {0.0, Bound::kOpen, kMaxFlangeAngle, Bound::kOpen}},
                                    &W::flange_angle));
    return t;
  }();
  return table;
}

const std::vector<Parameter<InitialState>>& initial_state_table() {
  using I = InitialState;
  static const std::vector<Parameter<I>> table{
      member_parameter<I>({"y0", nullptr, "m", "initial lateral shift", ParameterKind::kNumber, below_magnitude(0.05)},
                          &I::y),
      member_parameter<I>({"yaw0", nullptr, "rad", "initial yaw angle", ParameterKind::kNumber,
                           below_magnitude(kMaxValidatedYaw)}, &I::yaw),
      member_parameter<I>({"y_dot0", nullptr, "m/s", "initial lateral velocity"}, &I::y_dot),
      member_parameter<I>({"yaw_dot0", nullptr, "rad/s", "initial yaw rate"}, &I::yaw_dot),
      member_parameter<I>({"spin_rate_offset", nullptr, "rad/s", "initial spin rate minus speed / r0"},
                          &I::spin_rate_offset),
  };
  return table;
}

const std::vector<Parameter<IntegratorSettings>>& integrator_settings_table() {
  using G = IntegratorSettings;
  static const std::vector<Parameter<G>> table{
      member_parameter<G>({"t_end", nullptr, "s", "simulated end time", ParameterKind::kNumber, kPositive}, &G::t_end),
      member_parameter<G>({"rtol", nullptr, "-", "relative tolerance of the integrator", ParameterKind::kNumber,
                           {0.0, Bound::kOpen, 0.1, Bound::kOpen}}, &G::relative_tolerance),
      member_parameter<G>({"position_tolerance", nullptr, "m, rad", "absolute tolerance of y, z, roll, yaw",
                           ParameterKind::kNumber, kPositive}, &G::position_tolerance),
      member_parameter<G>({"velocity_tolerance", nullptr, "m/s, rad/s", "absolute tolerance of the rates",
                           ParameterKind::kNumber, kPositive}, &G::velocity_tolerance),
      member_parameter<G>({"max_step", nullptr, "s", "largest step", ParameterKind::kNumber, kPositive}, &G::max_step),
      member_parameter<G>({"max_steps", nullptr, "-", "steps before the run fails", ParameterKind::kInteger,
                           closed(1, kMaxRunSteps)}, &G::max_steps),
      member_parameter<G>({"output_period", nullptr, "s", "simulated time between output samples",
                           ParameterKind::kNumber, kPositive}, &G::output_period),
      member_parameter<G>({"two_point_sliding", nullptr, "-",
                           "rigid contact: a wheel whose contact point would chatter between two minima slides "
                           "in two-point contact (false: one-point contact, a restart at every switch)"},
                          &G::two_point_sliding),
  };
  return table;
}

const std::vector<RunParameter>& run_parameter_table() {
  static const std::vector<RunParameter> table = [] {
    std::vector<RunParameter> t = lift_parameters(wheelset_parameter_table(), &RunSpec::wheelset);
    append(t, lift_parameters(initial_state_table(), &RunSpec::initial));
    append(t, lift_parameters(integrator_settings_table(), &RunSpec::integrator));
    return t;
  }();
  return table;
}

}  // namespace wrc
