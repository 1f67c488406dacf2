// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Small RAII owners of SUNDIALS objects (context, serial vectors, IDA memory, dense matrix and
/// solver) and the one check of every SUNDIALS return flag.

#include <memory>
#include <string>

#include <ida/ida.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

namespace wrc {

/// Throws std::runtime_error "<function> failed with flag <flag>" when flag < 0.
void check_sundials(int flag, const char* function);

/// A SUNContext (freed last: declare it before everything made with it).
class SundialsContext {
 public:
  SundialsContext();
  ~SundialsContext();
  SundialsContext(const SundialsContext&) = delete;
  SundialsContext& operator=(const SundialsContext&) = delete;
  SUNContext get() const { return ctx_; }

 private:
  SUNContext ctx_ = nullptr;
};

/// A serial N_Vector of a given length.
class SerialVector {
 public:
  SerialVector(long length, SUNContext ctx);
  ~SerialVector();
  SerialVector(const SerialVector&) = delete;
  SerialVector& operator=(const SerialVector&) = delete;
  N_Vector get() const { return v_; }
  double* data() const { return N_VGetArrayPointer(v_); }
  long size() const { return length_; }

 private:
  N_Vector v_ = nullptr;
  long length_ = 0;
};

/// IDA's memory with its dense matrix and linear solver.
class IdaSolver {
 public:
  IdaSolver() = default;
  ~IdaSolver();
  IdaSolver(const IdaSolver&) = delete;
  IdaSolver& operator=(const IdaSolver&) = delete;
  /// IDACreate, IDAInit, the dense solver (SUNDenseMatrix, SUNLinSol_Dense, IDASetLinearSolver).
  void create(SUNContext ctx, IDAResFn residual, double t0, N_Vector y, N_Vector yp);
  void* mem() const { return mem_; }
  explicit operator bool() const { return mem_ != nullptr; }
  void reset();

 private:
  void* mem_ = nullptr;
  SUNMatrix matrix_ = nullptr;
  SUNLinearSolver solver_ = nullptr;
};

}  // namespace wrc
