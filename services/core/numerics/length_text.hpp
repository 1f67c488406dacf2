// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A length for a message: metres written in millimetres, the unit railway engineers read profile
/// and contact dimensions in ("0.14 mm", "25 mm").

#include <sstream>
#include <string>

namespace wrc {

/// `metres` [m] as "<value in mm> mm" (default stream precision, six significant digits).
inline std::string in_mm(double metres) {
  std::ostringstream out;
  out << metres * 1e3 << " mm";
  return out.str();
}

}  // namespace wrc
