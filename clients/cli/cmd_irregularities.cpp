// SPDX-License-Identifier: Apache-2.0
// wrc irregularities: a track-irregularity file (CSV, docs/track.md) generated from a published
// spectrum (ERRI low/high, FRA classes 1-6), for `wrc run --irregularities` and
// `wrc plot irregularities`.

#include <cstdint>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/options.hpp"
#include "core/numerics/number_text.hpp"
#include "core/track/irregularity_spectrum.hpp"
#include "core/track/track_irregularity_file.hpp"

namespace wrc::cli {
namespace {

std::vector<std::string> spectrum_names() {
  std::vector<std::string> names;
  for (IrregularitySpectrum s : irregularity_spectra()) names.push_back(irregularity_spectrum_name(s));
  return names;
}

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& w : words) text += (text.empty() ? "" : ", ") + w;
  return text;
}

int run_irregularities(const std::vector<std::string>& args) {
  const IrregularityGeneration defaults;
  const std::vector<OptionSpec> specs{
      {"--spectrum", true, "published spectrum: " + joined(spectrum_names()), "erri-low"},
      {"--length", true, "length of track from s = 0 [m]", number_text(defaults.length), NumberRange{0.0, 1e7}},
      {"--spacing", true, "distance of the samples [m]", number_text(defaults.spacing), NumberRange{0.0, 1e3}},
      {"--wavelengths", true, "wavelength band MIN:MAX [m]",
       number_text(defaults.min_wavelength) + ":" + number_text(defaults.max_wavelength)},
      {"--seed", true, "seed of the random phases (the same seed, the same track)", "1"},
      {"--fade-in", true, "distance over which the channels rise from 0 [m]", number_text(defaults.fade_in),
          NumberRange{0.0, 1e7}},
      {"--out", true, "write the CSV here (default: standard output)", ""},
  };
  Options opt("irregularities", "[--spectrum erri-low] [--length L] [--wavelengths 3:150] [--seed N] [--out FILE.csv]",
              specs, args);
  if (opt.help_requested()) {
    std::cout << opt.help()
              << "\nEach channel (alignment, vertical_level, cross_level, gauge) is a sum of cosines with random\n"
                 "phases whose amplitudes follow the spectrum's one-sided density over the band; the ERRI spectra\n"
                 "define no gauge (0). Sources and formulas: docs/track.md. Output columns, in metres:\n"
                 "s [m],alignment [m],vertical_level [m],cross_level [m],gauge [m].\n";
    return 0;
  }
  IrregularityGeneration g;
  g.spectrum = parse_irregularity_spectrum(opt.choice("--spectrum", spectrum_names()));
  g.length = opt.number("--length");
  g.spacing = opt.number("--spacing");
  g.fade_in = opt.number("--fade-in");
  const std::string band = opt.text("--wavelengths", number_text(defaults.min_wavelength) + ":" +
                                                         number_text(defaults.max_wavelength));
  const std::size_t colon = band.find(':');
  if (colon == std::string::npos) throw UsageError("--wavelengths: " + band + " is not MIN:MAX");
  g.min_wavelength = parse_finite(band.substr(0, colon), "--wavelengths");
  g.max_wavelength = parse_finite(band.substr(colon + 1), "--wavelengths");
  const std::string seed = opt.text("--seed", "1");
  try {
    std::size_t used = 0;
    g.seed = std::stoull(seed, &used);
    if (used != seed.size() || seed[0] == '-') throw std::invalid_argument(seed);
  } catch (const std::exception&) {
    throw UsageError("--seed: " + seed + " is not a whole number >= 0");
  }
  try {
    g.validate();
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const TrackIrregularity t = generate_irregularity(g);
  const std::string comment = "wrc irregularities --spectrum " + std::string(irregularity_spectrum_name(g.spectrum)) +
                              " --length " + number_text(g.length) + " --spacing " + number_text(g.spacing) +
                              " --wavelengths " + number_text(g.min_wavelength) + ":" +
                              number_text(g.max_wavelength) + " --seed " + seed + " --fade-in " +
                              number_text(g.fade_in);
  const std::string text = track_irregularity_text(t, comment);
  if (opt.has("--out")) {
    std::ofstream out(opt.text("--out"));
    out << text;
    if (!out) throw std::runtime_error(opt.text("--out") + ": cannot write the irregularities");
  } else {
    std::cout << text;
  }
  std::cerr << "irregularities: " << t.distances().size() << " samples over " << number_text(g.length) << " m";
  for (IrregularityChannel c : kIrregularityChannels)
    std::cerr << ", " << irregularity_channel_name(c) << " rms " << number_text(t.rms(c) * 1e3, 3) << " mm";
  std::cerr << "\n";
  return 0;
}

const CommandRegistrar registrar{
    {"irregularities", "track irregularities from a published spectrum (CSV for wrc run --irregularities)",
     run_irregularities}};

}  // namespace
}  // namespace wrc::cli
