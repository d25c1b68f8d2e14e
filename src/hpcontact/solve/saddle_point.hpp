// Linear systems of a displacement block and a few multipliers (contact pressures, a load
// factor): the multipliers eliminated, the displacements by a sparse direct solver.
#pragma once

#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "hpcontact/solve/linear_solver.hpp"

namespace hpcontact::solve {

/// The tangent J of a system whose first n unknowns are displacements u and whose last m are
/// multipliers z:
///
///     J = [ K  E ]   rows of u: K = ∂r_u/∂u (sparse, n × n), E = ∂r_u/∂z
///         [ G  H ]   rows of z: G = ∂r_z/∂u, H = ∂r_z/∂z (m × m)
///
/// A row k of z with G_k = 0 and H_kk ≠ 0 fixes z_k from the other multipliers (an inactive
/// contact node: z_k = 0; a slipping one: its tangential pressure tied to its normal one): those
/// z_k are eliminated first (they must not depend on each other). The remaining rows F — the
/// constraints G_k Δu = …, and rows such as a target force — and their unknowns form a
/// dense Schur complement
///
///     S = H̃ − G_F A⁻¹ Ê,   A = K + Σ_c g_cᵀ g_c / γ_c,
///
/// where the augmentation adds each constraint row c with γ_c > 0 to the rows of u (an
/// augmented Lagrangian: the solution is unchanged, and A is definite where only the
/// constraints hold a body, or where K is indefinite along them). One sparse factorisation
/// of A, |F| solves with it, and a dense LU of S per tangent; each right-hand side then costs
/// one sparse solve. With an LU (LinearSolver::splits_solves, A⁻¹ = B F) the |F| solves are
/// halves that stay sparse: G_F A⁻¹ Ê = (Bᵀ G_Fᵀ)ᵀ (F Ê), and a right-hand side costs one
/// solve and one back half (A⁻¹ Ê z = B (F Ê) z).
class SaddlePointSolver {
public:
  /// Factorises J (n + m square) with `sparse` for A; gamma (size m) is the augmentation of
  /// each row of z (0: none). NumericalError when A or S is singular. The sparsity pattern of A
  /// is that of K and of g_kᵀ g_k for every row k of G with stored entries (zero or not), so a
  /// caller that stores the gradients of inactive constraints as zeros keeps it from one
  /// tangent to the next.
  void factorize(LinearSolver& sparse, const SparseMatrix& J, int n, const Eigen::VectorXd& gamma);
  /// J⁻¹ b.
  Eigen::VectorXd solve(const LinearSolver& sparse, const Eigen::VectorXd& b) const;

  /// Multipliers fixed by their own row, and those solved in the Schur complement.
  int n_eliminated() const { return static_cast<int>(dependent_.size()); }
  int n_schur() const { return static_cast<int>(free_.size()); }
  /// Columns of A⁻¹ Ê the last factorize() solved for (the others kept from the tangent
  /// before; with split solves every column, none kept), for tests and benchmarks.
  int columns_solved() const { return columns_solved_; }

private:
  int n_ = 0, m_ = 0;
  std::vector<int> free_, dependent_;  ///< indices into z
  std::vector<int> position_;          ///< per z index: its position in free_ or dependent_
  std::vector<char> is_dependent_;     ///< per z index
  SparseMatrix E_, H_;                 ///< blocks of J
  Eigen::SparseMatrix<double, Eigen::RowMajor> H_rows_;  ///< H by rows
  Eigen::VectorXd h_dd_;               ///< H_kk of the dependent rows
  Eigen::VectorXd inv_gamma_;          ///< 1/γ of the free rows (0: not augmented)
  SparseMatrix G_F_;                   ///< the free rows of G
  Eigen::MatrixXd H_tilde_;            ///< H_FF − H_FD H_DD⁻¹ H_DF
  Eigen::MatrixXd Y_;                  ///< A⁻¹ Ê (none when the sparse solver splits its solves)
  /// F Ê where the sparse solver splits A⁻¹ = B F (LinearSolver::splits_solves), else empty.
  Eigen::MatrixXd front_;
  SparseMatrix E_hat_;                 ///< Ê of the last tangent (its columns are sparse)
  std::vector<int> z_of_column_;       ///< the multiplier of each column of Ê and Y
  std::uint64_t columns_factors_ = 0;  ///< the factors_serial() Y was solved with (0: none)
  int columns_solved_ = 0;
  /// Y = A⁻¹ Ê, keeping the columns of the last tangent that are still A⁻¹ Ê.
  void solve_columns(const LinearSolver& sparse, const Eigen::MatrixXd& E_hat);
  Eigen::PartialPivLU<Eigen::MatrixXd> S_;  ///< of the equilibrated D⁻¹ S D⁻¹
  Eigen::VectorXd s_scale_;                 ///< D
};

}  // namespace hpcontact::solve
