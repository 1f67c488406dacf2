// SPDX-License-Identifier: Apache-2.0
/// @file
/// Tensor-product B-spline evaluation, contraction with many functions' coefficients, and the
/// weighted least-squares fit by sparse normal equations (Eigen SimplicialLDLT).

#include "core/spline/tensor_spline.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstddef>
#include <cstring>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "core/numerics/simd_clones.hpp"

namespace wrc {
namespace {

// out[j] = sum_t weight[t] * row_t[j] for the W functions j0 .. j0 + W - 1 (row_t = coefficient row
// of term t): terms outer, functions inner, the W accumulators in registers (W compile-time, a
// multiple of 4 dividing into SSE/AVX registers); writes the first `count` <= W of them.
template <int W>
void contract_block(const double* data, int stride, int j0, int count, const TensorBasisPoint& point,
                    const double* weight, double* out) {
  double acc[W] = {};
  for (int t = 0; t < point.terms; ++t) {
    const double w = weight[t];
    const double* row = data + static_cast<size_t>(point.index[static_cast<size_t>(t)]) * stride + j0;
    for (int j = 0; j < W; ++j) acc[j] += w * row[j];
  }
  for (int j = 0; j < count; ++j) out[j0 + j] = acc[j];
}

// out[j] = sum_t weight[t] * data[index[t] * stride + j], j < functions (<= the functions stored),
// in blocks of 8 functions and a last one of 4 (stride is a multiple of 4 and the padding columns
// of data are zero). Measured
// (SSE2): blocks of 8 beat one pass over 20 or 12 + 8, whose wider unrolls the compiler spills.
// Compiled twice (runtime dispatch): for x86-64-v3 (AVX2, FMA) where the processor has it, and
// for the baseline, so that the binary runs anywhere and the Release flags stay the default.
WRC_SIMD_CLONES
void contract(const std::vector<double>& data, int stride, int functions, const TensorBasisPoint& point,
              const double* weight, double* out) {
  const int width = (functions + 3) / 4 * 4;  // <= stride; the padding columns of data are zero
  int j0 = 0;
  for (; j0 + 8 <= width; j0 += 8) contract_block<8>(data.data(), stride, j0, std::min(8, functions - j0), point, weight, out);
  if (j0 < width) contract_block<4>(data.data(), stride, j0, functions - j0, point, weight, out);
}

// dst[t * Q + a] = src[t] * f[a], t < terms: the tensor product of a term array with the Q 1-D
// factors of the next variable. dst may be src (in place): backwards, each src[t] is read before
// the block t * Q .. t * Q + Q - 1 (>= t) is written, and blocks above t are already consumed.
template <int Q>
void outer(const double* src, int terms, const double* f, double* dst) {
  double g[Q];
  for (int a = 0; a < Q; ++a) g[a] = f[a];
  for (int t = terms - 1; t >= 0; --t) {
    const double v = src[t];
    for (int a = 0; a < Q; ++a) dst[t * Q + a] = v * g[a];
  }
}

// Multiplies the tensor product of variables 0..k-1 (terms entries, D the derivative order filled)
// by the Q = degree + 1 factors of variable k: new arrays (d/dv_k, d2/dv_l dv_k) first, from the
// old ones, then the old ones in place; the index becomes index * size + first + a.
template <int D, int Q>
void expand(int k, int dimension, int first, int size, const double* b, const double* d1, const double* d2,
            int terms, TensorBasisPoint& out) {
  auto hess = [&out, dimension](int l, int n) { return out.hessian[static_cast<size_t>(hessian_slot(l, n, dimension))].data(); };
  auto grad = [&out](int l) { return out.gradient[static_cast<size_t>(l)].data(); };
  double* value = out.value.data();
  if (D >= 2) {
    outer<Q>(value, terms, d2, hess(k, k));
    for (int l = 0; l < k; ++l) outer<Q>(grad(l), terms, d1, hess(l, k));
    for (int l = 0; l < k; ++l)
      for (int n = l; n < k; ++n) outer<Q>(hess(l, n), terms, b, hess(l, n));
  }
  if (D >= 1) {
    outer<Q>(value, terms, d1, grad(k));
    for (int l = 0; l < k; ++l) outer<Q>(grad(l), terms, b, grad(l));
  }
  outer<Q>(value, terms, b, value);
  int* index = out.index.data();
  for (int t = terms - 1; t >= 0; --t) {
    const int base = index[t] * size + first;
    for (int a = 0; a < Q; ++a) index[t * Q + a] = base + a;
  }
}

template <int D>
void evaluate_tensor(const std::vector<BSplineBasis>& bases, const double* point, TensorBasisPoint& out) {
  const int dimension = static_cast<int>(bases.size());
  int terms = 1;
  out.index[0] = 0;
  out.value[0] = 1.0;
  for (int k = 0; k < dimension; ++k) {
    const BSplineBasis& basis = bases[static_cast<size_t>(k)];
    double b[kMaxSplineDegree + 1], d1[kMaxSplineDegree + 1], d2[kMaxSplineDegree + 1];
    const int first = basis.evaluate(point[k], b, D >= 1 ? d1 : nullptr, D >= 2 ? d2 : nullptr);
    const int size = basis.size();
    switch (basis.degree()) {
      case 0: expand<D, 1>(k, dimension, first, size, b, d1, d2, terms, out); break;
      case 1: expand<D, 2>(k, dimension, first, size, b, d1, d2, terms, out); break;
      case 2: expand<D, 3>(k, dimension, first, size, b, d1, d2, terms, out); break;
      default: expand<D, 4>(k, dimension, first, size, b, d1, d2, terms, out); break;
    }
    terms *= basis.degree() + 1;
  }
  out.terms = terms;
  out.dimension = dimension;
  out.derivatives = static_cast<SplineDerivatives>(D);
}

[[noreturn]] void fit_error(const std::string& message) {
  throw std::invalid_argument("fit_tensor_spline: " + message);
}

// Validates the samples against the basis (sizes, weights, values, the box); throws naming the
// offending sample and value.
void validate_samples(const TensorBasis& basis, const WeightedSamples& samples) {
  const int d = basis.dimension();
  const int n = samples.count();
  std::ostringstream msg;
  if (samples.dimension != d) {
    msg << "samples have dimension " << samples.dimension << ", the basis " << d;
    fit_error(msg.str());
  }
  if (samples.points.size() != static_cast<size_t>(n) * static_cast<size_t>(d)) {
    msg << "points hold " << samples.points.size() << " values, expected count " << n << " x dimension " << d;
    fit_error(msg.str());
  }
  if (samples.values.rows() != n) {
    msg << "values have " << samples.values.rows() << " rows, expected the sample count " << n;
    fit_error(msg.str());
  }
  if (samples.values.cols() == 0) fit_error("values have no column (no function to fit)");
  for (int i = 0; i < n; ++i) {
    const double w = samples.weights[static_cast<size_t>(i)];
    if (!(w >= 0.0) || !std::isfinite(w)) {
      msg << "weight of sample " << i << " = " << w << " must be non-negative and finite";
      fit_error(msg.str());
    }
    for (int k = 0; k < d; ++k) {
      const BSplineBasis& b = basis.basis(k);
      const double x = samples.points[static_cast<size_t>(i) * d + k];
      const double slack = 1e-12 * (b.upper() - b.lower());
      if (!(x >= b.lower() - slack && x <= b.upper() + slack)) {
        msg << "sample " << i << " variable " << k << " = " << x << " is outside the basis range [" << b.lower()
            << ", " << b.upper() << "]";
        fit_error(msg.str());
      }
    }
  }
  for (Eigen::Index j = 0; j < samples.values.cols(); ++j)
    for (Eigen::Index i = 0; i < n; ++i)
      if (!std::isfinite(samples.values(i, j))) {
        msg << "value of sample " << i << " function " << j << " = " << samples.values(i, j) << " is not finite";
        fit_error(msg.str());
      }
}

// Per-variable indices of flat coefficient index i (row-major, last variable fastest).
std::array<int, kMaxTensorDimension> unflatten(const TensorBasis& basis, int i) {
  std::array<int, kMaxTensorDimension> idx{};
  for (int k = basis.dimension() - 1; k >= 0; --k) {
    const int n = basis.basis(k).size();
    idx[static_cast<size_t>(k)] = i % n;
    i /= n;
  }
  return idx;
}

[[noreturn]] void uncovered_error(const TensorBasis& basis, int i) {
  const auto idx = unflatten(basis, i);
  std::ostringstream msg;
  msg << "basis function " << i << " (indices (";
  for (int k = 0; k < basis.dimension(); ++k) msg << (k ? ", " : "") << idx[static_cast<size_t>(k)];
  msg << ")) has no sample in its support";
  for (int k = 0; k < basis.dimension(); ++k) {
    // Support of N_j on clamped knots: [b_max(j-p,0), b_min(j+1,m)].
    const BSplineBasis& b = basis.basis(k);
    const int j = idx[static_cast<size_t>(k)];
    const auto& bp = b.breakpoints();
    msg << (k ? " x " : " ") << "[" << bp[static_cast<size_t>(std::max(j - b.degree(), 0))] << ", "
        << bp[static_cast<size_t>(std::min(j + 1, b.intervals()))] << "]";
  }
  fit_error(msg.str());
}

// Symmetric normal matrix B^T W B stored by column j (the smaller flat index) with one slot per
// coefficient-index offset delta = i - j that is lexicographically >= 0 and within the band
// |delta_k| <= p_k: slot(delta) = sum_k (delta_k + p_k) w_k - centre, w_k the strides of the
// (2p_k + 1)-box. A pair of terms s <= t of one sample (row-major, so index[s] <= index[t]) lands in
// slot local[t] - local[s], local[t] = sum_k a_k w_k for the term's local multi-index a: a direct
// address, no search, and each sample's (p+1)^d x (p+1)^d block accumulated in O(1) per pair.
class BandedNormalMatrix {
 public:
  explicit BandedNormalMatrix(const TensorBasis& basis) : basis_(basis) {
    const int d = basis.dimension();
    int box = 1;
    centre_ = 0;
    for (int k = d - 1; k >= 0; --k) {
      const int p = basis.basis(k).degree();
      box_stride_[static_cast<size_t>(k)] = box;
      centre_ += p * box;
      box *= 2 * p + 1;
    }
    slots_ = box - centre_;  // offsets lexicographically >= 0, centre included
    // Local offset of each term position of an evaluated point (the same for every sample).
    int terms = 1;
    local_[0] = 0;
    for (int k = 0; k < d; ++k) {
      const int q = basis.basis(k).degree() + 1;
      for (int t = terms - 1; t >= 0; --t)
        for (int a = q - 1; a >= 0; --a) local_[static_cast<size_t>(t * q + a)] = local_[static_cast<size_t>(t)] + a * box_stride_[static_cast<size_t>(k)];
      terms *= q;
    }
    entries_.assign(static_cast<size_t>(basis.size()) * static_cast<size_t>(slots_), 0.0);
  }

  // Adds w * value value^T of one evaluated sample point (lower triangle).
  void add(const TensorBasisPoint& point, double w) {
    for (int s = 0; s < point.terms; ++s) {
      const size_t ss = static_cast<size_t>(s);
      const double ws = w * point.value[ss];
      // Column index[s]; the term t lands at slot local_[t] - local_[s] >= 0.
      const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(point.index[ss]) * slots_ - local_[ss];
      for (int t = s; t < point.terms; ++t) {
        const size_t ts = static_cast<size_t>(t);
        entries_[static_cast<size_t>(base + local_[ts])] += ws * point.value[ts];
      }
    }
  }

  // Lower triangle as an Eigen sparse matrix, ridge * (mean diagonal) added to the diagonal;
  // full_nonzeros receives the non-zeros of the full symmetric matrix.
  Eigen::SparseMatrix<double> lower(double ridge, long& full_nonzeros) const {
    const int n = basis_.size();
    double trace = 0.0;
    for (int j = 0; j < n; ++j) trace += entries_[static_cast<size_t>(j) * slots_];
    const double shift = ridge * trace / n;
    const int d = basis_.dimension();
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(static_cast<size_t>(n) * static_cast<size_t>(slots_));
    for (int j = 0; j < n; ++j) {
      const auto jdx = unflatten(basis_, j);
      for (int slot = 0; slot < slots_; ++slot) {
        // Offset delta of this slot and the row index j + delta, skipped when outside the basis.
        int rest = slot + centre_, row = 0;
        bool inside = true;
        for (int k = 0; k < d; ++k) {
          const int p = basis_.basis(k).degree();
          const int delta = rest / box_stride_[static_cast<size_t>(k)] - p;
          rest %= box_stride_[static_cast<size_t>(k)];
          const int ik = jdx[static_cast<size_t>(k)] + delta;
          const int nk = basis_.basis(k).size();
          inside = inside && ik >= 0 && ik < nk;
          row = row * nk + ik;
        }
        if (!inside) continue;
        double value = entries_[static_cast<size_t>(j) * slots_ + slot];
        if (slot == 0) value += shift;
        triplets.emplace_back(row, j, value);
      }
    }
    Eigen::SparseMatrix<double> a(n, n);
    a.setFromTriplets(triplets.begin(), triplets.end());
    full_nonzeros = 2 * static_cast<long>(triplets.size()) - n;
    return a;
  }

 private:
  const TensorBasis& basis_;
  std::array<int, kMaxTensorDimension> box_stride_{};
  int centre_ = 0;
  int slots_ = 0;
  std::array<int, kMaxTensorTerms> local_{};
  std::vector<double> entries_;  // [column][slot]
};

}  // namespace

int hessian_slot(int k, int l, int dimension) {
  if (k > l) std::swap(k, l);
  // Rows 0..k-1 of the upper triangle hold dimension, dimension - 1, .. entries.
  return k * dimension - k * (k - 1) / 2 + (l - k);
}

TensorBasis::TensorBasis(std::vector<BSplineBasis> bases) : bases_(std::move(bases)) {
  if (bases_.empty() || bases_.size() > static_cast<size_t>(kMaxTensorDimension)) {
    throw std::invalid_argument("TensorBasis: " + std::to_string(bases_.size()) + " bases, need 1.." +
                                std::to_string(kMaxTensorDimension));
  }
  long long size = 1;
  for (const BSplineBasis& b : bases_) size *= b.size();
  if (size > INT_MAX) throw std::invalid_argument("TensorBasis: " + std::to_string(size) + " coefficients overflow int");
  size_ = static_cast<int>(size);
}

bool TensorBasis::contains(const double* point) const {
  for (int k = 0; k < dimension(); ++k)
    if (!(point[k] >= basis(k).lower() && point[k] <= basis(k).upper())) return false;
  return true;
}

void TensorBasis::evaluate(const double* point, SplineDerivatives derivatives, TensorBasisPoint& out) const {
  switch (derivatives) {
    case SplineDerivatives::kValue: evaluate_tensor<0>(bases_, point, out); break;
    case SplineDerivatives::kGradient: evaluate_tensor<1>(bases_, point, out); break;
    case SplineDerivatives::kHessian: evaluate_tensor<2>(bases_, point, out); break;
  }
}

// The 1-D factors of a 3-D query: f[k][order][a] for variable k, derivative order 0..2 and the
// degree + 1 non-zero basis functions, and the first basis index of each variable.
struct spline_kernels::QueryFactors {
  double f[3][3][kMaxSplineDegree + 1];
  int first[3];
};

namespace {

using spline_kernels::KernelRow;
using spline_kernels::QueryFactors;
using spline_kernels::QueryKernel;

// Four doubles (the GCC vector extension, which clang has too): one AVX register in the
// x86-64-v3 clones, two SSE registers in the baseline.
typedef double Vec4 __attribute__((vector_size(32)));

// Lanes i0..i3 of the eight lanes of a and b (a's 0..3, b's 4..7): clang's and GCC 12's
// __builtin_shufflevector, GCC's older __builtin_shuffle before that. A permutation, so the
// results are the same bits either way.
#if defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)
#define WRC_SHUFFLE4(a, b, i0, i1, i2, i3) __builtin_shufflevector(a, b, i0, i1, i2, i3)
#endif
#endif
#ifndef WRC_SHUFFLE4
typedef long long Index4 __attribute__((vector_size(32)));
#define WRC_SHUFFLE4(a, b, i0, i1, i2, i3) __builtin_shuffle(a, b, Index4{i0, i1, i2, i3})
#endif

// The lane sums of four vectors p[0..3], {sum p[0], .., sum p[3]}, each (x0 + x1) + (x2 + x3), by
// two rounds of shuffles and adds (a 4 x 4 transpose folded into the sums).
__attribute__((always_inline)) inline void lane_sums(const Vec4* p, Vec4& sums) {
  const Vec4 s01 = WRC_SHUFFLE4(p[0], p[1], 0, 4, 2, 6) + WRC_SHUFFLE4(p[0], p[1], 1, 5, 3, 7);
  const Vec4 s23 = WRC_SHUFFLE4(p[2], p[3], 0, 4, 2, 6) + WRC_SHUFFLE4(p[2], p[3], 1, 5, 3, 7);
  sums = WRC_SHUFFLE4(s01, s23, 0, 1, 4, 5) + WRC_SHUFFLE4(s01, s23, 2, 3, 6, 7);
}
#undef WRC_SHUFFLE4

// TensorSplineSet::query for degrees Q0 - 1, Q1 - 1, Q2 - 1 and the values of the first S
// functions of each row (S a multiple of 4, at most the stride; compile-time loop bounds, so that
// the S / 4 accumulators stay in registers and the terms are one pass: the term's weight is formed
// from the 1-D factors, its row is base + row offset). The derivatives of function n come from
// its transposed coefficients (transposed[n]: the query's first term; transposed_offsets: the
// (b, c) vectors of 4 y terms from there). Fewer instructions than a fully separable contraction
// of the values (its intermediate sums cost more than the term weights they save), than values and
// derivatives merged into one pass (register pressure), and than the derivatives of functions 0..3
// contracted together from the rows (instruction counts: tests/bench/models_bench.cpp,
// BM_SplineBothWheels). Compiled for x86-64-v3 (AVX2, FMA) and the baseline, chosen at run time.
template <int Q0, int Q1, int Q2, int S>
WRC_SIMD_CLONES
void query_kernel(const double* base, const std::ptrdiff_t* offsets, const double* const* transposed,
                  const std::ptrdiff_t* transposed_offsets, const QueryFactors& q, int value_count, double* values,
                  int derivative_count, double* derivatives) {
  if (value_count > 0) {
    // S / 4 accumulators of four doubles, all functions in one pass over the terms.
    constexpr int kVectors = S / 4;
    Vec4 acc[kVectors];
    for (int k = 0; k < kVectors; ++k) acc[k] = Vec4{0.0, 0.0, 0.0, 0.0};
    Vec4 yaw;  // the yaw factors (Q2 <= 4 used)
    std::memcpy(&yaw, q.f[2][0], sizeof yaw);
    int t = 0;
    for (int a = 0; a < Q0; ++a)
      for (int b = 0; b < Q1; ++b) {
        const double wab = q.f[0][0][a] * q.f[1][0][b];
        const Vec4 w = Vec4{wab, wab, wab, wab} * yaw;  // the weights of the (a, b, c) terms
        for (int c = 0; c < Q2; ++c, ++t) {
          const Vec4 wv = {w[c], w[c], w[c], w[c]};
          const double* row = base + offsets[t];
          for (int k = 0; k < kVectors; ++k) {
            Vec4 r;
            std::memcpy(&r, row + 4 * k, sizeof r);
            acc[k] += wv * r;
          }
        }
      }
    double all[S];
    std::memcpy(all, acc, sizeof all);
    for (int j = 0; j < value_count; ++j) values[j] = all[j];
  }
  if (derivative_count > 0) {
    // Per function, its coefficients of the (a, b, c) terms with a, the y index, contiguous
    // (transposed: one 4-lane vector per (b, c)); contracted over yaw (orders 0..2), then roll
    // (keeping total orders <= 2), the lanes over y last: the 10 outputs are dot products of the
    // y factors with 6 vectors.
    static_assert(Q0 == 4, "the derivative lanes are the 4 cubic y terms");
#define WRC_SPLAT(v) (Vec4{(v), (v), (v), (v)})  // a macro: a function returning Vec4 would change the baseline ABI
    Vec4 yaw[3][Q2], roll[3][Q1], y[3];
    for (int order = 0; order < 3; ++order) {
      for (int c = 0; c < Q2; ++c) yaw[order][c] = WRC_SPLAT(q.f[2][order][c]);
      for (int b = 0; b < Q1; ++b) roll[order][b] = WRC_SPLAT(q.f[1][order][b]);
      std::memcpy(&y[order], q.f[0][order], sizeof y[order]);
    }
    // (roll order, yaw order) of the 6 roll-yaw contractions: (0,0), (1,0), (0,1), (2,0), (1,1), (0,2).
    constexpr int kRoll[6] = {0, 1, 0, 2, 1, 0}, kYaw[6] = {0, 0, 1, 0, 1, 2};
    // Output slot -> (y order, contraction): value, gradient (y, roll, yaw), Hessian (hessian_slot order).
    constexpr int kY[10] = {0, 1, 0, 0, 2, 1, 1, 0, 0, 0}, kU[10] = {0, 0, 1, 2, 0, 1, 2, 3, 4, 5};
    for (int n = 0; n < derivative_count; ++n) {
      const double* block = transposed[n];
      Vec4 T[3][Q1];
      for (int order = 0; order < 3; ++order)
        for (int b = 0; b < Q1; ++b) T[order][b] = WRC_SPLAT(0.0);
      for (int b = 0; b < Q1; ++b)
        for (int c = 0; c < Q2; ++c) {
          Vec4 r;
          std::memcpy(&r, block + transposed_offsets[b * Q2 + c], sizeof r);
          for (int order = 0; order < 3; ++order) T[order][b] += yaw[order][c] * r;
        }
      Vec4 U[6];
      for (int m = 0; m < 6; ++m) {
        Vec4 u = WRC_SPLAT(0.0);
        for (int b = 0; b < Q1; ++b) u += roll[kRoll[m]][b] * T[kYaw[m]][b];
        U[m] = u;
      }
      Vec4 p[12];
      for (int slot = 0; slot < 10; ++slot) p[slot] = y[kY[slot]] * U[kU[slot]];
      p[10] = p[11] = WRC_SPLAT(0.0);
      double* out = derivatives + 10 * n;
      for (int group = 0; group < 3; ++group) {
        Vec4 sums;
        lane_sums(p + 4 * group, sums);
        std::memcpy(out + 4 * group, &sums, sizeof(double) * (group < 2 ? 4 : 2));
      }
    }
#undef WRC_SPLAT
  }
}

static_assert(std::is_same_v<QueryKernel, decltype(&query_kernel<4, 4, 4, 4>)>,
              "the kernel table's type is the kernels' own");

// The kernels for degrees (Q0, Q1, Q2) - 1 by the number of 4-function blocks of values.
template <int Q0, int Q1, int Q2>
constexpr KernelRow kernel_row() {
  static_assert(spline_kernels::kMaxBlocks == 8, "one entry per block count");
  return {nullptr,
          &query_kernel<Q0, Q1, Q2, 4>,
          &query_kernel<Q0, Q1, Q2, 8>,
          &query_kernel<Q0, Q1, Q2, 12>,
          &query_kernel<Q0, Q1, Q2, 16>,
          &query_kernel<Q0, Q1, Q2, 20>,
          &query_kernel<Q0, Q1, Q2, 24>,
          &query_kernel<Q0, Q1, Q2, 28>,
          &query_kernel<Q0, Q1, Q2, 32>};
}

// The one dispatch table of the compiled query kernels: the degrees (y, roll, yaw) each row is for.
struct KernelTableEntry {
  int degrees[3];
  KernelRow kernels;
};
const KernelTableEntry kKernelTable[] = {
    {{3, 3, 3}, kernel_row<4, 4, 4>()},
    {{3, 3, 2}, kernel_row<4, 4, 3>()},
};

// The table's row for the basis's degrees, or null (the general path).
const KernelRow* select_kernels(const TensorBasis& basis) {
  if (basis.dimension() != 3) return nullptr;
  for (const KernelTableEntry& e : kKernelTable)
    if (basis.basis(0).degree() == e.degrees[0] && basis.basis(1).degree() == e.degrees[1] &&
        basis.basis(2).degree() == e.degrees[2])
      return &e.kernels;
  return nullptr;
}

}  // namespace

TensorSplineSet::TensorSplineSet(TensorBasis basis, const Eigen::MatrixXd& coefficients)
    : basis_(std::move(basis)), functions_(static_cast<int>(coefficients.cols())) {
  if (coefficients.rows() != basis_.size() || functions_ == 0) {
    std::ostringstream msg;
    msg << "TensorSplineSet: coefficients are " << coefficients.rows() << " x " << coefficients.cols()
        << ", expected " << basis_.size() << " rows (the basis size) and at least one column";
    throw std::invalid_argument(msg.str());
  }
  stride_ = (functions_ + 3) / 4 * 4;
  data_.assign(static_cast<size_t>(basis_.size()) * static_cast<size_t>(stride_), 0.0);
  for (int i = 0; i < basis_.size(); ++i)
    for (int j = 0; j < functions_; ++j) data_[static_cast<size_t>(i) * stride_ + j] = coefficients(i, j);
  kernels_ = select_kernels(basis_);
  kernel_blocks_ = kernels_ ? std::min(stride_ / 4, spline_kernels::kMaxBlocks) : 0;
  if (kernels_) {
    // Row offsets of the (q0 q1 q2) terms of a query from the first term's row.
    const int n0 = basis_.basis(0).size(), n1 = basis_.basis(1).size(), n2 = basis_.basis(2).size();
    for (int a = 0; a <= basis_.basis(0).degree(); ++a)
      for (int b = 0; b <= basis_.basis(1).degree(); ++b)
        for (int c = 0; c <= basis_.basis(2).degree(); ++c)
          offsets_.push_back(static_cast<std::ptrdiff_t>((a * n1 + b) * n2 + c) * stride_);
    // The derivative functions' coefficients transposed, y index fastest: (i2 * n1 + i1) * n0 + i0.
    transposed_count_ = std::min(kMaxDerivativeFunctions, functions_);
    transposed_.assign(static_cast<size_t>(transposed_count_) * basis_.size(), 0.0);
    for (int j = 0; j < transposed_count_; ++j)
      for (int i0 = 0; i0 < n0; ++i0)
        for (int i1 = 0; i1 < n1; ++i1)
          for (int i2 = 0; i2 < n2; ++i2)
            transposed_[static_cast<size_t>(j) * basis_.size() + static_cast<size_t>((i2 * n1 + i1) * n0 + i0)] =
                coefficient((i0 * n1 + i1) * n2 + i2, j);
    for (int b = 0; b <= basis_.basis(1).degree(); ++b)
      for (int c = 0; c <= basis_.basis(2).degree(); ++c)
        transposed_offsets_.push_back(static_cast<std::ptrdiff_t>(c * n1 + b) * n0);
  }
}

Eigen::MatrixXd TensorSplineSet::coefficients() const {
  Eigen::MatrixXd c(basis_.size(), functions_);
  for (int i = 0; i < basis_.size(); ++i)
    for (int j = 0; j < functions_; ++j) c(i, j) = coefficient(i, j);
  return c;
}

void TensorSplineSet::values(const TensorBasisPoint& point, double* out) const {
  contract(data_, stride_, functions_, point, point.value.data(), out);
}

void TensorSplineSet::gradients(const TensorBasisPoint& point, double* gradient) const {
  if (point.derivatives == SplineDerivatives::kValue)
    throw std::invalid_argument("TensorSplineSet::gradients: point evaluated without derivatives");
  for (int k = 0; k < point.dimension; ++k)
    contract(data_, stride_, functions_, point, point.gradient[static_cast<size_t>(k)].data(),
             gradient + static_cast<size_t>(k) * functions_);
}

void TensorSplineSet::query(const double* point, int value_count, double* values, int derivative_count,
                            double* derivatives) const {
  if (basis_.dimension() != 3) throw std::invalid_argument("TensorSplineSet::query: the basis is not 3-D");
  if (value_count < 0 || value_count > functions_ || derivative_count < 0 ||
      derivative_count > std::min(kMaxDerivativeFunctions, functions_))
    throw std::invalid_argument("TensorSplineSet::query: value_count = " + std::to_string(value_count) +
                                " or derivative_count = " + std::to_string(derivative_count) + " out of range");
  QueryFactors q;
  const bool orders = derivative_count > 0;
  for (int k = 0; k < 3; ++k) {
    const BSplineBasis& b = basis_.basis(k);
    q.first[k] = b.evaluate(point[k], q.f[k][0], orders ? q.f[k][1] : nullptr, orders ? q.f[k][2] : nullptr);
    // Orders above the degree vanish (degree 0 and 1 bases fill only what they have), and so do
    // the factors past degree + 1 (the kernels read all four as one vector).
    if (!orders || b.degree() < kMaxSplineDegree) {
      for (int order = 0; order < 3; ++order) {
        const bool computed = order == 0 || (orders && order <= b.degree());
        for (int a = computed ? b.degree() + 1 : 0; a <= kMaxSplineDegree; ++a) q.f[k][order][a] = 0.0;
      }
    }
  }
  // The kernel for the values asked (their count rounded up to a multiple of 4: the padding
  // columns of data_ are zero and go nowhere).
  const int blocks = std::max(1, (value_count + 3) / 4);
  if (blocks <= kernel_blocks_) {
    const QueryKernel kernel = (*kernels_)[static_cast<size_t>(blocks)];
    const int n0 = basis_.basis(0).size(), n1 = basis_.basis(1).size(), n2 = basis_.basis(2).size();
    const double* base = data_.data() + static_cast<size_t>((q.first[0] * n1 + q.first[1]) * n2 + q.first[2]) * stride_;
    const double* transposed[kMaxDerivativeFunctions];
    for (int n = 0; n < derivative_count; ++n)
      transposed[n] = transposed_.data() + static_cast<size_t>(n) * basis_.size() +
                      static_cast<size_t>((q.first[2] * n1 + q.first[1]) * n0 + q.first[0]);
    kernel(base, offsets_.data(), transposed, transposed_offsets_.data(), q, value_count, values, derivative_count,
           derivatives);
    return;
  }
  // Other degree combinations: the general tensor-product path.
  TensorBasisPoint p;
  basis_.evaluate(point, orders ? SplineDerivatives::kHessian : SplineDerivatives::kValue, p);
  if (value_count > 0) contract(data_, stride_, value_count, p, p.value.data(), values);
  for (int n = 0; n < derivative_count; ++n) {
    double* out = derivatives + 10 * n;
    this->derivatives(p, n, out[0], out + 1, out + 4);
  }
}

bool TensorSplineSet::query_is_compiled(int value_count) const {
  return std::max(1, (value_count + 3) / 4) <= kernel_blocks_;
}

void TensorSplineSet::derivatives(const TensorBasisPoint& point, int j, double& value, double* gradient,
                                  double* hessian) const {
  if ((gradient && point.derivatives == SplineDerivatives::kValue) ||
      (hessian && point.derivatives != SplineDerivatives::kHessian)) {
    throw std::invalid_argument("TensorSplineSet::derivatives: point evaluated with fewer derivatives than asked");
  }
  // Gather function j's coefficients of the point's terms once, then contiguous dot products by
  // Eigen's packet reduction: independent vector lanes instead of a plain loop's one latency-bound
  // scalar chain per output, and no interleaving of all outputs (timings: tests/bench/spline_bench.cpp).
  const int n = point.terms;
  double c[kMaxTensorTerms];
  for (int t = 0; t < n; ++t) c[t] = coefficient(point.index[static_cast<size_t>(t)], j);
  const Eigen::Map<const Eigen::VectorXd> cv(c, n);
  auto dot = [&cv, n](const std::array<double, kMaxTensorTerms>& w) {
    return cv.dot(Eigen::Map<const Eigen::VectorXd>(w.data(), n));
  };
  value = dot(point.value);
  const int d = point.dimension;
  if (gradient)
    for (int k = 0; k < d; ++k) gradient[k] = dot(point.gradient[static_cast<size_t>(k)]);
  if (hessian)
    for (int s = 0; s < d * (d + 1) / 2; ++s) hessian[s] = dot(point.hessian[static_cast<size_t>(s)]);
}

TensorSplineSet fit_tensor_spline(const TensorBasis& basis, const WeightedSamples& samples, FitStatistics* statistics,
                                  double ridge) {
  const auto start = std::chrono::steady_clock::now();
  if (!(ridge >= 0.0) || !std::isfinite(ridge)) {
    std::ostringstream msg;
    msg << "ridge = " << ridge << " must be non-negative and finite";
    fit_error(msg.str());
  }
  validate_samples(basis, samples);
  const int d = basis.dimension();
  const int n = basis.size();
  const int count = samples.count();
  const int m = static_cast<int>(samples.values.cols());

  // Assembly: one basis evaluation per sample, the normal matrix block and the right-hand sides
  // B^T W F of every function (row-major, so a sample adds contiguous rows).
  BandedNormalMatrix normal(basis);
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rhs =
      Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>::Zero(n, m);
  std::vector<int> touched(static_cast<size_t>(n), 0);
  Eigen::RowVectorXd wf(m);
  TensorBasisPoint point;
  std::array<double, kMaxTensorDimension> x{};
  for (int i = 0; i < count; ++i) {
    for (int k = 0; k < d; ++k) {  // clamp the tolerated slack onto the box
      const BSplineBasis& b = basis.basis(k);
      x[static_cast<size_t>(k)] = std::clamp(samples.points[static_cast<size_t>(i) * d + k], b.lower(), b.upper());
    }
    basis.evaluate(x.data(), SplineDerivatives::kValue, point);
    const double w = samples.weights[static_cast<size_t>(i)];
    normal.add(point, w);
    wf = w * samples.values.row(i);
    for (int t = 0; t < point.terms; ++t) {
      const int index = point.index[static_cast<size_t>(t)];
      rhs.row(index) += point.value[static_cast<size_t>(t)] * wf;
      ++touched[static_cast<size_t>(index)];
    }
  }
  for (int i = 0; i < n; ++i)
    if (touched[static_cast<size_t>(i)] == 0) uncovered_error(basis, i);

  long nonzeros = 0;
  const Eigen::SparseMatrix<double> a = normal.lower(ridge, nonzeros);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt(a);
  if (ldlt.info() != Eigen::Success) {
    throw std::runtime_error("fit_tensor_spline: LDLT factorisation of the " + std::to_string(n) +
                             "-unknown normal equations failed (zero pivot)");
  }
  const Eigen::MatrixXd coefficients = ldlt.solve(Eigen::MatrixXd(rhs));
  if (ldlt.info() != Eigen::Success) throw std::runtime_error("fit_tensor_spline: LDLT solve failed");

  if (statistics) {
    statistics->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    statistics->coefficients = n;
    statistics->samples = count;
    statistics->nonzeros = nonzeros;
    statistics->ridge = ridge;
  }
  return TensorSplineSet(basis, coefficients);
}

}  // namespace wrc
