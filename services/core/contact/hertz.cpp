// SPDX-License-Identifier: Apache-2.0
#include "core/contact/hertz.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/contact/elliptic.hpp"

namespace wrc {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Smallest minor/major axis ratio the shape solver accepts (curvature ratio ~6e12 there).
constexpr double kMinAxisRatio = 1e-7;

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument(what); }

// ln of the curvature ratio max(A,B)/min(A,B) produced by the axis ratio k' = exp(t), t < 0.
double log_curvature_ratio(double t) {
  const double kc = std::exp(t);
  const CompleteEllipticIntegrals ei = complete_elliptic_integrals_from_complement(kc);
  return std::log(ei.E_minus_kc2_K / (kc * kc * ei.K_minus_E));
}

void check_modulus(double contact_modulus, const char* where) {
  if (!(contact_modulus > 0.0) || !std::isfinite(contact_modulus)) {
    std::ostringstream msg;
    msg << where << ": contact modulus E* = " << contact_modulus << " Pa must be positive and finite";
    fail(msg.str());
  }
}

void check_shape(const HertzShape& s, const char* where) {
  if (!(s.A > 0.0) || !(s.B > 0.0) || !(s.minor_over_major > 0.0)) {
    std::ostringstream msg;
    msg << where << ": invalid Hertz shape (A = " << s.A << " 1/m, B = " << s.B
        << " 1/m); build it with hertz_shape()";
    fail(msg.str());
  }
}

// Fills a, b, p0 and C_H once the minor semi-axis is known.
HertzContact finish(const HertzShape& s, double contact_modulus, double minor, double normal_force,
                    double penetration) {
  HertzContact c;
  c.shape = s;
  const double major = minor / s.minor_over_major;
  const bool rolling_is_major = s.B >= s.A;
  c.a = rolling_is_major ? major : minor;
  c.b = rolling_is_major ? minor : major;
  c.normal_force = normal_force;
  c.penetration = penetration;
  c.stiffness = hertz_stiffness(s, contact_modulus);
  c.max_pressure = hertz_max_pressure(normal_force, c.a, c.b);
  return c;
}

}  // namespace

double hertz_max_pressure(double normal_force, double a, double b) {
  const bool bad_force = !(normal_force >= 0.0) || !std::isfinite(normal_force);
  const bool bad_axes = normal_force > 0.0 && !(a > 0.0 && b > 0.0 && std::isfinite(a) && std::isfinite(b));
  if (bad_force || bad_axes) {
    std::ostringstream msg;
    msg << "hertz_max_pressure: need N >= 0 and, for N > 0, semi-axes a, b > 0, got N = " << normal_force
        << " N, a = " << a << " m, b = " << b << " m";
    fail(msg.str());
  }
  return normal_force > 0.0 ? 3.0 * normal_force / (2.0 * kPi * a * b) : 0.0;
}

double contact_modulus(double shear_modulus, double poisson) {
  if (!(shear_modulus > 0.0) || !std::isfinite(shear_modulus) || !(poisson >= 0.0 && poisson < 0.5)) {
    std::ostringstream msg;
    msg << "contact_modulus: need shear modulus G > 0 and Poisson's ratio in [0, 0.5), got G = "
        << shear_modulus << " Pa, nu = " << poisson;
    fail(msg.str());
  }
  return shear_modulus / (1.0 - poisson);
}

HertzShape hertz_shape(double A, double B) {
  if (!(A > 0.0) || !(B > 0.0) || !std::isfinite(A) || !std::isfinite(B)) {
    std::ostringstream msg;
    msg << "hertz_shape: relative curvatures must be positive and finite, got A = " << A
        << " 1/m, B = " << B << " 1/m";
    fail(msg.str());
  }
  HertzShape s;
  s.A = A;
  s.B = B;
  const double ratio = std::max(A, B) / std::min(A, B);
  double kc = 1.0;
  if (ratio > 1.0) {
    const double target = std::log(ratio);
    auto f = [target](double t) { return log_curvature_ratio(t) - target; };
    const double t_floor = std::log(kMinAxisRatio);
    // Start from the Brewe-Hamrock estimate a/b ~ 1.0339 (B/A)^0.636 and bracket the root;
    // f is decreasing in t (a rounder ellipse needs a smaller curvature ratio).
    double t0 = std::min(-1e-3, -std::log(1.0339) - 0.636 * target);
    t0 = std::max(t0, t_floor);
    double f0 = f(t0);
    double t_lo, f_lo, t_hi, f_hi;  // f(t_lo) >= 0 >= f(t_hi), t_lo < t_hi < 0
    if (f0 >= 0.0) {
      t_lo = t0, f_lo = f0;
      t_hi = 0.5 * t0, f_hi = f(t_hi);
      while (f_hi > 0.0) {
        t_lo = t_hi, f_lo = f_hi;
        t_hi *= 0.5;
        if (t_hi > -1e-300) break;  // only for curvature ratios within rounding of 1
        f_hi = f(t_hi);
      }
    } else {
      t_hi = t0, f_hi = f0;
      double step = 0.25;
      t_lo = std::max(t0 - step, t_floor), f_lo = f(t_lo);
      while (f_lo < 0.0) {
        if (t_lo <= t_floor) {
          std::ostringstream msg;
          msg << "hertz_shape: curvature ratio " << ratio << " (A = " << A << " 1/m, B = " << B
              << " 1/m) is beyond the supported axis ratio 1/" << 1.0 / kMinAxisRatio;
          fail(msg.str());
        }
        t_hi = t_lo, f_hi = f_lo;
        step *= 2.0;
        t_lo = std::max(t_lo - step, t_floor), f_lo = f(t_lo);
      }
    }
    // Illinois (modified regula falsi): superlinear, never leaves the bracket.
    double t = t_hi;
    int side = 0;
    for (int it = 0; it < 100 && (t_hi - t_lo) > 1e-15 * (1.0 + std::abs(t_lo)); ++it) {
      t = (t_lo * f_hi - t_hi * f_lo) / (f_hi - f_lo);
      const double ft = f(t);
      if (ft == 0.0) {
        t_lo = t_hi = t;
        break;
      }
      if (ft > 0.0) {
        t_lo = t, f_lo = ft;
        if (side == -1) f_hi *= 0.5;
        side = -1;
      } else {
        t_hi = t, f_hi = ft;
        if (side == +1) f_lo *= 0.5;
        side = +1;
      }
      if (std::abs(ft) < 1e-15) break;
    }
    kc = std::exp(t);
  }
  const CompleteEllipticIntegrals ei = complete_elliptic_integrals_from_complement(kc);
  s.minor_over_major = kc;
  s.eccentricity = std::sqrt((1.0 - kc) * (1.0 + kc));
  s.K = ei.K;
  s.E = ei.E;
  const double major_coef = std::cbrt(2.0 * ei.E / (kPi * kc * kc));
  const double minor_coef = std::cbrt(2.0 * ei.E * kc / kPi);
  const bool rolling_is_major = B >= A;
  s.m = rolling_is_major ? major_coef : minor_coef;
  s.n = rolling_is_major ? minor_coef : major_coef;
  s.axis_ratio = s.m / s.n;
  return s;
}

double hertz_stiffness(const HertzShape& s, double contact_modulus) {
  check_shape(s, "hertz_stiffness");
  check_modulus(contact_modulus, "hertz_stiffness");
  return (2.0 * kPi * contact_modulus / 3.0) * std::sqrt(s.E) /
         (std::sqrt(s.A + s.B) * s.K * std::sqrt(s.K) * s.minor_over_major);
}

HertzContact hertz_from_force(const HertzShape& s, double contact_modulus, double normal_force) {
  check_shape(s, "hertz_from_force");
  check_modulus(contact_modulus, "hertz_from_force");
  if (!(normal_force >= 0.0) || !std::isfinite(normal_force)) {
    std::ostringstream msg;
    msg << "hertz_from_force: normal force N = " << normal_force << " N must be non-negative and finite";
    fail(msg.str());
  }
  const double scale = std::cbrt(3.0 * normal_force / (4.0 * contact_modulus * (s.A + s.B)));
  const double minor = std::cbrt(2.0 * s.E * s.minor_over_major / kPi) * scale;
  const double penetration = (s.A + s.B) * minor * minor * s.K / s.E;
  return finish(s, contact_modulus, minor, normal_force, penetration);
}

HertzContact hertz_from_penetration(const HertzShape& s, double contact_modulus, double penetration) {
  check_shape(s, "hertz_from_penetration");
  check_modulus(contact_modulus, "hertz_from_penetration");
  if (!(penetration >= 0.0) || !std::isfinite(penetration)) {
    std::ostringstream msg;
    msg << "hertz_from_penetration: penetration delta = " << penetration << " m must be non-negative and finite";
    fail(msg.str());
  }
  const double minor = std::sqrt(penetration * s.E / ((s.A + s.B) * s.K));
  const double normal_force = hertz_stiffness(s, contact_modulus) * penetration * std::sqrt(penetration);
  return finish(s, contact_modulus, minor, normal_force, penetration);
}

HertzContact hertz_from_force(double A, double B, double contact_modulus, double normal_force) {
  return hertz_from_force(hertz_shape(A, B), contact_modulus, normal_force);
}

}  // namespace wrc
