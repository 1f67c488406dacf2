// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Kalker's creepages at a wheel-rail contact point from the rigid wheelset motion, in the general
/// (sign-safe) vector form: the rail is at rest in the track frame, so the slip velocity is the
/// velocity of the wheel material at the contact point,
///   v_c = v_G + omega x r_c,
/// resolved in the contact frame {t1, t2, n} and divided by the forward speed V:
///   xi_x = v_c . t1 / V,   xi_y = v_c . t2 / V,   phi_s = omega . n / V.
///
/// Frames and conventions (track frame, SI units): x forward along the track, y lateral to the LEFT,
/// z up. n is the unit contact normal pointing from the rail into the wheel; t1 is the unit vector of
/// the track's x axis projected onto the contact plane (longitudinal); t2 = n x t1 (lateral, in the
/// contact plane, pointing left for a flat contact). For the left wheel with contact angle delta,
/// n = (0, -sin delta, cos delta) and t2 = (0, cos delta, sin delta).
///
/// For rigid contact (zero normal slip velocity) this reproduces the linearised table of the physics
/// notes, e.g. xi_y = (y' + r phi' - V psi) / (V cos delta); for elastic contact it also contains the
/// normal-velocity part, which the linearised table drops.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/contact/creep_forces.hpp"

namespace wrc {

/// The orthonormal contact frame at one contact point, in track coordinates.
struct ContactFrame {
  Eigen::Vector3d t1;  ///< longitudinal tangent (track x projected onto the contact plane) [-]
  Eigen::Vector3d t2;  ///< lateral tangent, t2 = n x t1 [-]
  Eigen::Vector3d n;   ///< unit normal from the rail into the wheel [-]
};

/// Builds the contact frame from the contact normal.
/// @param normal normal from the rail into the wheel, track frame [-]; normalised here, so any positive
///        length works.
/// @throws std::invalid_argument when the normal is not finite, has zero length, or lies within 1e-6
///         of the track's x axis (no longitudinal direction in the contact plane).
ContactFrame contact_frame(const Eigen::Vector3d& normal);

/// Creepages at one contact point of a rigid wheelset on a rail at rest.
/// @param forward_speed V [m/s], > 0: the rolling speed the creepages are normalised by.
/// @param centre_velocity v_G, velocity of the wheelset centre, track frame [m/s].
/// @param angular_velocity omega, wheelset angular velocity, track frame [rad/s]
///        (to first order (phi' - psi Omega, Omega, psi') with the spin Omega = V/r0 + beta').
/// @param contact_point r_c, contact point relative to the wheelset centre, track frame [m].
/// @param normal unit normal from the rail into the wheel, track frame [-] (normalised here).
/// @return xi_x, xi_y [-] and phi_s [1/m].
/// @throws std::invalid_argument naming the value when V <= 0 or an input is not finite, or as contact_frame().
Creepages creepages(double forward_speed, const Eigen::Vector3d& centre_velocity,
                    const Eigen::Vector3d& angular_velocity, const Eigen::Vector3d& contact_point,
                    const Eigen::Vector3d& normal);

}  // namespace wrc
