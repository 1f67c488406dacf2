// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Tensor products of B-spline bases over up to four variables (y, roll, yaw and, as an option
/// for a non-prismatic rail, x), the basis evaluated once per configuration (TensorBasisPoint) and
/// contracted with the coefficients of every fitted quantity (TensorSplineSet).

#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "core/spline/bspline_basis.hpp"

namespace wrc {

/// Largest number of variables of a tensor product.
constexpr int kMaxTensorDimension = 4;
/// Largest number of non-zero tensor basis functions at one point: (kMaxSplineDegree + 1)^4.
constexpr int kMaxTensorTerms = 256;

/// Largest number of functions whose derivatives one TensorSplineSet::query computes.
constexpr int kMaxDerivativeFunctions = 4;

/// The compiled kernels of TensorSplineSet::query (defined in tensor_spline.cpp).
namespace spline_kernels {
/// The 1-D basis factors of one query (tensor_spline.cpp).
struct QueryFactors;
/// The type of every compiled query kernel: the coefficient row of the query's first term, the
/// terms' row offsets from it, the derivative functions' transposed coefficients at the first term
/// and their offsets, the factors, and the outputs of TensorSplineSet::query.
using QueryKernel = void (*)(const double* base, const std::ptrdiff_t* offsets, const double* const* transposed,
                             const std::ptrdiff_t* transposed_offsets, const QueryFactors& factors, int value_count,
                             double* values, int derivative_count, double* derivatives);
/// Largest number of 4-function blocks of values a compiled kernel computes.
constexpr int kMaxBlocks = 8;
/// One degree combination's kernels by the number of 4-function blocks of values (index 0 unused).
using KernelRow = std::array<QueryKernel, kMaxBlocks + 1>;
}  // namespace spline_kernels

/// How many derivatives TensorBasis::evaluate computes.
enum class SplineDerivatives { kValue = 0, kGradient = 1, kHessian = 2 };

/// The non-zero tensor basis functions at one point: coefficient index and weights for the value,
/// the gradient and the Hessian (upper triangle, row-major: (0,0), (0,1), .., (0,d-1), (1,1), ..).
/// Units: weights of derivatives carry 1 / (unit of the variable) per derivative.
/// The arrays are left uninitialised by construction (30 kB: zeroing them would cost more than
/// the evaluation); TensorBasis::evaluate fills the first `terms` entries of what it computes.
struct TensorBasisPoint {
  int terms = 0;                                          ///< number of non-zero basis functions
  int dimension = 0;                                      ///< variables of the tensor product
  SplineDerivatives derivatives = SplineDerivatives::kValue;  ///< what is filled in
  std::array<int, kMaxTensorTerms> index;                 ///< flat coefficient index of each term
  std::array<double, kMaxTensorTerms> value;              ///< basis value of each term
  /// d/dv_k of each term, k < dimension (filled for kGradient and kHessian).
  std::array<std::array<double, kMaxTensorTerms>, kMaxTensorDimension> gradient;
  /// d2/dv_k dv_l of each term, upper triangle (k <= l) in the order above (filled for kHessian).
  std::array<std::array<double, kMaxTensorTerms>, kMaxTensorDimension*(kMaxTensorDimension + 1) / 2> hessian;
};

/// Position of Hessian entry (k, l) in the upper-triangle order of TensorBasisPoint::hessian.
int hessian_slot(int k, int l, int dimension);

/// The tensor product of 1..kMaxTensorDimension univariate bases. Flat coefficient index:
/// row-major with the last variable fastest, index = ((i0 * n1 + i1) * n2 + i2) * n3 + i3.
class TensorBasis {
 public:
  /// @throws std::invalid_argument for no basis or more than kMaxTensorDimension.
  explicit TensorBasis(std::vector<BSplineBasis> bases);

  int dimension() const { return static_cast<int>(bases_.size()); }
  const BSplineBasis& basis(int k) const { return bases_[static_cast<size_t>(k)]; }
  const std::vector<BSplineBasis>& bases() const { return bases_; }
  /// Number of coefficients per function: the product of the basis sizes.
  int size() const { return size_; }
  /// True when every coordinate of point lies inside [lower, upper] of its basis.
  bool contains(const double* point) const;

  /// The non-zero basis functions at point (dimension() coordinates) with the derivatives asked for.
  void evaluate(const double* point, SplineDerivatives derivatives, TensorBasisPoint& out) const;

 private:
  std::vector<BSplineBasis> bases_;
  int size_ = 0;
};

/// M functions on one tensor basis (all fitted quantities of one wheel), coefficients stored
/// basis-index-major with the functions contiguous, so that one basis evaluation is contracted
/// with every function in one pass.
class TensorSplineSet {
 public:
  /// @param coefficients size() x M, column j the coefficients of function j (flat index above).
  /// @throws std::invalid_argument when the rows do not match basis.size() or M = 0.
  TensorSplineSet(TensorBasis basis, const Eigen::MatrixXd& coefficients);

  const TensorBasis& basis() const { return basis_; }
  int functions() const { return functions_; }
  /// Coefficient of basis function i for function j.
  double coefficient(int i, int j) const { return data_[static_cast<size_t>(i) * stride_ + j]; }
  /// size() x M matrix of the coefficients (the constructor's argument).
  Eigen::MatrixXd coefficients() const;

  /// Every function's value at the evaluated point: out[j], j < functions().
  void values(const TensorBasisPoint& point, double* out) const;
  /// Value, gradient (dimension entries) and Hessian (upper triangle, hessian_slot order) of
  /// function j; point must have been evaluated with kHessian (kGradient: hessian may be null).
  void derivatives(const TensorBasisPoint& point, int j, double& value, double* gradient, double* hessian) const;
  /// Gradient of every function: gradient[k * functions() + j] = d f_j / d v_k (point evaluated
  /// with kGradient or kHessian).
  void gradients(const TensorBasisPoint& point, double* gradient) const;

  /// What one query of a 3-D set needs, from one evaluation of the three 1-D bases at point:
  /// the values of functions 0..value_count-1 into values, and for functions 0..derivative_count-1
  /// (at most kMaxDerivativeFunctions) their value, gradient (3) and Hessian (6, the hessian_slot
  /// order) into derivatives[10 * n ..]. Degrees (3, 3, 3) and (3, 3, 2) with up to 32 functions
  /// run a compiled kernel (one pass over the terms for the values asked, in blocks of 4
  /// functions; each derivative function contracted one variable at a time from a transposed copy
  /// of its coefficients, the 4 y terms as vector lanes); other bases the general path. The cost
  /// grows with value_count and derivative_count: ask only for what is needed.
  /// @throws std::invalid_argument for a basis that is not 3-D or a count out of range.
  void query(const double* point, int value_count, double* values, int derivative_count, double* derivatives) const;
  /// True when query() with value_count values (0..functions()) runs a compiled kernel, false when
  /// it takes the general path (what the tests check of the spline model's query shape).
  bool query_is_compiled(int value_count) const;

 private:
  TensorBasis basis_;
  int functions_ = 0;
  int stride_ = 0;             // functions_ rounded up for aligned contraction
  std::vector<double> data_;   // [basis index][function]
  // query(): the kernel table's row for these degrees (null: the general path) and the largest
  // number of 4-function blocks of values it is used for (stride_ / 4, at most kMaxBlocks).
  const spline_kernels::KernelRow* kernels_ = nullptr;
  int kernel_blocks_ = 0;
  std::vector<std::ptrdiff_t> offsets_;  // query(): row offsets of the terms from the first term's row
  // query(): functions 0..transposed_count_-1 again, transposed (y index fastest), for their
  // derivatives, and the offsets of the query's (roll, yaw) terms in them.
  int transposed_count_ = 0;
  std::vector<double> transposed_;
  std::vector<std::ptrdiff_t> transposed_offsets_;
};

/// Samples for a weighted least-squares fit (the paper's equation (1) discretised):
/// minimise sum_i w_i (f_ij - s_j(x_i))^2 for every function j.
struct WeightedSamples {
  int dimension = 0;                ///< variables per sample point
  std::vector<double> points;       ///< sample i at points[i * dimension ..] [units of the variables]
  std::vector<double> weights;      ///< w_i >= 0 [-]
  Eigen::MatrixXd values;           ///< samples x M, f_ij [SI of function j]
  int count() const { return static_cast<int>(weights.size()); }
};

/// What the fit did.
struct FitStatistics {
  double seconds = 0;         ///< wall time of assembly and solve [s]
  int coefficients = 0;       ///< unknowns per function
  int samples = 0;            ///< samples used
  long nonzeros = 0;          ///< non-zeros of the normal-equation matrix
  double ridge = 0;           ///< regularisation added to the diagonal, relative to its mean [-]
};

/// Weighted least-squares fit of every function in samples on basis: the normal equations
/// B^T W B c = B^T W f assembled sparse (each sample touches at most (p+1)^d coefficients) and
/// solved once by Eigen's SimplicialLDLT for all right-hand sides. A relative ridge
/// (ridge * mean diagonal added to the diagonal, default 1e-12) keeps a basis function whose
/// support holds only zero-weight samples determined (its coefficient goes to ~0).
/// @throws std::invalid_argument for mismatched sizes, a negative or NaN weight, a NaN value, a
///         point outside the basis box, or a basis function with no sample in its support
///         (message names the function's index and its support); std::runtime_error when the
///         factorisation fails.
TensorSplineSet fit_tensor_spline(const TensorBasis& basis, const WeightedSamples& samples,
                                  FitStatistics* statistics = nullptr, double ridge = 1e-12);

}  // namespace wrc
