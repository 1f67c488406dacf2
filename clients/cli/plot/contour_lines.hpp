// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Level lines of a function sampled on a rectangular grid (marching squares with linear
/// interpolation along the cell edges): the outlines of the contact area at eps0.

#include <vector>

namespace wrc::cli::plot {

/// One straight piece of a level line: (x0, y0) to (x1, y1).
struct LineSegment {
  double x0, y0, x1, y1;
};

/// The level line value of f sampled at (x[i], y[j]), f[j * x.size() + i]. Cells with a NaN
/// corner give no segment. A saddle cell is resolved by the mean of its corners.
std::vector<LineSegment> level_line(const std::vector<double>& x, const std::vector<double>& y,
                                    const std::vector<double>& f, double value);

}  // namespace wrc::cli::plot
