// SPDX-License-Identifier: Apache-2.0
// wrc run: one wheelset run on wrc-dynamicsd (started, with the contact services it needs, when
// none runs), with a progress bar, the state history as CSV and the summary as JSON
// (cli/run_options.hpp: options -> request; cli/run_session.hpp: the run itself).
#include <iostream>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/output_paths.hpp"
#include "cli/run_options.hpp"
#include "cli/run_session.hpp"
#include "core/geometry/geometry_spec.hpp"

namespace wrc::cli {
namespace {

int run_run(const std::vector<std::string>& args) {
  const Options o("run", "--model M --summary FILE.json [options]", run_option_specs(), args);
  if (o.help_requested()) {
    std::cout << o.help()
              << "\nRuns the rigid wheelset on straight track or a --track layout (wrc-dynamicsd, SUNDIALS IDA) with\n"
                 "contact model M, from the paper's benchmark parameters (or --params FILE; the options override\n"
                 "both), and writes the summary (final state, wall time, integrator and contact counters, swaps).\n"
                 "With --track and without --lateral-force the parameters' lateral load (the benchmark's -20 kN, or\n"
                 "a --params file's) is set to 0, and the first line of output says so: on a curve it would add to\n"
                 "the centrifugal force. --lateral-force F on the command line (0 or not) keeps F. Services that\n"
                 "are not running are started for the run and stopped after it. `wrc swap M` from another\n"
                 "terminal swaps the model at the next step; --swap-at T:M reproduces such a swap.\n";
    return 0;
  }
  protocol::RunRequest request = run_request_from(o, std::cout);
  // Before any service starts: the outputs can be written and the profiles and track make a
  // geometry (built here as `wrc query` builds it), so that a mistake is one line naming the file,
  // not a log of services or a run that fails at its end.
  check_output_path(o.required_text("--summary"), "--summary");
  if (o.has("--history")) check_output_path(o.text("--history"), "--history");
  make_geometry(request.geometry);
  RunSession session(o, std::move(request));
  session.start_services();
  session.run();
  return session.finish();
}

const CommandRegistrar registrar{
    {"run", "a wheelset run on wrc-dynamicsd (services started when none run); summary as JSON", run_run}};

}  // namespace
}  // namespace wrc::cli
