// SPDX-License-Identifier: Apache-2.0
#include "core/geometry/slope_envelope.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wrc {

SlopeEnvelope::SlopeEnvelope(double lower, double upper, double bin, int per_bin, double safety,
                             const std::function<void(double, double&, double&)>& derivatives)
    : lower_(lower), inverse_bin_(1.0 / bin) {
  const int bins = std::max(1, static_cast<int>(std::ceil((upper - lower) / bin)));
  slope_.assign(bins, 0.0);
  second_.assign(bins, 0.0);
  second_low_.assign(bins, std::numeric_limits<double>::infinity());
  second_high_.assign(bins, -std::numeric_limits<double>::infinity());
  for (int i = 0; i < bins; ++i) {
    for (int j = 0; j <= per_bin; ++j) {
      const double x = std::min(upper, lower + bin * (i + static_cast<double>(j) / per_bin));
      double d1 = 0, d2 = 0;
      derivatives(x, d1, d2);
      if (std::isfinite(d1)) slope_[i] = std::max(slope_[i], std::fabs(d1));
      if (std::isfinite(d2)) {
        second_[i] = std::max(second_[i], std::fabs(d2));
        second_low_[i] = std::min(second_low_[i], d2);
        second_high_[i] = std::max(second_high_[i], d2);
      }
    }
    if (second_low_[i] > second_high_[i]) second_low_[i] = second_high_[i] = 0.0;  // no finite sample
  }
  // Signed ranges: neighbours included, then widened by a quarter of the width plus 5 % of the
  // magnitude (the samples are 1/per_bin of a bin apart; f'' changes little between them).
  {
    std::vector<double> lo(second_low_), hi(second_high_);
    for (int i = 0; i < bins; ++i) {
      if (i > 0) {
        lo[i] = std::min(lo[i], second_low_[i - 1]);
        hi[i] = std::max(hi[i], second_high_[i - 1]);
      }
      if (i + 1 < bins) {
        lo[i] = std::min(lo[i], second_low_[i + 1]);
        hi[i] = std::max(hi[i], second_high_[i + 1]);
      }
      const double pad = 0.25 * (hi[i] - lo[i]) + 0.05 * std::max(std::fabs(lo[i]), std::fabs(hi[i]));
      lo[i] -= pad;
      hi[i] += pad;
    }
    second_low_ = std::move(lo);
    second_high_ = std::move(hi);
  }
  // Maxima and ranges over runs of 1..kRun consecutive bins, so that short queries cost O(1).
  for (int w = 0; w < kRun; ++w) {
    Run& r = runs_[w];
    r.slope.resize(bins);
    r.second.resize(bins);
    r.low.resize(bins);
    r.high.resize(bins);
    for (int i = 0; i < bins; ++i) {
      const int j = std::min(bins - 1, i + w);
      const Run* shorter = w > 0 ? &runs_[w - 1] : nullptr;
      r.slope[i] = shorter ? std::max(shorter->slope[i], slope_[j]) : slope_[i];
      r.second[i] = shorter ? std::max(shorter->second[i], second_[j]) : second_[i];
      r.low[i] = shorter ? std::min(shorter->low[i], second_low_[j]) : second_low_[i];
      r.high[i] = shorter ? std::max(shorter->high[i], second_high_[j]) : second_high_[i];
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
  const int i = bin_of(std::min(a, b)), e = bin_of(std::max(a, b));
  if (e - i < kRun) return runs_[e - i].slope[i];
  double m = 0;
  for (int k = i; k <= e; ++k) m = std::max(m, slope_[k]);
  return m;
}

void SlopeEnvelope::second_range(double a, double b, double& low, double& high) const {
  const int i = bin_of(std::min(a, b)), e = bin_of(std::max(a, b));
  if (e - i < kRun) {
    low = runs_[e - i].low[i];
    high = runs_[e - i].high[i];
    return;
  }
  low = std::numeric_limits<double>::infinity();
  high = -std::numeric_limits<double>::infinity();
  for (int k = i; k <= e; ++k) {
    low = std::min(low, second_low_[k]);
    high = std::max(high, second_high_[k]);
  }
}

double SlopeEnvelope::max_second(double a, double b) const {
  const int i = bin_of(std::min(a, b)), e = bin_of(std::max(a, b));
  if (e - i < kRun) return runs_[e - i].second[i];
  double m = 0;
  for (int k = i; k <= e; ++k) m = std::max(m, second_[k]);
  return m;
}

}  // namespace wrc
