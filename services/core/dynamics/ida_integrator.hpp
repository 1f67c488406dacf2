// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The driver of SUNDIALS IDA for one DAE F(t, y, y') = 0: it owns the context, the vectors, IDA's
/// memory and its dense solver, calls the system through C trampolines, takes one step at a time
/// and restarts a segment from new values. Nothing of SUNDIALS shows here: the system sees plain
/// arrays and a column-major view of the iteration matrix.

#include <memory>
#include <optional>
#include <vector>

#include "core/dynamics/run_counters.hpp"

namespace wrc {

/// A dense n x n matrix stored column by column (IDA's dense matrix), entry (i, k) at
/// data[k * rows + i].
struct DenseMatrixView {
  double* data = nullptr;
  long rows = 0;
  double& operator()(long i, long k) const { return data[k * rows + i]; }
};

/// What IDA integrates. Each function returns 0 on success, > 0 for a recoverable failure (IDA
/// retries with a smaller step), < 0 for one that ends the step.
class DaeSystem {
 public:
  virtual ~DaeSystem() = default;
  /// F(t, y, y') into r.
  virtual int residual(double t, const double* y, const double* yp, double* r) = 0;
  /// The iteration matrix dF/dy + cj dF/dy' at (t, y, y'), with r = F(t, y, y').
  virtual int jacobian(double t, double cj, const double* y, const double* yp, const double* r,
                       DenseMatrixView jac) = 0;
  /// The event functions at (t, y) into g (one per IdaSegment::root_direction).
  virtual int roots(double t, const double* y, double* g) = 0;
  /// IDA's error or warning text (IDA prints nothing itself).
  virtual void message(const char* function, const char* text) = 0;
};

/// How a segment is integrated.
struct IdaSegment {
  double relative_tolerance = 0;          ///< [-]
  std::vector<double> absolute_tolerance; ///< per unknown [unit of the unknown]
  std::vector<double> differential;       ///< per unknown: 1 differential, 0 algebraic [-]
  double max_step = 0;                    ///< [s]
  /// Relative change of cj beyond which the Newton matrix is rebuilt [-].
  double newton_matrix_cj_change = 0;
  /// Index 2 (rigid contact): the algebraic unknowns left out of the error test, at most
  /// max_newton_iterations corrector iterations, and the event functions (one per entry of
  /// root_direction).
  bool index2 = false;
  int max_newton_iterations = 0;  ///< [-]
  /// Per event function: -1 an event only where it falls through 0, +1 where it rises, 0 both [-].
  std::vector<int> root_direction;
};

/// How one step ended.
struct IdaStep {
  int flag = 0;          ///< IDASolve's return flag (< 0: failure)
  double t = 0;          ///< time reached [s]
  bool root = false;     ///< at an event
  bool stop_time = false;  ///< at the stop time
  bool convergence_failure = false;  ///< the corrector failed at every step size
};

class IdaIntegrator {
 public:
  struct Impl;  // IDA's memory and vectors (the C callbacks reach the system through it)

  /// @param system is called for every residual, Jacobian and event function; it must outlive
  ///        the integrator.
  explicit IdaIntegrator(DaeSystem& system);
  ~IdaIntegrator();
  IdaIntegrator(const IdaIntegrator&) = delete;
  IdaIntegrator& operator=(const IdaIntegrator&) = delete;

  /// Whether a segment was begun.
  bool started() const;
  /// A segment from the consistent (y, y') at time t [s]: with as many unknowns as before, IDA
  /// re-initialised (the settings of the first such segment stay); otherwise new vectors and a new
  /// IDA set up with settings.
  void begin(double t, const std::vector<double>& y, const std::vector<double>& yp, const IdaSegment& settings);
  /// One step towards t_stop [s], which it does not pass.
  IdaStep step(double t_stop);
  /// Called from DaeSystem::residual: whether IDA will build a new Newton matrix (call
  /// DaeSystem::jacobian) at the state of this residual right after it, judged as IDA judges it:
  /// the first matrix of a segment, or cj moved by more than IdaSegment::newton_matrix_cj_change
  /// since the last matrix. A forecast only (a corrector that fails to converge asks for a matrix
  /// nobody forecast), so the system may fetch ahead what the Jacobian will need, never decide
  /// anything by it.
  bool newton_matrix_expected() const;
  /// Whether a step with coefficient cj [1/s] would build a new Newton matrix (the same rule).
  bool newton_matrix_expected(double cj) const;
  /// IDA's current time: the time of the last step's state while IDA evaluates the event functions
  /// there [s].
  double current_time() const;
  /// Where IDA's next step will ask its first residual, as IDA will compute it (after a step,
  /// from IDA's divided differences and its next step size and order): t [s] and the predicted
  /// state. Empty before the first step and where the stop time ends the run. A forecast: a
  /// failed error test or corrector changes the step, so it may only be fetched ahead, never used
  /// as the residual's state.
  struct NextStep {
    double t = 0;           ///< [s]
    std::vector<double> y;  ///< the predicted state
    double cj = 0;          ///< the step's coefficient cj [1/s]
  };
  std::optional<NextStep> next_step() const;
  /// Which event functions found a root at the last step (one flag per event function).
  std::vector<int> root_info(int root_count) const;
  /// IDA's counters of this segment (steps, evaluations, failures, last order and step).
  RunCounters counters() const;
  /// The state after the last step (or at the segment's start).
  std::vector<double> state() const;
  const double* state_data() const;
  /// The derivative y' after the last step.
  const double* derivative_data() const;
  /// The state at t [s] within the last step: IDA's interpolation, and at the time of the state
  /// itself exactly that state.
  std::vector<double> state_at(double t);

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace wrc
