// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/sundials_support.hpp"

#include <stdexcept>

namespace wrc {

void check_sundials(int flag, const char* function) {
  if (flag < 0) throw std::runtime_error(std::string(function) + " failed with flag " + std::to_string(flag));
}

SundialsContext::SundialsContext() { check_sundials(SUNContext_Create(nullptr, &ctx_), "SUNContext_Create"); }

SundialsContext::~SundialsContext() {
  if (ctx_) SUNContext_Free(&ctx_);
}

SerialVector::SerialVector(long length, SUNContext ctx) : length_(length) {
  v_ = N_VNew_Serial(length, ctx);
  if (!v_) throw std::runtime_error("N_VNew_Serial failed for length " + std::to_string(length));
  N_VConst(0.0, v_);
}

SerialVector::~SerialVector() {
  if (v_) N_VDestroy(v_);
}

void IdaSolver::create(SUNContext ctx, IDAResFn residual, double t0, N_Vector y, N_Vector yp) {
  reset();
  mem_ = IDACreate(ctx);
  if (!mem_) throw std::runtime_error("IDACreate failed");
  check_sundials(IDAInit(mem_, residual, t0, y, yp), "IDAInit");
  const sunindextype n = N_VGetLength(y);
  matrix_ = SUNDenseMatrix(n, n, ctx);
  if (!matrix_) throw std::runtime_error("SUNDenseMatrix failed");
  solver_ = SUNLinSol_Dense(y, matrix_, ctx);
  if (!solver_) throw std::runtime_error("SUNLinSol_Dense failed");
  check_sundials(IDASetLinearSolver(mem_, solver_, matrix_), "IDASetLinearSolver");
}

void IdaSolver::reset() {
  if (mem_) IDAFree(&mem_);
  if (solver_) SUNLinSolFree(solver_);
  if (matrix_) SUNMatDestroy(matrix_);
  mem_ = nullptr;
  solver_ = nullptr;
  matrix_ = nullptr;
}

IdaSolver::~IdaSolver() { reset(); }

}  // namespace wrc
