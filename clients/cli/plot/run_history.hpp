#pragma once
/// @file
/// A wheelset run's time history as `wrc run --history FILE.csv` writes it (header line
/// t,y,z,roll,yaw,...,s_left,s_right,...,normal_force_left,normal_force_right,model), or from the
/// wheelset states in an LCM log that `wrc record` wrote during the run.

#include <string>
#include <vector>

namespace wrc::cli::plot {

/// The columns the run pictures draw, one entry per row [s, m, N].
struct RunHistory {
  std::vector<double> t;                   ///< time [s]
  std::vector<double> y;                   ///< lateral displacement of the wheelset [m]
  std::vector<double> s_right;             ///< right contact point, wheel profile coordinate [m]
  std::vector<double> normal_force_right;  ///< right normal force [N]
  std::vector<std::string> models;         ///< the contact models of the run, in order of appearance
};

/// Reads a history file or an LCM log (the states of its first run); throws std::runtime_error
/// naming the file and the line for a missing column, a bad number, or no rows.
RunHistory read_run_history(const std::string& path);

}  // namespace wrc::cli::plot
