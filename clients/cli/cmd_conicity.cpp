// SPDX-License-Identifier: Apache-2.0
// wrc conicity: equivalent conicity by harmonic linearisation at one or more amplitudes.

#include <cstdio>
#include <iostream>
#include <sstream>

#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/profile_options.hpp"
#include "core/geometry/conicity.hpp"

namespace wrc::cli {
namespace {

int run_conicity(const std::vector<std::string>& args) {
  auto specs = profile_option_specs();
  specs.push_back({"--amplitude", true, "lateral amplitude(s) [m], comma-separated, each in (0, 0.02]", ""});
  specs.push_back({"--method", true, "harmonic (harmonic linearisation of delta_r)", "harmonic"});
  specs.push_back({"--samples", true, "points on the period for the Fourier integral", "512", NumberRange{8, 100000}});
  specs.push_back({"--format", true, "csv or table", "csv"});
  Options opt("conicity", "--amplitude A[,A2,...] [--method harmonic] [options]", specs, args);
  if (opt.help_requested()) {
    std::cout << opt.help()
              << "\nlambda_e(A) = 1/(2 pi A) * integral over one period of delta_r(A sin t) sin t dt, with delta_r from\n"
                 "the exact rigid-wheelset geometry (contact-point jumps included). Output: amplitude,conicity.\n";
    return 0;
  }
  opt.choice("--method", {"harmonic"});
  const int samples = opt.integer("--samples");
  const bool csv = opt.choice("--format", {"csv", "table"}) == "csv";
  std::vector<double> amplitudes;
  std::stringstream list(opt.required_text("--amplitude"));
  for (std::string item; std::getline(list, item, ',');) {
    const double a = parse_finite(item, "--amplitude");
    if (!(a > 0 && a <= 0.02)) throw UsageError("--amplitude: " + item + " is outside (0, 0.02] m");
    amplitudes.push_back(a);
  }
  const WheelsetGeometry geometry = geometry_from_options(opt);
  const RigidWheelsetSolver solver(geometry);
  std::printf(csv ? "amplitude,conicity\n" : "%12s %12s\n", "A[mm]", "conicity");
  for (double a : amplitudes) {
    const double lambda = equivalent_conicity(solver, a, samples);
    if (csv) std::printf("%.9g,%.9g\n", a, lambda);
    else std::printf("%12.4f %12.5f\n", a * 1e3, lambda);
  }
  return 0;
}

const CommandRegistrar registrar{{"conicity", "equivalent conicity (harmonic linearisation)", run_conicity}};

}  // namespace
}  // namespace wrc::cli
