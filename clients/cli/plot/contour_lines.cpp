// SPDX-License-Identifier: Apache-2.0
#include "cli/plot/contour_lines.hpp"

#include <array>
#include <cmath>

namespace wrc::cli::plot {

std::vector<LineSegment> level_line(const std::vector<double>& x, const std::vector<double>& y,
                                    const std::vector<double>& f, double value) {
  std::vector<LineSegment> segments;
  const size_t nx = x.size();
  if (nx < 2 || y.size() < 2 || f.size() != nx * y.size()) return segments;
  for (size_t j = 0; j + 1 < y.size(); ++j) {
    for (size_t i = 0; i + 1 < nx; ++i) {
      // Corners counter-clockwise: (i,j), (i+1,j), (i+1,j+1), (i,j+1).
      const std::array<double, 4> cx{x[i], x[i + 1], x[i + 1], x[i]};
      const std::array<double, 4> cy{y[j], y[j], y[j + 1], y[j + 1]};
      const std::array<double, 4> cf{f[j * nx + i], f[j * nx + i + 1], f[(j + 1) * nx + i + 1], f[(j + 1) * nx + i]};
      bool missing = false;
      for (double v : cf) missing = missing || std::isnan(v);
      if (missing) continue;
      // Crossing points on the four edges (edge k joins corner k and k+1).
      std::array<double, 4> px{}, py{};
      std::array<bool, 4> crossed{};
      for (int k = 0; k < 4; ++k) {
        const int l = (k + 1) % 4;
        const bool below_k = cf[k] < value, below_l = cf[l] < value;
        if (below_k == below_l) continue;
        const double t = (value - cf[k]) / (cf[l] - cf[k]);
        px[k] = cx[k] + t * (cx[l] - cx[k]);
        py[k] = cy[k] + t * (cy[l] - cy[k]);
        crossed[k] = true;
      }
      const int count = crossed[0] + crossed[1] + crossed[2] + crossed[3];
      if (count == 2) {
        int a = -1, b = -1;
        for (int k = 0; k < 4; ++k)
          if (crossed[k]) (a < 0 ? a : b) = k;
        segments.push_back({px[a], py[a], px[b], py[b]});
      } else if (count == 4) {
        // Saddle: corners 0 and 2 on one side. Join the edges around the corners on the side the
        // centre is not on.
        const bool centre_below = (cf[0] + cf[1] + cf[2] + cf[3]) / 4 < value;
        const bool corner0_below = cf[0] < value;
        if (centre_below == corner0_below) {  // corners 1 and 3 are cut off
          segments.push_back({px[0], py[0], px[1], py[1]});
          segments.push_back({px[2], py[2], px[3], py[3]});
        } else {  // corners 0 and 2 are cut off
          segments.push_back({px[3], py[3], px[0], py[0]});
          segments.push_back({px[1], py[1], px[2], py[2]});
        }
      }
    }
  }
  return segments;
}

}  // namespace wrc::cli::plot
