// SPDX-License-Identifier: Apache-2.0
// wrc creep: creep forces on one Hertzian contact patch by FASTSIM or Kalker's linear theory.
// Prints the forces on the wheel in SI units: CSV header `fx,fy,mz` and one row, or a text block.

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/grid_option.hpp"
#include "cli/options.hpp"
#include "core/contact/fastsim.hpp"
#include "core/contact/linear_creep.hpp"

namespace wrc::cli {
namespace {

// A required number that must be strictly positive.
double positive(const Options& o, const std::string& name) {
  const double v = o.required_number(name);
  if (!(v > 0.0)) throw UsageError(name + ": " + o.text(name) + " must be positive");
  return v;
}

int run_creep(const std::vector<std::string>& args) {
  const Options o("creep",
                  "--a A --b B --normal-force N [--mu MU] [--shear-modulus G] [--poisson NU] "
                  "[--xi-x X] [--xi-y Y] [--spin S] [--model fastsim|linear] [--grid MxN] [--format csv|text]\n"
                  "Creep forces on the wheel for one Hertzian patch (x rolling direction, y lateral, moment about "
                  "the normal).",
                  {{"--a", true, "semi-axis in the rolling direction [m]", ""},
                   {"--b", true, "semi-axis in the lateral direction [m]", ""},
                   {"--normal-force", true, "normal force N [N]", ""},
                   {"--mu", true, "friction coefficient [-]", "0.3"},
                   {"--shear-modulus", true, "shear modulus G [Pa]", "8.2e10"},
                   {"--poisson", true, "Poisson's ratio [-], 0..0.5", "0.28"},
                   {"--xi-x", true, "longitudinal creepage [-]", "0"},
                   {"--xi-y", true, "lateral creepage [-]", "0"},
                   {"--spin", true, "spin creepage [1/m]", "0"},
                   {"--model", true, "fastsim or linear (Kalker's linear theory, unsaturated)", "fastsim"},
                   grid_option_spec(),
                   {"--format", true, "csv or text", "csv"}},
                  args);
  if (o.help_requested()) {
    std::cout << o.help();
    return 0;
  }
  CreepPatch patch;
  patch.a = positive(o, "--a");
  patch.b = positive(o, "--b");
  patch.normal_force = o.required_number("--normal-force");
  if (patch.normal_force < 0.0) throw UsageError("--normal-force: " + o.text("--normal-force") + " must be >= 0");
  patch.friction = o.number("--mu");
  if (patch.friction < 0.0) throw UsageError("--mu: " + o.text("--mu") + " must be >= 0");
  patch.shear_modulus = o.number("--shear-modulus");
  if (!(patch.shear_modulus > 0.0)) {
    throw UsageError("--shear-modulus: " + o.text("--shear-modulus") + " must be positive");
  }
  patch.poisson = o.number("--poisson");
  if (patch.poisson < 0.0 || patch.poisson > 0.5) {
    throw UsageError("--poisson: " + o.text("--poisson") + " must be in [0, 0.5]");
  }
  const Creepages creep{o.number("--xi-x"), o.number("--xi-y"), o.number("--spin")};
  const std::string model = o.choice("--model", {"fastsim", "linear"});
  const std::string format = o.choice("--format", {"csv", "text"});
  const FastsimGrid grid = grid_option(o, kMinFastsimCount, kMaxFastsimCount);

  const CreepForces f = model == "linear" ? linear_creep_forces(patch, creep)
                                          : Fastsim(grid.elements_per_strip, grid.strips).solve(patch, creep);
  char line[256];
  if (format == "csv") {
    std::snprintf(line, sizeof line, "fx,fy,mz\n%.10g,%.10g,%.10g\n", f.fx + 0.0, f.fy + 0.0, f.mz + 0.0);
  } else {
    std::snprintf(line, sizeof line, "fx = %.6g N\nfy = %.6g N\nmz = %.6g N m\nslip fraction = %.4g\n", f.fx + 0.0,
                  f.fy + 0.0, f.mz + 0.0, f.slip_fraction);
  }
  std::cout << line;
  return 0;
}

const CommandRegistrar registrar{{"creep", "creep forces on one Hertzian patch (FASTSIM or linear theory)", run_creep}};

}  // namespace
}  // namespace wrc::cli
