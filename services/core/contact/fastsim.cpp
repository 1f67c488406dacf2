#include "core/contact/fastsim.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wrc {
namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int kMaxCount = 10000;
}  // namespace

Fastsim::Fastsim(int elements_per_strip, int strips) : m_x_(elements_per_strip), m_y_(strips) {
  if (m_x_ < 1 || m_x_ > kMaxCount || m_y_ < 1 || m_y_ > kMaxCount) {
    std::ostringstream msg;
    msg << "Fastsim: grid " << elements_per_strip << "x" << strips << " (elements per strip x strips) must have "
        << "both counts in 1.." << kMaxCount;
    throw std::invalid_argument(msg.str());
  }
  strip_eta_.resize(m_y_);
  strip_half_length_.resize(m_y_);
  for (int j = 0; j < m_y_; ++j) {
    const double eta = -1.0 + (2.0 * j + 1.0) / m_y_;
    strip_eta_[j] = eta;
    strip_half_length_[j] = std::sqrt((1.0 - eta) * (1.0 + eta));
  }
  element_zeta_.resize(m_x_);
  element_bound_.resize(m_x_);
  for (int i = 0; i < m_x_; ++i) {
    const double zeta = 1.0 - (2.0 * i + 1.0) / m_x_;
    element_zeta_[i] = zeta;
    element_bound_[i] = (1.0 - zeta) * (1.0 + zeta);
  }
}

CreepForces Fastsim::solve(const CreepPatch& patch, const KalkerCoefficients& k, const Creepages& cr) const {
  validate_creep_patch(patch, "fastsim");
  validate_creepages(cr, "fastsim");
  if (!(k.c11 > 0.0) || !(k.c22 > 0.0) || !(k.c23 > 0.0)) {
    std::ostringstream msg;
    msg << "fastsim: Kalker coefficients must be positive, got C11 = " << k.c11 << ", C22 = " << k.c22
        << ", C23 = " << k.c23;
    throw std::invalid_argument(msg.str());
  }
  const double a = patch.a;
  const double b = patch.b;
  const double G = patch.shear_modulus;
  const double c = std::sqrt(a * b);
  // Inverse flexibilities [Pa/m]: 1/L1, 1/L2, 1/L3.
  const double inv_l1 = 3.0 * k.c11 * G / (8.0 * a);
  const double inv_l2 = 3.0 * k.c22 * G / (8.0 * a);
  const double inv_l3 = 4.0 * k.c23 * G * c / (kPi * a * a);
  const double bound_scale = patch.friction * 2.0 * patch.normal_force / (kPi * a * b);  // mu p_max [Pa]
  const double dy = 2.0 * b / m_y_;
  const double sx = cr.longitudinal * inv_l1;
  const double sy = cr.lateral * inv_l2;
  const double sphi = cr.spin * inv_l3;

  double fx = 0.0, fy = 0.0, mz = 0.0, slip_area = 0.0, area = 0.0;
  const double* zeta = element_zeta_.data();
  const double* ebound = element_bound_.data();
  for (int j = 0; j < m_y_; ++j) {
    const double eta = strip_eta_[j];
    const double y = b * eta;
    const double aj = a * strip_half_length_[j];
    const double dx = 2.0 * aj / m_x_;
    const double gj = bound_scale * (1.0 - eta) * (1.0 + eta);  // bound on the strip axis [Pa]
    const double ux = (sx - sphi * y) * dx;                      // constant along the strip [Pa]
    const double uy0 = sy * dx;
    const double uy_per_x = sphi * dx;
    double px = 0.0, py = 0.0;           // traction carried from the previous element [Pa]
    double sum_px = 0.0, sum_py = 0.0, sum_xpy = 0.0;
    int slipping = 0;
    for (int i = 0; i < m_x_; ++i) {
      const double x = aj * zeta[i];
      const double uy = uy0 + uy_per_x * x;
      const double g = gj * ebound[i];
      const double g2 = g * g;
      // half-step (centre) value charged to this element
      double hx = px - 0.5 * ux, hy = py - 0.5 * uy;
      const double h2 = hx * hx + hy * hy;
      if (h2 > g2) {
        const double s = g / std::sqrt(h2);
        hx *= s, hy *= s;
        ++slipping;
      }
      sum_px += hx;
      sum_py += hy;
      sum_xpy += x * hy;
      // full-step value carried to the next element
      px -= ux, py -= uy;
      const double p2 = px * px + py * py;
      if (p2 > g2) {
        const double s = g / std::sqrt(p2);
        px *= s, py *= s;
      }
    }
    const double da = dx * dy;
    fx += sum_px * da;
    fy += sum_py * da;
    mz += (sum_xpy - y * sum_px) * da;
    slip_area += slipping * da;
    area += m_x_ * da;
  }
  CreepForces f;
  f.fx = fx;
  f.fy = fy;
  f.mz = mz;
  f.slip_fraction = area > 0.0 ? slip_area / area : 0.0;
  return f;
}

CreepForces Fastsim::solve(const CreepPatch& patch, const Creepages& creepages) const {
  validate_creep_patch(patch, "fastsim");
  return solve(patch, kalker_coefficients(patch.a / patch.b, patch.poisson), creepages);
}

CreepForces fastsim(const CreepPatch& patch, const Creepages& creepages, int elements_per_strip, int strips) {
  return Fastsim(elements_per_strip, strips).solve(patch, creepages);
}

}  // namespace wrc
