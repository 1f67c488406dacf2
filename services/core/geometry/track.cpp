// SPDX-License-Identifier: Apache-2.0
#include "core/geometry/track.hpp"

#include <optional>
#include <sstream>
#include <stdexcept>

#include "core/geometry/track_table.hpp"
#include "core/numerics/number_text.hpp"

namespace wrc {

void TrackParameters::validate() const {
  validate_parameters(track_parameter_table(), *this);  // each member's rule; then the rule between them
  if (flange_back_spacing >= gauge) {
    std::ostringstream msg;
    msg << "flange-back spacing " << flange_back_spacing << " m is not smaller than the gauge " << gauge << " m";
    throw std::invalid_argument(msg.str());
  }
}

double parse_inclination(const std::string& text) {
  if (text == "none" || text == "0") return 0.0;
  if (text.rfind("1:", 0) == 0) {
    const std::optional<double> n = finite_number(text.substr(2));
    if (n && *n >= 5) return std::atan(1.0 / *n);
  } else {
    const std::optional<double> v = finite_number(text);
    if (v && std::fabs(*v) <= 0.2) return *v;
  }
  throw std::invalid_argument("inclination '" + text + "' is not 1:N (N >= 5), none, or an angle in [-0.2, 0.2] rad");
}

}  // namespace wrc
