#include "core/geometry/slope_envelope.hpp"

#include <algorithm>
#include <cmath>

namespace wrc {

SlopeEnvelope::SlopeEnvelope(double lower, double upper, double bin, int per_bin, double safety,
                             const std::function<void(double, double&, double&)>& derivatives)
    : lower_(lower), bin_(bin), inverse_bin_(1.0 / bin) {
  const int bins = std::max(1, static_cast<int>(std::ceil((upper - lower) / bin)));
  slope_.assign(bins, 0.0);
  second_.assign(bins, 0.0);
  for (int i = 0; i < bins; ++i) {
    for (int j = 0; j <= per_bin; ++j) {
      const double x = std::min(upper, lower + bin * (i + static_cast<double>(j) / per_bin));
      double d1 = 0, d2 = 0;
      derivatives(x, d1, d2);
      if (std::isfinite(d1)) slope_[i] = std::max(slope_[i], std::fabs(d1));
      if (std::isfinite(d2)) second_[i] = std::max(second_[i], std::fabs(d2));
    }
  }
  // Neighbouring bins share their ends; a curvature jump at a bin end counts for both.
  for (auto* v : {&slope_, &second_}) {
    std::vector<double> widened(*v);
    for (int i = 0; i < bins; ++i) {
      if (i > 0) widened[i] = std::max(widened[i], (*v)[i - 1]);
      if (i + 1 < bins) widened[i] = std::max(widened[i], (*v)[i + 1]);
      widened[i] *= safety;
    }
    *v = std::move(widened);
  }
}

int SlopeEnvelope::bin_of(double x) const {
  const double b = (x - lower_) * inverse_bin_;
  if (!(b > 0)) return 0;
  const int last = static_cast<int>(slope_.size()) - 1;
  return b >= last ? last : static_cast<int>(b);
}

double SlopeEnvelope::max_slope(double a, double b) const {
  double m = 0;
  for (int i = bin_of(std::min(a, b)), e = bin_of(std::max(a, b)); i <= e; ++i) m = std::max(m, slope_[i]);
  return m;
}

double SlopeEnvelope::max_second(double a, double b) const {
  double m = 0;
  for (int i = bin_of(std::min(a, b)), e = bin_of(std::max(a, b)); i <= e; ++i) m = std::max(m, second_[i]);
  return m;
}

}  // namespace wrc
