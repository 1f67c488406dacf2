// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The kinds of `wrc plot KIND`: each lives in its own plot/kind_<name>.cpp and registers itself,
/// like the subcommands (cli/command.hpp). The order of registration is the order of `--help`.

#include <string>
#include <vector>

namespace wrc::cli::plot {

/// One kind of picture: its name as typed, a one-line summary, and its entry point, which gets the
/// arguments after the kind and returns the exit code.
struct PlotKind {
  std::string name;
  std::string summary;
  int (*run)(const std::vector<std::string>& args);
  int order = 0;  ///< position in `wrc plot --help` (static initialisation order is unspecified)
};

/// Every registered kind, sorted by order.
std::vector<PlotKind> plot_kinds();

/// Registers a kind at static-initialisation time: `const PlotKindRegistrar registrar{{...}};`.
struct PlotKindRegistrar {
  explicit PlotKindRegistrar(PlotKind kind);
};

}  // namespace wrc::cli::plot
