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

  // Strips are independent, each a serial recursion along x whose latency (a square root and a division
  // when an element slips) dominates the cost. Processing kLanes strips in lockstep gives the processor
  // independent chains to overlap; missing strips of the last block are padded with zero-width strips.
  constexpr int kLanes = 4;
  double fx = 0.0, fy = 0.0, mz = 0.0, slip_area = 0.0, area = 0.0;
  const double* zeta = element_zeta_.data();
  const double* ebound = element_bound_.data();
  for (int j0 = 0; j0 < m_y_; j0 += kLanes) {
    double y[kLanes], aj[kLanes], gj[kLanes], ux[kLanes], uy0[kLanes], uy_per_x[kLanes], da[kLanes];
    double px[kLanes], py[kLanes], sum_px[kLanes], sum_py[kLanes], sum_xpy[kLanes], slipping[kLanes];
    for (int l = 0; l < kLanes; ++l) {
      const int j = j0 + l;
      const bool real = j < m_y_;
      const double eta = real ? strip_eta_[j] : 0.0;
      y[l] = b * eta;
      aj[l] = real ? a * strip_half_length_[j] : 0.0;
      const double dx = 2.0 * aj[l] / m_x_;
      gj[l] = real ? bound_scale * (1.0 - eta) * (1.0 + eta) : 0.0;  // bound on the strip axis [Pa]
      ux[l] = (sx - sphi * y[l]) * dx;                                 // constant along the strip [Pa]
      uy0[l] = sy * dx;
      uy_per_x[l] = sphi * dx;
      da[l] = dx * dy;
      px[l] = py[l] = 0.0;  // traction carried from the previous element [Pa]
      sum_px[l] = sum_py[l] = sum_xpy[l] = slipping[l] = 0.0;
    }
    for (int i = 0; i < m_x_; ++i) {
      const double z = zeta[i];
      const double eb = ebound[i];
      for (int l = 0; l < kLanes; ++l) {
        const double x = aj[l] * z;
        const double uy = uy0[l] + uy_per_x[l] * x;
        const double g = gj[l] * eb;
        const double g2 = g * g;
        // half-step (centre) value charged to this element
        double hx = px[l] - 0.5 * ux[l], hy = py[l] - 0.5 * uy;
        const double h2 = hx * hx + hy * hy;
        if (h2 > g2) {
          const double s = g / std::sqrt(h2);
          hx *= s, hy *= s;
          slipping[l] += 1.0;
        }
        sum_px[l] += hx;
        sum_py[l] += hy;
        sum_xpy[l] += x * hy;
        // full-step value carried to the next element
        double qx = px[l] - ux[l], qy = py[l] - uy;
        const double q2 = qx * qx + qy * qy;
        if (q2 > g2) {
          const double s = g / std::sqrt(q2);
          qx *= s, qy *= s;
        }
        px[l] = qx, py[l] = qy;
      }
    }
    for (int l = 0; l < kLanes; ++l) {
      fx += sum_px[l] * da[l];
      fy += sum_py[l] * da[l];
      mz += (sum_xpy[l] - y[l] * sum_px[l]) * da[l];
      slip_area += slipping[l] * da[l];
      area += m_x_ * da[l];
    }
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
