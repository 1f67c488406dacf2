// SPDX-License-Identifier: Apache-2.0
// wrc plot KIND: the pictures of wrc (the paper's figures and the usual contact-geometry charts),
// drawn by gnuplot into PNG or SVG. Each kind lives in cli/plot/kind_<name>.cpp.

#include <algorithm>
#include <iostream>

#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/plot/plot_kind.hpp"

namespace wrc::cli {
namespace {

std::string plot_help() {
  std::string text =
      "usage: wrc plot KIND [options] [--out FILE]\n\n"
      "Draws a picture with gnuplot (Debian's gnuplot-nox): PNG or SVG by the extension of --out.\n"
      "Axes show the quantity and its unit; the title names profiles, track and pose.\n"
      "`wrc plot KIND --help` lists the options of a kind.\n\nkinds:\n";
  for (const auto& kind : plot::plot_kinds()) {
    text += "  " + kind.name + std::string(kind.name.size() < 14 ? 14 - kind.name.size() : 1, ' ') + kind.summary + "\n";
  }
  return text;
}

int run_plot(const std::vector<std::string>& args) {
  if (args.empty() || args[0] == "--help" || args[0] == "-h") {
    std::cout << plot_help();
    return args.empty() ? 2 : 0;
  }
  const auto kinds = plot::plot_kinds();
  const auto kind = std::find_if(kinds.begin(), kinds.end(), [&](const auto& k) { return k.name == args[0]; });
  if (kind == kinds.end()) {
    std::string names;
    for (const auto& k : kinds) names += (names.empty() ? "" : ", ") + k.name;
    throw UsageError("unknown kind '" + args[0] + "' (kinds: " + names + ")");
  }
  return kind->run(std::vector<std::string>(args.begin() + 1, args.end()));
}

const CommandRegistrar registrar{{"plot", "pictures of the contact geometry and of runs (wrc plot --help lists the kinds)", run_plot}};

}  // namespace
}  // namespace wrc::cli
