// CHOLMOD supernodal Cholesky through Eigen's wrapper, Eigen's SimplicialLDLT as alternative, and
// UMFPACK's LU for matrices that are not symmetric positive definite.
#include "hpcontact/solve/linear_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <Eigen/UmfPackSupport>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "hpcontact/core/error.hpp"
#include "hpcontact/core/stop.hpp"
#include "hpcontact/solve/available_memory.hpp"

namespace hpcontact::solve {

namespace {

/// CHOLMOD's supernodal LLᵀ with access to its pivots: the squared diagonal of L, each with the
/// row of A it eliminates.
class CholmodWithPivots : public Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> {
public:
  /// The row of A whose pivot was not positive when the factorisation stopped, or -1.
  int failed_row() const {
    const cholmod_factor* L = m_cholmodFactor;
    if (!L || L->minor >= L->n) return -1;
    return static_cast<const int*>(L->Perm)[L->minor];
  }

  /// Whether an analysis left a factor to fill (CHOLMOD returns none when it runs out of memory).
  bool has_factor() const { return m_cholmodFactor != nullptr; }

  /// After an analysis of a matrix with nnz_lower entries in its lower triangle: the factor's
  /// size and what the numeric factorisation will allocate. A supernodal factor holds xsize
  /// reals (L with the zeros the supernodes pad it with) and ssize integers; the factorisation
  /// first makes two permuted transposes of the lower triangle (8 + 4 bytes an entry), frees one
  /// and keeps the other while it fills the factor and an update matrix of at most maxcsize
  /// reals; its workspace takes about 48 bytes an unknown (measured: the rest of its peak on the
  /// 3D Laplacians of tests/unit/solve/test_linear_solver_memory.cpp).
  FactorMemory analysed_memory(Eigen::Index nnz_lower) const {
    const cholmod_factor* L = m_cholmodFactor;
    const cholmod_common& cm = common();
    FactorMemory m;
    m.factor_entries = cm.lnz;
    m.flops = cm.fl;
    const double reals = L->is_super ? static_cast<double>(L->xsize + L->maxcsize) : cm.lnz;
    const double integers = L->is_super ? static_cast<double>(L->ssize) : cm.lnz;
    const double copy = (sizeof(double) + sizeof(int)) * static_cast<double>(nnz_lower);
    m.estimate_bytes = sizeof(int) * integers + std::max(2 * copy, sizeof(double) * reals + copy) +
                       48.0 * static_cast<double>(L->n);
    return m;
  }

  /// CHOLMOD's peak memory in use so far.
  double peak_bytes() const { return static_cast<double>(common().memory_usage); }

  /// CHOLMOD's settings and statistics (Eigen gives them non-const only).
  const cholmod_common& common() const { return const_cast<CholmodWithPivots&>(*this).cholmod(); }

  /// Calls f(row of A, pivot) for every column of the factor.
  template <typename F>
  void for_each_pivot(F f) const {
    const cholmod_factor* L = m_cholmodFactor;
    const auto* x = static_cast<const double*>(L->x);
    const auto* perm = static_cast<const int*>(L->Perm);
    if (L->is_super) {
      const auto* super = static_cast<const int*>(L->super);
      const auto* pi = static_cast<const int*>(L->pi);
      const auto* px = static_cast<const int*>(L->px);
      for (std::size_t k = 0; k < L->nsuper; ++k) {
        const int ncols = super[k + 1] - super[k], nrows = pi[k + 1] - pi[k];
        for (int j = 0; j < ncols; ++j) {
          const double d = x[px[k] + j * (nrows + 1)];
          f(perm[super[k] + j], L->is_ll ? d * d : d);
        }
      }
    } else {
      const auto* p = static_cast<const int*>(L->p);
      for (std::size_t k = 0; k < L->n; ++k) {
        const double d = x[p[k]];
        f(perm[k], L->is_ll ? d * d : d);
      }
    }
  }
};

/// After a CHOLMOD call (`stage`: analysis, factorisation, solve) on a system of n unknowns
/// with nnz stored entries: ResourceError if it failed for want of memory or of integer range,
/// with the size of the factor when the analysis got that far. (A matrix that is not positive
/// definite is a warning status, handled by the caller through the factor's pivots.)
void require_cholmod_resources(const CholmodWithPivots& c, const char* stage, Eigen::Index n,
                               Eigen::Index nnz) {
  const cholmod_common& cm = const_cast<CholmodWithPivots&>(c).cholmod();
  if (cm.status >= CHOLMOD_OK && c.has_factor()) return;
  std::ostringstream os;
  os << "the sparse Cholesky solver (CHOLMOD) failed in its " << stage << " of the system of "
     << n << " unknowns";
  if (nnz > 0) os << " (" << nnz << " stored matrix entries)";
  os << ": "
     << (cm.status == CHOLMOD_OUT_OF_MEMORY ? "out of memory"
         : cm.status == CHOLMOD_TOO_LARGE   ? "the system is too large for its integers"
                                            : "status " + std::to_string(cm.status));
  if (cm.lnz > 0)
    os << "; the factor has " << cm.lnz << " entries, at least " << std::setprecision(3)
       << cm.lnz * sizeof(double) / 1e9 << " GB";
  os << "; memory in use at the peak " << std::setprecision(3) << cm.memory_usage / 1e9
     << " GB. Use fewer elements or a lower degree (or static condensation), or more memory";
  throw ResourceError(os.str());
}

/// The stored entries of A on and below its diagonal (what CHOLMOD reads of it).
Eigen::Index lower_entries(const SparseMatrix& A) {
  Eigen::Index count = 0;
  for (Eigen::Index col = 0; col < A.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(A, col); it; ++it) count += it.row() >= col;
  return count;
}

/// Refuses to factorise (ResourceError) when the analysis's estimate is more than the memory
/// available: a failed allocation would be reported too, but past a limit the kernel does not
/// refuse an allocation, it ends the process later (overcommit, the OOM killer).
void require_memory_for_factor(const FactorMemory& m, Eigen::Index n, Eigen::Index nnz) {
  const std::optional<AvailableMemory> available = available_memory();
  if (!available || m.estimate_bytes <= available->bytes) return;
  std::ostringstream os;
  os << std::setprecision(3) << "the sparse Cholesky factorisation (CHOLMOD) of the system of " << n
     << " unknowns (" << nnz << " stored matrix entries) would run out of memory: its factor has "
     << m.factor_entries << " entries and needs about " << m.estimate_bytes / 1e9
     << " GB with its workspace (" << m.flops / 1e9 << " GFLOP to compute), but "
     << available->bytes / 1e9 << " GB are available (" << available->limit
     << "). Use fewer elements or a lower degree (or static condensation), or run where more "
        "memory is available";
  throw ResourceError(os.str());
}

/// A pivot this small relative to its diagonal entry of A means the row is (to round-off) a
/// combination of the rows eliminated before it: the matrix is singular. Well-posed stiffness
/// matrices of the examples give ratios above 1e-6 (the quarter circle at p = 1..12: ≥ 3e-2);
/// a free rigid-body motion gives round-off, ≤ 1e-13.
constexpr double default_singular_pivot_ratio = 1e-11;

/// The smallest pivot ratio seen, and its row.
struct SmallestPivot {
  double ratio = std::numeric_limits<double>::infinity();
  int row = -1;
  void take(int row_of_a, double r) {
    if (!(r >= ratio)) {  // NaN pivots count as the smallest
      ratio = r;
      row = row_of_a;
    }
  }
  /// A symmetric factor's pivot against the matrix's diagonal entry of its row.
  void take(int row_of_a, double pivot, double diagonal) {
    take(row_of_a, diagonal > 0 ? pivot / diagonal : pivot);
  }
};

}  // namespace

/// UMFPACK's LU (P R A Q = L U, R a row scaling) with access to the diagonal of U.
class UmfPackWithPivots : public Eigen::UmfPackLU<SparseMatrix> {
public:
  /// Calls f(column of A, |U_kk| / max_i |(R A)_i,col|) for every column of the factor.
  template <typename F>
  void for_each_pivot(const SparseMatrix& A, F f) const {
    const int n = static_cast<int>(A.cols());
    std::vector<int> Q(n);
    std::vector<double> D(n), Rs(n);
    int recip = 0;
    if (umfpack_di_get_numeric(nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
                               Q.data(), D.data(), &recip, Rs.data(), m_numeric) != UMFPACK_OK)
      return;
    for (int k = 0; k < n; ++k) {
      double column_max = 0;
      for (SparseMatrix::InnerIterator it(A, Q[k]); it; ++it) {
        const double r = Rs[it.row()];
        column_max = std::max(column_max, std::abs(recip ? it.value() * r : it.value() / r));
      }
      f(Q[k], column_max > 0 ? std::abs(D[k]) / column_max : 0.0);
    }
  }

  /// x = the solution of (sys)x = b for each column of B, sys a system of the factors alone
  /// (UMFPACK_Pt_L, UMFPACK_U_Qt, UMFPACK_Q_Ut, ...: no scaling, no iterative refinement; the
  /// work of a triangular solve skips the zeros of a sparse right-hand side as it goes).
  Eigen::MatrixXd solve_factor(int sys, const SparseMatrix& A, const Eigen::MatrixXd& B) const {
    const int n = static_cast<int>(A.rows());
    Eigen::MatrixXd X(B.rows(), B.cols());
    std::vector<int> Wi(n);
    std::vector<double> W(5 * static_cast<size_t>(n));
    Eigen::VectorXd b(n);
    for (Eigen::Index j = 0; j < B.cols(); ++j) {
      b = B.col(j);
      const int status = umfpack_di_wsolve(sys, A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr(),
                                           X.col(j).data(), b.data(), m_numeric, m_control.data(),
                                           nullptr, Wi.data(), W.data());
      HPC_REQUIRE(status == UMFPACK_OK, NumericalError,
                  "UMFPACK's triangular solve failed (status " + std::to_string(status) + ")");
    }
    return X;
  }

  /// The row scaling R of P R A Q = L U as factors to multiply the rows with.
  Eigen::VectorXd row_scaling(int n) const {
    Eigen::VectorXd Rs(n);
    int recip = 0;
    const int status = umfpack_di_get_numeric(nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
                                              nullptr, nullptr, nullptr, &recip, Rs.data(), m_numeric);
    HPC_REQUIRE(status == UMFPACK_OK, NumericalError,
                "UMFPACK's factors could not be read (status " + std::to_string(status) + ")");
    return recip ? Rs : Eigen::VectorXd(Rs.cwiseInverse());
  }
};

struct LinearSolver::Impl {
  CholmodWithPivots cholmod;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt;
  UmfPackWithPivots lu;
  /// The matrix factorised last: UMFPACK's solve reads A itself (iterative refinement), and
  /// Eigen's wrapper keeps only a reference to it.
  SparseMatrix matrix;
  /// The sparsity pattern of the last matrix analysed (compressed column storage).
  std::vector<SparseMatrix::StorageIndex> outer, inner;
  bool analysed = false;
  /// CHOLMOD's figures of the last analysis.
  FactorMemory memory;

  /// Whether A (compressed) is the matrix factorised last, with the same values: then the
  /// factors in hand are its factors.
  bool is_factorised(const SparseMatrix& A) const {
    if (!analysed || A.rows() != matrix.rows() || A.cols() != matrix.cols() ||
        A.nonZeros() != matrix.nonZeros())
      return false;
    const auto n = A.cols(), nnz = A.nonZeros();
    return std::equal(A.outerIndexPtr(), A.outerIndexPtr() + n + 1, matrix.outerIndexPtr()) &&
           std::equal(A.innerIndexPtr(), A.innerIndexPtr() + nnz, matrix.innerIndexPtr()) &&
           std::equal(A.valuePtr(), A.valuePtr() + nnz, matrix.valuePtr());
  }

  /// Whether A has the pattern analysed last; if not, it becomes the pattern to analyse.
  bool same_pattern(const SparseMatrix& A) {
    const auto n = A.cols(), nnz = A.nonZeros();
    const bool same = analysed && static_cast<Eigen::Index>(outer.size()) == n + 1 &&
                      static_cast<Eigen::Index>(inner.size()) == nnz &&
                      std::equal(outer.begin(), outer.end(), A.outerIndexPtr()) &&
                      std::equal(inner.begin(), inner.end(), A.innerIndexPtr());
    if (!same) {
      outer.assign(A.outerIndexPtr(), A.outerIndexPtr() + n + 1);
      inner.assign(A.innerIndexPtr(), A.innerIndexPtr() + nnz);
    }
    return same;
  }
};

bool symmetric_to_round_off(const SparseMatrix& A, double tolerance) {
  if (A.rows() != A.cols()) return false;
  const Eigen::VectorXd d = A.diagonal().cwiseAbs();
  auto close = [&](Eigen::Index row, Eigen::Index col, double a, double b) {
    return std::abs(a - b) <= tolerance * std::sqrt(d(row) * d(col));
  };
  const SparseMatrix At = A.transpose();
  // Column by column through A and Aᵀ side by side: an entry stored in one and not in the other
  // is compared with zero.
  for (Eigen::Index col = 0; col < A.outerSize(); ++col) {
    SparseMatrix::InnerIterator a(A, col), b(At, col);
    while (a || b) {
      if (a && (!b || a.row() < b.row())) {
        if (!close(a.row(), col, a.value(), 0.0)) return false;
        ++a;
      } else if (b && (!a || b.row() < a.row())) {
        if (!close(b.row(), col, 0.0, b.value())) return false;
        ++b;
      } else {
        if (!close(a.row(), col, a.value(), b.value())) return false;
        ++a;
        ++b;
      }
    }
  }
  return true;
}

LinearSolverKind linear_solver_kind(const std::string& name, const std::string& where) {
  if (name == "cholmod") return LinearSolverKind::cholmod;
  if (name == "ldlt") return LinearSolverKind::ldlt;
  if (name == "lu") return LinearSolverKind::lu;
  throw InputError(where + ": unknown linear solver '" + name + "' (expected cholmod, ldlt or lu)");
}

LinearSolver::LinearSolver(LinearSolverKind kind)
    : kind_(kind == LinearSolverKind::cholmod_else_lu ? LinearSolverKind::cholmod : kind),
      singular_pivot_ratio_(default_singular_pivot_ratio),
      lu_when_indefinite_(kind == LinearSolverKind::cholmod_else_lu),
      impl_(std::make_unique<Impl>()) {
  impl_->cholmod.cholmod().print = 0;  // failures are reported through info(), not printed
}
LinearSolver::~LinearSolver() = default;
LinearSolver::LinearSolver(LinearSolver&&) noexcept = default;
LinearSolver& LinearSolver::operator=(LinearSolver&&) noexcept = default;

FactorMemory LinearSolver::memory() const {
  if (kind_ != LinearSolverKind::cholmod) return {};
  FactorMemory m = impl_->memory;
  m.peak_bytes = impl_->cholmod.peak_bytes();
  return m;
}

// A copy in compressed storage (the comparisons need it, and LU's solve reads A).
void LinearSolver::factorize(const SparseMatrix& A) { factorize(SparseMatrix(A)); }

void LinearSolver::factorize(SparseMatrix&& A_in) {
  // A stop request (core/stop.hpp) is honoured before each phase, the analysis and the numeric
  // factorisation (in 3D each takes minutes); a stop leaves the solver fit to be used again.
  stop_point("factorising");
  bool ok;
  SmallestPivot smallest;
  A_in.makeCompressed();
  kept_factors_ = impl_->is_factorised(A_in);
  if (kept_factors_) return;
  impl_->matrix.swap(A_in);  // Eigen 3.4's SparseMatrix has no move assignment: it would copy
  const SparseMatrix& A = impl_->matrix;
  ++factorizations_;
  static std::atomic<std::uint64_t> serials{0};
  factors_serial_ = ++serials;
  const bool analyse = !impl_->same_pattern(A);
  impl_->analysed = false;  // until this factorisation has succeeded
  if (analyse) ++analyses_;
  auto compute = [&](auto& solver) {
    if (analyse) solver.analyzePattern(A);
    stop_point("factorising");
    solver.factorize(A);
  };
  if (kind_ == LinearSolverKind::cholmod && lu_when_indefinite_ && !symmetric_to_round_off(A)) {
    kind_ = LinearSolverKind::lu;  // not symmetric: LU from now on (neither done here)
    --factorizations_;
    if (analyse) --analyses_;
    return factorize(SparseMatrix(A));
  }
  if (kind_ == LinearSolverKind::cholmod) {
    if (analyse) {
      impl_->cholmod.analyzePattern(A);
      require_cholmod_resources(impl_->cholmod, "analysis", A.rows(), A.nonZeros());
      impl_->memory = impl_->cholmod.analysed_memory(lower_entries(A));
      require_memory_for_factor(impl_->memory, A.rows(), A.nonZeros());
    }
    stop_point("factorising");
    impl_->cholmod.factorize(A);
    require_cholmod_resources(impl_->cholmod, "factorisation", A.rows(), A.nonZeros());
    ok = impl_->cholmod.info() == Eigen::Success;
    if (!ok && lu_when_indefinite_) {  // not positive definite: LU from now on
      kind_ = LinearSolverKind::lu;
      return factorize(SparseMatrix(A));
    }
    const Eigen::VectorXd diagonal = ok ? Eigen::VectorXd(A.diagonal()) : Eigen::VectorXd();
    if (ok)
      impl_->cholmod.for_each_pivot(
          [&](int row, double pivot) { smallest.take(row, pivot, diagonal(row)); });
    else
      smallest.row = impl_->cholmod.failed_row();
  } else if (kind_ == LinearSolverKind::ldlt) {
    compute(impl_->ldlt);
    ok = impl_->ldlt.info() == Eigen::Success;
    if (ok) {
      const Eigen::VectorXd diagonal = A.diagonal();
      const auto& D = impl_->ldlt.vectorD();
      const auto& P = impl_->ldlt.permutationPinv();  // column k of the factor eliminates row P(k)
      for (Eigen::Index k = 0; k < D.size(); ++k) {
        const int row = P.indices()(k);
        smallest.take(row, D(k), diagonal(row));
      }
    }
  } else {
    compute(impl_->lu);
    ok = impl_->lu.info() == Eigen::Success;
    if (ok)
      impl_->lu.for_each_pivot(A, [&](int column, double ratio) { smallest.take(column, ratio); });
  }
  last_singular_row_ = -1;
  if (ok && smallest.ratio > singular_pivot_ratio_) {
    impl_->analysed = true;
    return;
  }
  last_singular_row_ = smallest.row;
  std::ostringstream os;
  os << "the stiffness matrix is singular or not positive definite";
  if (ok)
    os << " (pivot of equation " << smallest.row << ": " << smallest.ratio << " of its "
       << (kind_ == LinearSolverKind::lu ? "column's largest entry)" : "diagonal entry)");
  else if (smallest.row >= 0)
    os << " (at equation " << smallest.row << ")";
  os << ": a body is not constrained against rigid-body motion, or an element is degenerate";
  throw NumericalError(os.str());
}

Eigen::VectorXd LinearSolver::solve(const Eigen::VectorXd& b) const {
  switch (kind_) {
    case LinearSolverKind::cholmod: {
      Eigen::VectorXd x = impl_->cholmod.solve(b);
      require_cholmod_resources(impl_->cholmod, "solve", b.size(), 0);
      return x;
    }
    case LinearSolverKind::ldlt: return impl_->ldlt.solve(b);
    case LinearSolverKind::lu:
    case LinearSolverKind::cholmod_else_lu: break;  // kind_ is never cholmod_else_lu
  }
  return impl_->lu.solve(b);
}

Eigen::MatrixXd LinearSolver::solve_columns(const Eigen::MatrixXd& B) const {
  switch (kind_) {
    case LinearSolverKind::cholmod: {
      Eigen::MatrixXd X = impl_->cholmod.solve(B);
      require_cholmod_resources(impl_->cholmod, "solve", B.rows(), 0);
      return X;
    }
    case LinearSolverKind::ldlt: return impl_->ldlt.solve(B);
    case LinearSolverKind::lu:
    case LinearSolverKind::cholmod_else_lu: break;  // kind_ is never cholmod_else_lu
  }
  // Many columns (a Schur complement's): without UMFPACK's iterative refinement, which would
  // triple the cost of each; the LU with pivoting is backward stable, and the Newton iteration
  // that uses these columns converges on its exact residual.
  auto& control = impl_->lu.umfpackControl();
  const double refinement = control[UMFPACK_IRSTEP];
  control[UMFPACK_IRSTEP] = 0;
  Eigen::MatrixXd X = impl_->lu.solve(B);
  control[UMFPACK_IRSTEP] = refinement;
  return X;
}

// P R A Q = L U: A⁻¹ = Q U⁻¹ · L⁻¹ P R, the halves UMFPACK's systems Pt_L (P'L x = b) and
// U_Qt (U Q' x = b) solve; the back half's transpose U⁻ᵀ Qᵀ is its system Q_Ut (Q U' x = b).
Eigen::MatrixXd LinearSolver::solve_front_columns(const Eigen::MatrixXd& B) const {
  HPC_ASSERT(splits_solves(), "split solves need an LU");
  const SparseMatrix& A = impl_->matrix;
  const Eigen::MatrixXd RB = impl_->lu.row_scaling(static_cast<int>(A.rows())).asDiagonal() * B;
  return impl_->lu.solve_factor(UMFPACK_Pt_L, A, RB);
}

Eigen::VectorXd LinearSolver::solve_back(const Eigen::VectorXd& w) const {
  HPC_ASSERT(splits_solves(), "split solves need an LU");
  return impl_->lu.solve_factor(UMFPACK_U_Qt, impl_->matrix, w);
}

Eigen::MatrixXd LinearSolver::solve_back_transposed_columns(const Eigen::MatrixXd& C) const {
  HPC_ASSERT(splits_solves(), "split solves need an LU");
  return impl_->lu.solve_factor(UMFPACK_Q_Ut, impl_->matrix, C);
}

}  // namespace hpcontact::solve
