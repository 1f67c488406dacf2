// SPDX-License-Identifier: Apache-2.0
#include "core/contact/fastsim.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/numerics/simd_clones.hpp"

namespace wrc {
namespace {
constexpr double kPi = 3.14159265358979323846;

// Four strips in lockstep (GCC vector extension: one AVX register in the x86-64-v3 clone, two SSE
// registers in the baseline): strips are independent, each a serial recursion along x, so the
// lanes are independent chains.
constexpr int kLanes = 4;
typedef double Lanes __attribute__((vector_size(kLanes * sizeof(double))));
typedef long long LaneMask __attribute__((vector_size(kLanes * sizeof(double))));

// What is constant along the strips of a block [m, Pa].
struct StripBlock {
  Lanes half_length;   // a_j
  Lanes bound;         // traction bound on the strip axis
  Lanes slip_x;        // x rigid-slip increment per element, constant along the strip
  Lanes slip_y0;       // y increment without the spin term
  Lanes slip_y_per_x;  // spin term of the y increment per unit of x
};

// The block's sums over its elements: tractions [Pa], x p_y [Pa m] and slipping elements [-].
struct StripSums {
  Lanes px, py, xpy, slipping;
};

// Caps (x, y) to magnitude g in the lanes where |(x, y)|^2 = r2 exceeds g^2 (over): every lane's
// square root and division at once (r2 is a sum of squares, never negative; a lane with r2 = 0 is
// never over, so its 0/0 is discarded), the lanes not over left as they are.
inline void cap(Lanes& x, Lanes& y, const Lanes& r2, const Lanes& g, const LaneMask& over) {
  Lanes root;
  for (int l = 0; l < kLanes; ++l) root[l] = std::sqrt(r2[l]);  // vectorised: no errno (CMakeLists)
  const Lanes scale = g / root;
  x = over ? x * scale : x;
  y = over ? y * scale : y;
}

// One block of strips from the leading edge (zero traction) to the trailing one. The element
// updates are lane-parallel; the capping (cap) runs only when some lane exceeds its bound, so
// the adhering part of a patch costs a few vector operations per element. Compiled for
// x86-64-v3 and the baseline.
WRC_SIMD_CLONES
StripSums sweep_strips(const StripBlock& block, const double* zeta, const double* element_bound, int elements) {
  const Lanes zero = {0.0, 0.0, 0.0, 0.0};
  Lanes px = zero, py = zero;  // traction carried from the previous element [Pa]
  StripSums sums{zero, zero, zero, zero};
  const Lanes half_slip_x = 0.5 * block.slip_x;
  for (int i = 0; i < elements; ++i) {
    const Lanes x = block.half_length * zeta[i];
    const Lanes uy = block.slip_y0 + block.slip_y_per_x * x;
    const Lanes g = block.bound * element_bound[i];
    const Lanes g2 = g * g;
    // half-step (centre) value charged to this element
    Lanes hx = px - half_slip_x, hy = py - 0.5 * uy;
    const Lanes h2 = hx * hx + hy * hy;
    // full-step value carried to the next element
    Lanes qx = px - block.slip_x, qy = py - uy;
    const Lanes q2 = qx * qx + qy * qy;
    const LaneMask h_over = h2 > g2, q_over = q2 > g2;
    const LaneMask over = h_over | q_over;
    if (over[0] | over[1] | over[2] | over[3]) {
      cap(hx, hy, h2, g, h_over);
      cap(qx, qy, q2, g, q_over);
      sums.slipping -= __builtin_convertvector(h_over, Lanes);  // a true lane is -1
    }
    sums.px += hx;
    sums.py += hy;
    sums.xpy += x * hy;
    px = qx, py = qy;
  }
  return sums;
}

}  // namespace

Fastsim::Fastsim(int elements_per_strip, int strips) : m_x_(elements_per_strip), m_y_(strips) {
  if (m_x_ < kMinFastsimCount || m_x_ > kMaxFastsimCount || m_y_ < kMinFastsimCount || m_y_ > kMaxFastsimCount) {
    std::ostringstream msg;
    msg << "Fastsim: grid " << elements_per_strip << "x" << strips << " (elements per strip x strips) must have "
        << "both counts in " << kMinFastsimCount << ".." << kMaxFastsimCount;
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
  for (int j0 = 0; j0 < m_y_; j0 += kLanes) {
    // Missing strips of the last block are zero-width strips: no slip, no bound, no force.
    StripBlock block;
    double y[kLanes], da[kLanes];
    for (int l = 0; l < kLanes; ++l) {
      const int j = j0 + l;
      const bool real = j < m_y_;
      const double eta = real ? strip_eta_[j] : 0.0;
      y[l] = b * eta;
      block.half_length[l] = real ? a * strip_half_length_[j] : 0.0;
      const double dx = 2.0 * block.half_length[l] / m_x_;
      block.bound[l] = real ? bound_scale * (1.0 - eta) * (1.0 + eta) : 0.0;
      block.slip_x[l] = (sx - sphi * y[l]) * dx;
      block.slip_y0[l] = sy * dx;
      block.slip_y_per_x[l] = sphi * dx;
      da[l] = dx * dy;
    }
    const StripSums sums = sweep_strips(block, element_zeta_.data(), element_bound_.data(), m_x_);
    for (int l = 0; l < kLanes; ++l) {
      fx += sums.px[l] * da[l];
      fy += sums.py[l] * da[l];
      mz += (sums.xpy[l] - y[l] * sums.px[l]) * da[l];
      slip_area += sums.slipping[l] * da[l];
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
