// SPDX-License-Identifier: Apache-2.0
#include "core/numerics/bspline_span.hpp"

#include <stdexcept>
#include <string>

namespace wrc {

BSplineSpanTable bspline_span_derivatives(const std::vector<double>& knots, int p, int span, double x) {
  constexpr int kMaxOrder = kMaxBSplineSpanDegree + 1;
  if (p < 0 || p > kMaxBSplineSpanDegree)
    throw std::invalid_argument("B-spline span: degree " + std::to_string(p) + " not in 0.." +
                                std::to_string(kMaxBSplineSpanDegree));
  if (span < p || static_cast<std::size_t>(span + p) >= knots.size())
    throw std::invalid_argument("B-spline span: span " + std::to_string(span) + " of degree " + std::to_string(p) +
                                " needs knots " + std::to_string(span - p) + ".." + std::to_string(span + p) +
                                " of " + std::to_string(knots.size()));
  using DerivativeTable = BSplineSpanTable;
  // values[q][j]: the degree-q B-spline N_{span-q+j, q}(x), j = 0..q.
  DerivativeTable values{};
  values[0][0] = 1.0;
  for (int q = 1; q <= p; ++q) {
    for (int j = 0; j <= q; ++j) {
      const int i = span - q + j;  // global index of N_{i,q}
      double v = 0.0;
      if (j > 0) {  // N_{i,q-1} is values[q-1][j-1]
        const double w = knots[i + q] - knots[i];
        if (w > 0) v += (x - knots[i]) / w * values[q - 1][j - 1];
      }
      if (j < q) {  // N_{i+1,q-1} is values[q-1][j]
        const double w = knots[i + q + 1] - knots[i + 1];
        if (w > 0) v += (knots[i + q + 1] - x) / w * values[q - 1][j];
      }
      values[q][j] = v;
    }
  }
  DerivativeTable d{};
  for (int k = 0; k <= p; ++k) {
    // coefficient[j'] of N_{span-(p-k)+j', p-k} in the k-th derivative of each N_{span-p+j, p}.
    for (int j = 0; j <= p; ++j) {
      std::array<double, kMaxOrder> c{};
      c[static_cast<std::size_t>(j)] = 1.0;  // indices relative to span - p, degree p
      int q = p;
      for (int step = 0; step < k; ++step, --q) {
        // d/dx sum_i c_i N_{i,q} = q sum_i (c_i - c_{i-1}) / (u_{i+q} - u_i) N_{i,q-1}
        std::array<double, kMaxOrder> next{};
        for (int r = 0; r <= p; ++r) {
          const int i = span - p + r;
          const double w = knots[i + q] - knots[i];
          const double previous = r > 0 ? c[static_cast<std::size_t>(r - 1)] : 0.0;
          next[static_cast<std::size_t>(r)] = w > 0 ? q * (c[static_cast<std::size_t>(r)] - previous) / w : 0.0;
        }
        c = next;
      }
      // Evaluate sum_r c_r N_{span-p+r, q}(x): the non-zero ones are r = p - q .. p.
      double sum = 0.0;
      for (int r = p - q; r <= p; ++r) sum += c[static_cast<std::size_t>(r)] * values[q][r - (p - q)];
      d[k][j] = sum;
    }
  }
  return d;
}

}  // namespace wrc
