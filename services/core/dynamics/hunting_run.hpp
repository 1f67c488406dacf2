// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// One hunting run (docs/bifurcation.md): the wheelset on straight track at one speed, from a given
/// lateral state, integrated until its lateral oscillation has settled (a converged limit cycle,
/// an irregular motion whose envelope holds, or the centred state) or a time limit, and classified
/// by the last cycles of y and their envelope. A run judged a limit cycle at max_time without a
/// second judgement is reported as one.

#include <memory>
#include <string>
#include <vector>

#include "core/dynamics/contact_evaluator.hpp"
#include "core/dynamics/limit_cycle.hpp"
#include "core/dynamics/simulation.hpp"
#include "core/dynamics/wheelset_simulation.hpp"
#include "core/dynamics/wheelset_parameters.hpp"

namespace wrc {

/// How long a hunting run goes and how it is judged.
struct HuntingSettings {
  double settle_time = 2.0;        ///< simulated time before the first judgement [s], > 0
  /// The cycles are measured over the last window [s], > 0, <= settle_time; over the run's second
  /// half instead when the window holds fewer than 3 cycles and the half more.
  double window = 2.0;
  double check_period = 0.5;       ///< simulated time between judgements [s], > 0
  double max_time = 20.0;          ///< the run ends here whatever its state [s], >= settle_time
  double centred_amplitude = 1e-5; ///< amplitude of y below which the wheelset is centred [m], > 0
  /// |growth - 1| per cycle within which a cycle has converged [-], in (0, 1).
  double growth_tolerance = 0.01;
  /// Contact angle above which a wheel touches with its flange [rad], in (0, pi/2): S1002 on
  /// UIC60 has contact angles below 0.1 rad on the tread and 1.2 rad on the flange flank, so any
  /// threshold in between separates them.
  double flange_contact_angle = 0.5;
  /// @throws std::invalid_argument naming the first value out of range.
  void validate() const;
};

/// What a hunting run ended in.
enum class HuntingState {
  kCentred,     ///< the oscillation decayed below centred_amplitude
  kDecaying,    ///< still decaying at max_time (growth < 1 - tolerance)
  kLimitCycle,  ///< constant amplitude (growth within tolerance) at two successive judgements
  kGrowing,     ///< still growing at max_time (growth > 1 + tolerance)
  /// A bounded oscillation whose cycles differ (their growth outside the tolerance either way)
  /// while its envelope, the largest cycle of the last window, holds within the tolerance per
  /// period against the window before, at every judgement over a whole window (or at max_time):
  /// motion that is not one periodic cycle (quasi-periodic or chaotic; the Cooperrider bogie's in
  /// flange contact).
  kIrregular,
  kFailed,      ///< the run failed (message says why) before it settled
};

/// "centred", "decaying", "limit-cycle", "growing", "irregular", "failed".
const char* hunting_state_name(HuntingState state);

/// One hunting run's result.
struct HuntingRun {
  double speed = 0;               ///< V [m/s]
  InitialState start;             ///< where it started
  HuntingState state = HuntingState::kFailed;
  CycleMeasurement cycle;         ///< of y over the last window [m, s]
  double envelope = 0;            ///< the largest cycle's half peak-to-peak over the last window [m]
  /// The envelope's growth per period against the window before it [-]: (envelope / previous
  /// window's)^(period / window); 0 while not measurable (the run shorter than two windows, no
  /// cycle in either window).
  double envelope_growth = 0;
  double yaw_amplitude = 0;       ///< half peak-to-peak of the yaw angle's last cycle [rad]
  double largest_contact_angle = 0;  ///< of both wheels over the last window [rad]
  bool flange_contact = false;    ///< largest_contact_angle above the settings' threshold
  InitialState end;               ///< the lateral state at the end (y, yaw, rates, spin offset)
  double simulated_time = 0;      ///< [s]
  std::string message;            ///< the failure's reason (kFailed)
  /// A hunting oscillation that does not die out: a limit cycle, irregular or still growing.
  bool persists() const {
    return state == HuntingState::kLimitCycle || state == HuntingState::kGrowing || state == HuntingState::kIrregular;
  }
  /// The amplitude a diagram draws [m]: the envelope of an irregular motion, else the last cycle's.
  double amplitude() const { return state == HuntingState::kIrregular ? envelope : cycle.amplitude; }
};

/// The output samples a hunting run is judged by: the observed wheelset's lateral shift y [m],
/// yaw [rad] and the larger contact angle of its wheels [rad] at the times t [s].
struct HuntingSamples {
  std::vector<double> t, y, yaw, angle;
  /// Appends the output sample w.
  void add(const WheelsetSnapshot& w);
};

/// Judges a hunting run at time now [s] by its samples (docs/bifurcation.md, "One run"): sets
/// result's cycle (of y over the last settings.window, or over the run's second half when that
/// holds more cycles and the window fewer than 3), envelope and envelope growth, yaw amplitude,
/// largest contact angle, flange contact and state (never kFailed). Pure: no simulation.
void judge_hunting(const HuntingSamples& samples, double now, const HuntingSettings& settings, HuntingRun& result);

/// Starts simulation and advances it until the oscillation of samples (which its output fills)
/// has settled (judge_hunting() every check period from settle_time on) or its end time; sets
/// result's state, cycle, envelope, yaw amplitude, contact angle, flange contact, simulated time
/// and message (not start, end, speed).
/// The one loop of the lone wheelset's hunting run and a vehicle's. Returns false when the run
/// found no consistent initial state (result kFailed, the message says why).
bool follow_hunting(Simulation& simulation, const HuntingSamples& samples, const HuntingSettings& settings,
                    HuntingRun& result);

/// Runs the wheelset of base (its track, irregularities and initial state ignored: straight
/// track, start given) at speed [m/s] from start, with contact and the nominal rolling radius
/// nominal_radius [m], until settled or settings.max_time. The integrator's tolerances and step
/// limits are base's; its t_end and output period are set here (samples every 1 ms).
/// @throws std::invalid_argument naming an invalid value (parameters, speed, settings).
HuntingRun run_hunting(const RunSpec& base, double speed, const InitialState& start,
                       std::shared_ptr<ContactEvaluator> contact, double nominal_radius,
                       const HuntingSettings& settings);

}  // namespace wrc
