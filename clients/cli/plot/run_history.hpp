// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A wheelset run's time history as `wrc run --history FILE.csv` writes it (header line
/// "t [s],y [m],...,s_right [m],...,normal_force_right [N],...,model [-]"; headers without the
/// " [unit]" of older files are read too), or from the wheelset states in an LCM log that
/// `wrc record` wrote during the run.

#include <map>
#include <string>
#include <vector>

namespace wrc::cli::plot {

/// The columns the run pictures draw, one entry per row [s, m, N].
struct RunHistory {
  std::vector<double> t;                   ///< time [s]
  std::vector<double> y;                   ///< lateral displacement of the wheelset [m]
  std::vector<double> yaw;                 ///< yaw from its track tangent, the angle of attack [rad] (NaN: not in the file)
  std::vector<double> s_right;             ///< right contact point, wheel profile coordinate [m]
  std::vector<double> normal_force_right;  ///< right normal force [N]
  std::vector<std::string> models;         ///< the contact models of the run, in order of appearance
  /// What engineers read off the run (docs/run-quantities.md), one entry per row; empty when the
  /// file has no such columns (a history written before they existed).
  struct Forces {
    std::vector<double> distance;           ///< distance travelled [m]
    std::vector<double> y_over_q_left;      ///< Y/Q of the left wheel [-]
    std::vector<double> y_over_q_right;     ///< Y/Q of the right wheel [-]
    std::vector<double> nadal_limit;        ///< Nadal's limit of Y/Q [-]
    std::vector<double> track_shift_force;  ///< sum Y of the axle [N]
    std::vector<double> prudhomme_limit;    ///< Prud'homme's limit of sum Y [N]
    std::vector<double> wear_number_left;   ///< T gamma of the left wheel [N]
    std::vector<double> wear_number_right;  ///< T gamma of the right wheel [N]
  } forces;
};

/// Reads a history file or an LCM log (the states of its first run), each wheelset's rows apart, by
/// its index (a vehicle run's `wheelset` column; the lone wheelset's run, or a file without the
/// column: 0 alone). Throws std::runtime_error naming the file and the line for a missing column, a
/// bad number, or no rows.
std::map<int, RunHistory> read_wheelset_histories(const std::string& path);
/// The first wheelset's history of read_wheelset_histories() (the lone wheelset's run: its only).
RunHistory read_run_history(const std::string& path);

}  // namespace wrc::cli::plot
