// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Inputs and outputs shared by the creep-force laws (linear_creep.hpp, fastsim.hpp): one elliptic
/// contact patch with its material and friction, the three creepages, and the resulting tangential
/// forces and spin moment on the wheel.
///
/// Frame: the contact frame {t1, t2, n} of creepage.hpp; x along t1 (rolling direction), y along t2
/// (lateral, in the contact plane), moments about n (the normal pointing into the wheel).

namespace wrc {

/// One Hertzian contact patch with material and friction.
struct CreepPatch {
  double a = 0;                   ///< semi-axis in the rolling direction [m], > 0
  double b = 0;                   ///< semi-axis in the lateral direction [m], > 0
  double normal_force = 0;        ///< normal force N [N], >= 0 (FASTSIM's traction bound)
  double shear_modulus = 8.2e10;  ///< combined shear modulus G [Pa], > 0
  double poisson = 0.28;          ///< Poisson's ratio nu [-], in [0, 0.5]
  double friction = 0.3;          ///< Coulomb friction coefficient mu [-], >= 0
};

/// Kalker's creepages at one contact point (see creepage.hpp for their definition).
struct Creepages {
  double longitudinal = 0;  ///< xi_x: relative slip velocity along t1 over V [-]
  double lateral = 0;       ///< xi_y: relative slip velocity along t2 over V [-]
  double spin = 0;          ///< phi_s: relative angular velocity about n over V [1/m]
};

/// Tangential contact forces on the WHEEL (the upper body).
struct CreepForces {
  double fx = 0;             ///< force along t1 (rolling direction) [N]
  double fy = 0;             ///< force along t2 (lateral) [N]
  double mz = 0;             ///< spin moment about n [N m]
  double slip_fraction = 0;  ///< slipping share of the contact area [-], 0 for the linear theory
};

/// Checks a patch: a, b, G > 0, N >= 0, mu >= 0, nu in [0, 0.5], all finite.
/// @throws std::invalid_argument naming the offending value; `where` prefixes the message.
void validate_creep_patch(const CreepPatch& patch, const char* where);

/// Checks that all three creepages are finite.
/// @throws std::invalid_argument naming the offending value; `where` prefixes the message.
void validate_creepages(const Creepages& creepages, const char* where);

}  // namespace wrc
