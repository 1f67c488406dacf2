// SPDX-License-Identifier: Apache-2.0
#include "core/track/irregularity_spectrum.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>

#include "core/numerics/number_text.hpp"

namespace wrc {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ERRI / ORE B176 (as given by Claus and Schiehlen, Vehicle System Dynamics 29 (1998)):
//   vertical level, alignment  S = A Oc^2 / ((O^2 + Or^2)(O^2 + Oc^2))            [m^2/(rad/m)]
//   cross-level (as the rails' roll angle over half the rail distance b = 0.75 m)
//                              S = (Av / b^2) Oc^2 O^2 / ((O^2 + Or^2)(O^2 + Oc^2)(O^2 + Os^2))
// with Oc = 0.8246, Or = 0.0206, Os = 0.4380 rad/m; the low and high levels' A [m rad].
// The cross-level's height difference is 2 b times the angle: 4 b^2 times its density.
constexpr double kErriOc = 0.8246, kErriOr = 0.0206, kErriOs = 0.4380;
struct ErriLevel {
  double a_vertical, a_lateral;  // [m rad]
};
constexpr ErriLevel kErriLow{4.032e-7, 2.119e-7};
constexpr ErriLevel kErriHigh{1.080e-6, 6.125e-7};

// FRA classes (Hamid and Yang's fits, as tabulated by Garg and Dukkipati, Dynamics of Railway
// Vehicle Systems, 1984), in cm^2 / (rad/m) with A in cm^2 rad/m, k = 0.25:
//   vertical level, alignment  S = k A Oc^2 / (O^2 (O^2 + Oc^2))
//   cross-level, gauge         S = 4 k Av Oc^2 / ((O^2 + Oc^2)(O^2 + Os^2))
struct FraClass {
  double a_vertical, a_lateral, omega_s;  // [cm^2 rad/m], [cm^2 rad/m], [rad/m]
};
constexpr FraClass kFraClasses[6] = {{1.2107, 3.3634, 0.6046}, {1.0181, 1.2107, 0.9308}, {0.6816, 0.4128, 0.8520},
                                     {0.5376, 0.3027, 1.1312}, {0.2095, 0.0762, 0.8209}, {0.0339, 0.0339, 0.4380}};
constexpr double kFraOc = 0.8245, kFraK = 0.25;
constexpr double kCm2 = 1e-4;  // [m^2] per cm^2

constexpr double kErriHalfRailDistance = 0.75;  // [m] b of the cross-level density

double erri_density(const ErriLevel& level, IrregularityChannel channel, double o) {
  const double o2 = o * o;
  const double base = kErriOc * kErriOc / ((o2 + kErriOr * kErriOr) * (o2 + kErriOc * kErriOc));
  switch (channel) {
    case IrregularityChannel::kVerticalLevel: return level.a_vertical * base;
    case IrregularityChannel::kAlignment: return level.a_lateral * base;
    case IrregularityChannel::kCrossLevel: {
      const double b = kErriHalfRailDistance;
      const double angle = level.a_vertical / (b * b) * base * o2 / (o2 + kErriOs * kErriOs);
      return 4.0 * b * b * angle;
    }
    case IrregularityChannel::kGauge: return 0.0;
  }
  return 0.0;
}

double fra_density(const FraClass& c, IrregularityChannel channel, double o) {
  const double o2 = o * o;
  const double oc2 = kFraOc * kFraOc;
  switch (channel) {
    case IrregularityChannel::kVerticalLevel: return kCm2 * kFraK * c.a_vertical * oc2 / (o2 * (o2 + oc2));
    case IrregularityChannel::kAlignment: return kCm2 * kFraK * c.a_lateral * oc2 / (o2 * (o2 + oc2));
    case IrregularityChannel::kCrossLevel:
    case IrregularityChannel::kGauge:
      return kCm2 * 4.0 * kFraK * c.a_vertical * oc2 / ((o2 + oc2) * (o2 + c.omega_s * c.omega_s));
  }
  return 0.0;
}

// The band's frequencies: count and spacing.
struct Band {
  double low, step;
  int count;
};

Band band_of(const IrregularityGeneration& g) {
  const double low = 2.0 * kPi / g.max_wavelength;
  const double high = 2.0 * kPi / g.min_wavelength;
  const double finest = 2.0 * kPi / g.length;
  const int count = std::max(64, static_cast<int>(std::ceil((high - low) / finest)));
  return {low, (high - low) / count, count};
}

// A uniform number in [0, 1) from 53 bits of the generator (the same on every platform, unlike
// std::uniform_real_distribution, whose algorithm the standard leaves open).
double unit_random(std::mt19937_64& generator) {
  return static_cast<double>(generator() >> 11) * (1.0 / 9007199254740992.0);
}

}  // namespace

const char* irregularity_spectrum_name(IrregularitySpectrum spectrum) {
  switch (spectrum) {
    case IrregularitySpectrum::kErriLow: return "erri-low";
    case IrregularitySpectrum::kErriHigh: return "erri-high";
    case IrregularitySpectrum::kFra1: return "fra-1";
    case IrregularitySpectrum::kFra2: return "fra-2";
    case IrregularitySpectrum::kFra3: return "fra-3";
    case IrregularitySpectrum::kFra4: return "fra-4";
    case IrregularitySpectrum::kFra5: return "fra-5";
    case IrregularitySpectrum::kFra6: return "fra-6";
  }
  return "?";
}

std::vector<IrregularitySpectrum> irregularity_spectra() {
  return {IrregularitySpectrum::kErriLow, IrregularitySpectrum::kErriHigh, IrregularitySpectrum::kFra1,
          IrregularitySpectrum::kFra2,    IrregularitySpectrum::kFra3,     IrregularitySpectrum::kFra4,
          IrregularitySpectrum::kFra5,    IrregularitySpectrum::kFra6};
}

IrregularitySpectrum parse_irregularity_spectrum(const std::string& name) {
  std::string names;
  for (IrregularitySpectrum s : irregularity_spectra()) {
    if (name == irregularity_spectrum_name(s)) return s;
    names += std::string(names.empty() ? "" : ", ") + irregularity_spectrum_name(s);
  }
  throw std::invalid_argument("unknown irregularity spectrum '" + name + "' (one of " + names + ")");
}

double irregularity_density(IrregularitySpectrum spectrum, IrregularityChannel channel, double omega) {
  if (!(omega > 0.0) || !std::isfinite(omega))
    throw std::invalid_argument("irregularity density: omega = " + number_text(omega) + " rad/m is not positive");
  switch (spectrum) {
    case IrregularitySpectrum::kErriLow: return erri_density(kErriLow, channel, omega);
    case IrregularitySpectrum::kErriHigh: return erri_density(kErriHigh, channel, omega);
    default: {
      const int k = static_cast<int>(spectrum) - static_cast<int>(IrregularitySpectrum::kFra1);
      return fra_density(kFraClasses[k], channel, omega);
    }
  }
}

void IrregularityGeneration::validate() const {
  auto fail = [](const std::string& what) { throw std::invalid_argument("irregularity generation: " + what); };
  if (!(length > 0.0) || !std::isfinite(length)) fail("length = " + number_text(length) + " m is not positive");
  if (!(spacing >= kMinIrregularitySpacing) || !std::isfinite(spacing))
    fail("spacing = " + number_text(spacing) + " m is below " + number_text(kMinIrregularitySpacing) + " m");
  if (length / spacing + 1.0 > static_cast<double>(kMaxIrregularitySamples))
    fail("length / spacing = " + number_text(length / spacing) + " gives more than " +
         std::to_string(kMaxIrregularitySamples) + " samples");
  if (!(min_wavelength > 4.0 * spacing) || !std::isfinite(min_wavelength))
    fail("min_wavelength = " + number_text(min_wavelength) + " m is not above 4 spacings (" +
         number_text(4.0 * spacing) + " m): the samples would not resolve it");
  if (!(max_wavelength > min_wavelength) || !std::isfinite(max_wavelength))
    fail("max_wavelength = " + number_text(max_wavelength) + " m is not above min_wavelength = " +
         number_text(min_wavelength) + " m");
  if (!(fade_in >= 0.0) || !(fade_in <= length))
    fail("fade_in = " + number_text(fade_in) + " m is outside [0, length = " + number_text(length) + "] m");
}

TrackIrregularity generate_irregularity(const IrregularityGeneration& g) {
  g.validate();
  const Band band = band_of(g);
  const std::size_t n = static_cast<std::size_t>(std::floor(g.length / g.spacing + 1e-9)) + 1;
  std::vector<double> distances(n);
  for (std::size_t i = 0; i < n; ++i) distances[i] = static_cast<double>(i) * g.spacing;
  std::array<std::vector<double>, kIrregularityChannelCount> channels;
  std::mt19937_64 generator(g.seed);
  for (IrregularityChannel channel : kIrregularityChannels) {
    std::vector<double>& v = channels[static_cast<std::size_t>(channel)];
    v.assign(n, 0.0);
    for (int j = 0; j < band.count; ++j) {
      const double omega = band.low + (j + 0.5) * band.step;
      const double phase = 2.0 * kPi * unit_random(generator);
      const double amplitude = std::sqrt(2.0 * irregularity_density(g.spectrum, channel, omega) * band.step);
      if (amplitude == 0.0) continue;
      for (std::size_t i = 0; i < n; ++i) v[i] += amplitude * std::cos(omega * distances[i] + phase);
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (distances[i] < g.fade_in) v[i] *= 0.5 * (1.0 - std::cos(kPi * distances[i] / g.fade_in));
      if (!(std::fabs(v[i]) <= kMaxIrregularity))
        throw std::invalid_argument(std::string("irregularity generation: ") + irregularity_spectrum_name(g.spectrum) +
                                    " gives " + irregularity_channel_name(channel) + " = " + number_text(v[i]) +
                                    " m at s = " + number_text(distances[i]) + " m, beyond " +
                                    number_text(kMaxIrregularity) + " m: choose a narrower wavelength band or a "
                                    "better track");
    }
  }
  return TrackIrregularity(std::move(distances), std::move(channels));
}

double band_variance(const IrregularityGeneration& g, IrregularityChannel channel) {
  // Simpson's rule on 4000 intervals: the densities are smooth over the band.
  const double low = 2.0 * kPi / g.max_wavelength, high = 2.0 * kPi / g.min_wavelength;
  const int intervals = 4000;
  const double h = (high - low) / intervals;
  double sum = 0.0;
  for (int k = 0; k <= intervals; ++k) {
    const double w = (k == 0 || k == intervals) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    sum += w * irregularity_density(g.spectrum, channel, low + k * h);
  }
  return sum * h / 3.0;
}

}  // namespace wrc
