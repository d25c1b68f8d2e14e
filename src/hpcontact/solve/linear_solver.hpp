// Sparse direct solvers: symmetric positive definite (CHOLMOD, Eigen's LDLT) and general (UMFPACK LU).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include <Eigen/Sparse>

namespace hpcontact::solve {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// cholmod_else_lu: CHOLMOD while the matrices are symmetric (to round-off:
/// |a_ij − a_ji| ≤ symmetry_tolerance · √|a_ii a_jj|) and positive definite, UMFPACK's LU from
/// the first that is not (a contact tangent made indefinite by a curvature term at a deep trial
/// penetration, a finite-strain body unstable under compression, friction in slip) — a singular
/// matrix is still refused, by the LU.
enum class LinearSolverKind { cholmod, ldlt, lu, cholmod_else_lu };

/// What a CHOLMOD factorisation needs, from its symbolic analysis, and what it took.
struct FactorMemory {
  double factor_entries = 0;  ///< nonzeros of L (CHOLMOD's lnz, without the supernodes' padding)
  double flops = 0;           ///< of the numeric factorisation (CHOLMOD's fl)
  /// What the numeric factorisation will allocate: the supernodal factor's reals and integers,
  /// its largest update matrix, a permuted copy of A's lower triangle (two while it is made).
  double estimate_bytes = 0;
  /// CHOLMOD's peak memory in use (analysis, factorisation and solves so far).
  double peak_bytes = 0;
};

/// The asymmetry, relative to the diagonal, up to which cholmod_else_lu takes a matrix for a
/// symmetric one and factorises its lower triangle: the sums of an assembly leave ~1e-16 of an
/// entry's terms, and a Newton step solved with the symmetric part of a tangent this close to
/// it converges as with the tangent itself.
constexpr double symmetry_tolerance = 1e-10;

/// Whether |a_ij − a_ji| ≤ tolerance · √|a_ii a_jj| for every entry of the square matrix A.
bool symmetric_to_round_off(const Eigen::SparseMatrix<double>& A, double tolerance = symmetry_tolerance);

/// Parses "cholmod" / "ldlt" / "lu"; InputError naming `where` otherwise.
LinearSolverKind linear_solver_kind(const std::string& name, const std::string& where);

/// Factorises once, solves many right-hand sides. The symbolic analysis (ordering, elimination
/// tree) is kept while the matrices factorised have the same sparsity pattern: Newton's
/// tangents of one solve usually do, and then only the numeric factorisation is repeated.
class LinearSolver {
public:
  explicit LinearSolver(LinearSolverKind kind = LinearSolverKind::cholmod);
  ~LinearSolver();
  LinearSolver(LinearSolver&&) noexcept;
  LinearSolver& operator=(LinearSolver&&) noexcept;

  /// Factorises A: for cholmod and ldlt A is symmetric (the lower triangle is used) and must be
  /// positive definite, for lu any nonsingular matrix. Throws NumericalError otherwise, which
  /// for a stiffness matrix means a rigid-body motion is unconstrained.
  /// Symmetric matrices are also refused when a pivot is below singular_pivot_ratio() of its
  /// diagonal entry (a singular matrix whose zero pivot comes out as positive round-off).
  /// CHOLMOD: after the symbolic analysis of a new pattern, a factor whose estimate (memory())
  /// exceeds the memory available (available_memory.hpp) is refused with a ResourceError that
  /// gives both and what to do, before the numeric factorisation tries to allocate it; so is a
  /// failed allocation (CHOLMOD's out-of-memory status).
  void factorize(const SparseMatrix& A);
  /// The same, taking A over instead of copying it (the solver keeps the matrix it factorised).
  void factorize(SparseMatrix&& A);
  /// CHOLMOD's figures of the last analysis and its peak memory so far; zero for ldlt and lu.
  FactorMemory memory() const;
  /// Whether the last factorize() kept the factors of the matrix before it (an equal matrix).
  bool kept_factors() const { return kept_factors_; }
  /// Numeric factorisations done so far (those kept not counted), for tests and benchmarks.
  int factorizations() const { return factorizations_; }
  /// A number no other factorisation in this process has had (0 before the first): what was
  /// solved with these factors may be reused while it is unchanged — unlike the solver's address
  /// and count, which a new solver in the same place repeats.
  std::uint64_t factors_serial() const { return factors_serial_; }
  /// After factorize() refused a matrix: the row of A whose pivot vanished or was negative; -1
  /// after a success, or when the solver names no row (LU).
  int last_singular_row() const { return last_singular_row_; }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  /// Solves for every column of B at once.
  Eigen::MatrixXd solve_columns(const Eigen::MatrixXd& B) const;
  /// Whether a solve splits into two halves, A⁻¹ = B F (the LU, P R A Q = L U: F = L⁻¹ P R,
  /// B = Q U⁻¹), each a triangular solve that skips the zeros of a sparse right-hand side: a
  /// product G A⁻¹ E with sparse G and E then costs F E and Bᵀ Gᵀ, forward solves that stay
  /// sparse, where A⁻¹ E pays a full backward solve per column.
  bool splits_solves() const { return kind_ == LinearSolverKind::lu; }
  /// F B for every column of B (splits_solves()).
  Eigen::MatrixXd solve_front_columns(const Eigen::MatrixXd& B) const;
  /// B w: A⁻¹ b = solve_back(F b) (splits_solves()).
  Eigen::VectorXd solve_back(const Eigen::VectorXd& w) const;
  /// Bᵀ C for every column of C (splits_solves()).
  Eigen::MatrixXd solve_back_transposed_columns(const Eigen::MatrixXd& C) const;
  /// Symbolic analyses done so far (a new one for each new sparsity pattern), for tests.
  int analyses() const { return analyses_; }
  /// The pivot, relative to its diagonal entry, below which a symmetric matrix is taken for a
  /// singular one: 1e-11 unless set (a slender solid's bending gives smaller ones that are not
  /// round-off, solve/fixed_dofs.hpp).
  double singular_pivot_ratio() const { return singular_pivot_ratio_; }
  void set_singular_pivot_ratio(double ratio) { singular_pivot_ratio_ = ratio; }
  /// The factorisation in use: for cholmod_else_lu, lu once a matrix was not positive definite.
  LinearSolverKind kind() const { return kind_; }
  /// Whether factorize() reads only the lower triangle of A (cholmod and ldlt; not lu, nor
  /// cholmod_else_lu, which may turn to LU): then A may hold that triangle alone.
  bool reads_lower_triangle() const { return kind_ != LinearSolverKind::lu && !lu_when_indefinite_; }

private:
  struct Impl;
  LinearSolverKind kind_;
  double singular_pivot_ratio_;
  bool lu_when_indefinite_ = false;
  int last_singular_row_ = -1;
  int analyses_ = 0;
  int factorizations_ = 0;
  std::uint64_t factors_serial_ = 0;
  bool kept_factors_ = false;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hpcontact::solve
