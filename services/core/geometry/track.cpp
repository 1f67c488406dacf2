#include "core/geometry/track.hpp"

#include <optional>
#include <sstream>
#include <stdexcept>

#include "core/numerics/number_text.hpp"

namespace wrc {
namespace {
void check(double value, double min, double max, const char* what) {
  if (!std::isfinite(value) || value < min || value > max) {
    std::ostringstream msg;
    msg << what << " = " << value << " is outside [" << min << ", " << max << "]";
    throw std::invalid_argument(msg.str());
  }
}
}  // namespace

void TrackParameters::validate() const {
  check(gauge, 0.5, 2.5, "gauge [m]");
  check(gauge_depth, 0.0, 0.05, "gauge depth [m]");
  check(flange_back_spacing, 0.4, 2.4, "flange-back spacing [m]");
  check(taping_line_offset, 0.0, 0.2, "taping-line offset [m]");
  check(inclination, -0.2, 0.2, "rail inclination [rad]");
  check(nominal_radius, 0.1, 1.5, "nominal rolling radius [m]");
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
