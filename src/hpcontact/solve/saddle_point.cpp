// Block elimination of the multipliers: dependent ones by their own rows, the rest by a dense
// Schur complement on an augmented sparse factorisation (see saddle_point.hpp for the algebra).
//
// With z = (z_F, z_D), the dependent rows give z_D = H_DD⁻¹ (b_D − H_DF z_F); substituted,
//   K Δu + Ẽ z_F = b_u − E_D H_DD⁻¹ b_D,     Ẽ = E_F − E_D H_DD⁻¹ H_DF,
//   G_F Δu + H̃ z_F = b_F − H_FD H_DD⁻¹ b_D,  H̃ = H_FF − H_FD H_DD⁻¹ H_DF.
// Adding G_Fᵀ Γ⁻¹ times the second to the first: A Δu + Ê z_F = b̂_u with A = K + G_Fᵀ Γ⁻¹ G_F,
// Ê = Ẽ + G_Fᵀ Γ⁻¹ H̃; so Δu = A⁻¹ b̂_u − Y z_F, Y = A⁻¹ Ê, and (H̃ − G_F Y) z_F = b̃_F − G_F A⁻¹ b̂_u.
#include "hpcontact/solve/saddle_point.hpp"

#include <cmath>
#include <sstream>

#include "hpcontact/core/error.hpp"
#include "hpcontact/core/stop.hpp"

namespace hpcontact::solve {

namespace {
using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor>;

/// Vᵀ W over the rows where both have a nonzero (the others add nothing): the columns of a
/// forward solve on a sparse right-hand side are zero outside a few rows.
Eigen::MatrixXd product_over_shared_rows(const Eigen::MatrixXd& V, const Eigen::MatrixXd& W) {
  std::vector<Eigen::Index> rows;
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    if ((V.row(i).array() != 0.0).any() && (W.row(i).array() != 0.0).any()) rows.push_back(i);
  Eigen::MatrixXd v(static_cast<Eigen::Index>(rows.size()), V.cols());
  Eigen::MatrixXd w(static_cast<Eigen::Index>(rows.size()), W.cols());
  for (size_t k = 0; k < rows.size(); ++k) {
    v.row(k) = V.row(rows[k]);
    w.row(k) = W.row(rows[k]);
  }
  return v.transpose() * w;
}
}  // namespace

void SaddlePointSolver::factorize(LinearSolver& sparse, const SparseMatrix& J, int n,
                                  const Eigen::VectorXd& gamma) {
  n_ = n;
  m_ = static_cast<int>(J.rows()) - n;
  HPC_ASSERT(m_ >= 0 && J.cols() == J.rows() && gamma.size() == m_, "saddle point blocks");
  const SparseMatrix K = J.topLeftCorner(n_, n_);
  E_ = J.topRightCorner(n_, m_);
  H_ = J.bottomRightCorner(m_, m_);
  const RowMajor G_rows = J.bottomLeftCorner(m_, n_);
  H_rows_ = H_;
  const RowMajor& H_rows = H_rows_;

  // Dependent rows: no u-part, a non-zero diagonal, and ties only to free multipliers.
  std::vector<char> dependent(m_, 0);
  for (int k = 0; k < m_; ++k) {
    bool has_g = false;
    for (RowMajor::InnerIterator it(G_rows, k); it; ++it) has_g = has_g || it.value() != 0.0;
    dependent[k] = !has_g && H_.coeff(k, k) != 0.0;
  }
  for (bool changed = true; changed;) {
    changed = false;
    for (int k = 0; k < m_; ++k) {
      if (!dependent[k]) continue;
      for (RowMajor::InnerIterator it(H_rows, k); it; ++it)
        if (it.col() != k && it.value() != 0.0 && dependent[it.col()]) {
          dependent[k] = 0;
          changed = true;
          break;
        }
    }
  }
  is_dependent_ = dependent;
  free_.clear();
  dependent_.clear();
  position_.assign(m_, -1);
  for (int k = 0; k < m_; ++k) {
    auto& set = dependent[k] ? dependent_ : free_;
    position_[k] = static_cast<int>(set.size());
    set.push_back(k);
  }
  const int nf = static_cast<int>(free_.size());
  h_dd_.resize(static_cast<Eigen::Index>(dependent_.size()));
  for (size_t i = 0; i < dependent_.size(); ++i) h_dd_(i) = H_.coeff(dependent_[i], dependent_[i]);

  // H̃ and Ẽ: the free blocks, less the ties through the dependent multipliers.
  H_tilde_ = Eigen::MatrixXd::Zero(nf, nf);
  Eigen::MatrixXd E_hat = Eigen::MatrixXd::Zero(n_, nf);
  for (int f = 0; f < nf; ++f) E_hat.col(f) = E_.col(free_[f]);
  for (int k = 0; k < m_; ++k)
    for (RowMajor::InnerIterator it(H_rows, k); it; ++it) {
      const int l = static_cast<int>(it.col());
      if (!dependent[k] && !dependent[l]) H_tilde_(position_[k], position_[l]) += it.value();
    }
  for (size_t i = 0; i < dependent_.size(); ++i) {
    const int d = dependent_[i];
    // the tie row: H_dF, and the column H_Fd that multiplies z_d in the free rows
    for (RowMajor::InnerIterator it(H_rows, d); it; ++it) {
      const int f = static_cast<int>(it.col());
      if (f == d || dependent[f]) continue;
      const double tie = it.value() / h_dd_(i);
      E_hat.col(position_[f]) -= tie * Eigen::VectorXd(E_.col(d));
      for (SparseMatrix::InnerIterator jt(H_, d); jt; ++jt)  // column d of H
        if (!dependent[jt.row()]) H_tilde_(position_[jt.row()], position_[f]) -= jt.value() * tie;
    }
  }

  // A = K + G_Fᵀ Γ⁻¹ G_F, with the pattern of every stored row of G kept. Without augmentation
  // A is K itself, no pattern of G added: it keeps its factors from one tangent to the next
  // while K does not change (LinearSolver::kept_factors).
  inv_gamma_ = Eigen::VectorXd::Zero(nf);
  if ((gamma.array() > 0).any()) {
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(K.nonZeros());
    for (int c = 0; c < K.outerSize(); ++c)
      for (SparseMatrix::InnerIterator it(K, c); it; ++it) t.emplace_back(it.row(), it.col(), it.value());
    for (int k = 0; k < m_; ++k) {
      double w = 0;
      if (!dependent[k] && gamma(k) > 0) {
        w = 1 / gamma(k);
        inv_gamma_(position_[k]) = w;
      }
      for (RowMajor::InnerIterator a(G_rows, k); a; ++a)
        for (RowMajor::InnerIterator b(G_rows, k); b; ++b)
          t.emplace_back(a.col(), b.col(), w * a.value() * b.value());
    }
    SparseMatrix A(n_, n_);
    A.setFromTriplets(t.begin(), t.end());
    sparse.factorize(std::move(A));
  } else {
    sparse.factorize(K);
  }

  RowMajor G_F(nf, n_);
  {
    std::vector<Eigen::Triplet<double>> tf;
    for (int f = 0; f < nf; ++f)
      for (RowMajor::InnerIterator it(G_rows, free_[f]); it; ++it) tf.emplace_back(f, it.col(), it.value());
    G_F.setFromTriplets(tf.begin(), tf.end());
  }
  G_F_ = G_F;
  for (int f = 0; f < nf; ++f)
    if (inv_gamma_(f) != 0)
      for (RowMajor::InnerIterator it(G_F, f); it; ++it)
        E_hat.row(it.col()) += inv_gamma_(f) * it.value() * H_tilde_.row(f);
  front_.resize(0, 0);
  if (nf == 0) {
    Y_.resize(n_, 0);
    E_hat_ = SparseMatrix(n_, 0);
    z_of_column_.clear();
    return;
  }
  Eigen::MatrixXd S;
  if (sparse.splits_solves()) {
    // G_F A⁻¹ Ê = (Bᵀ G_Fᵀ)ᵀ (F Ê): two forward solves per column, both on sparse columns.
    front_ = sparse.solve_front_columns(E_hat);
    const Eigen::MatrixXd back = sparse.solve_back_transposed_columns(Eigen::MatrixXd(G_F.transpose()));
    stop_point("factorising");  // between the columns' solves and the dense complement's LU
    S = H_tilde_ - product_over_shared_rows(back, front_);
    Y_.resize(n_, 0);
    E_hat_ = SparseMatrix(n_, 0);
    z_of_column_.clear();
    columns_factors_ = 0;
    columns_solved_ = nf;
  } else {
    solve_columns(sparse, E_hat);
    stop_point("factorising");  // between the columns' solves and the dense complement's LU
    S = H_tilde_ - G_F * Y_;
  }
  // Equilibrated, D⁻¹ S D⁻¹ with D² = |diag S|: the rows of multipliers whose boundary share is
  // small (near the axis of an axisymmetric body, ∝ r) are as well conditioned as the others,
  // and the test below sees dependence, not scale.
  s_scale_ = S.diagonal().cwiseAbs().cwiseSqrt();
  for (int i = 0; i < nf; ++i)
    if (!(s_scale_(i) > 0)) s_scale_(i) = 1;
  S_.compute(s_scale_.cwiseInverse().asDiagonal() * S * s_scale_.cwiseInverse().asDiagonal());
  HPC_REQUIRE(S.allFinite(), NumericalError, "the multiplier system is not finite (NaN or Inf): a "
              "constraint or the tangent it couples to is not finite");
  const double rcond = S_.rcond();
  if (!(rcond > 1e-14)) {
    std::ostringstream os;
    os << "the multiplier system is singular (reciprocal condition " << rcond << " of its "
       << nf << " coupled rows): constraints that repeat one another, or a force target no "
          "constraint carries";
    throw NumericalError(os.str());
  }
}

void SaddlePointSolver::solve_columns(const LinearSolver& sparse, const Eigen::MatrixXd& E_hat) {
  // A column of the last tangent's Y is A⁻¹ of its Ê column: it still is when A kept its
  // factors and the column (of the same multiplier) is unchanged — the gradient of a
  // constraint that is linear in u, the load factor's column.
  const int nf = static_cast<int>(free_.size());
  std::vector<int> column_of_z(m_, -1);
  // (the factors Y was solved with: no factorisation since, in this solver or another)
  if (sparse.factors_serial() != 0 && sparse.factors_serial() == columns_factors_)
    for (size_t c = 0; c < z_of_column_.size(); ++c)
      if (z_of_column_[c] < m_) column_of_z[z_of_column_[c]] = static_cast<int>(c);
  Eigen::MatrixXd Y(n_, nf);
  std::vector<int> fresh;
  for (int f = 0; f < nf; ++f) {
    const int c = column_of_z[free_[f]];
    if (c >= 0 && Eigen::VectorXd(E_hat_.col(c)) == E_hat.col(f)) Y.col(f) = Y_.col(c);
    else fresh.push_back(f);
  }
  if (!fresh.empty()) {
    Eigen::MatrixXd B(n_, static_cast<Eigen::Index>(fresh.size()));
    for (size_t i = 0; i < fresh.size(); ++i) B.col(i) = E_hat.col(fresh[i]);
    const Eigen::MatrixXd X = sparse.solve_columns(B);
    for (size_t i = 0; i < fresh.size(); ++i) Y.col(fresh[i]) = X.col(i);
  }
  columns_solved_ = static_cast<int>(fresh.size());
  columns_factors_ = sparse.factors_serial();
  z_of_column_ = free_;
  E_hat_ = E_hat.sparseView(0.0, 0.0);  // every nonzero, exactly: Ê's columns are sparse
  Y_.swap(Y);
}

Eigen::VectorXd SaddlePointSolver::solve(const LinearSolver& sparse, const Eigen::VectorXd& b) const {
  const int nf = static_cast<int>(free_.size()), nd = static_cast<int>(dependent_.size());
  const Eigen::VectorXd b_u = b.head(n_);
  Eigen::VectorXd zd0(nd), b_F(nf);
  for (int i = 0; i < nd; ++i) zd0(i) = b(n_ + dependent_[i]) / h_dd_(i);
  for (int f = 0; f < nf; ++f) b_F(f) = b(n_ + free_[f]);
  // b̃_u = b_u − E_D z_D⁰, b̃_F = b_F − H_FD z_D⁰ with z_D⁰ = H_DD⁻¹ b_D
  Eigen::VectorXd bt_u = b_u;
  for (int i = 0; i < nd; ++i) {
    if (zd0(i) == 0.0) continue;
    const int d = dependent_[i];
    bt_u -= zd0(i) * Eigen::VectorXd(E_.col(d));
    for (SparseMatrix::InnerIterator it(H_, d); it; ++it)  // column d of H
      if (!is_dependent_[it.row()]) b_F(position_[it.row()]) -= it.value() * zd0(i);
  }
  Eigen::VectorXd bh_u = bt_u;
  if (nf > 0) bh_u += G_F_.transpose() * inv_gamma_.cwiseProduct(b_F);
  const Eigen::VectorXd a = sparse.solve(bh_u);
  Eigen::VectorXd z_F;
  Eigen::VectorXd du = a;
  if (nf > 0) {
    z_F = S_.solve((b_F - G_F_ * a).cwiseQuotient(s_scale_)).cwiseQuotient(s_scale_);
    if (front_.cols() == nf) du -= sparse.solve_back(front_ * z_F);  // A⁻¹ Ê z_F = B (F Ê) z_F
    else du -= Y_ * z_F;
  }
  Eigen::VectorXd x(n_ + m_);
  x.head(n_) = du;
  for (int f = 0; f < nf; ++f) x(n_ + free_[f]) = z_F(f);
  // z_D = H_DD⁻¹ (b_D − H_DF z_F)
  for (int i = 0; i < nd; ++i) {
    const int d = dependent_[i];
    double v = b(n_ + d);
    for (RowMajor::InnerIterator it(H_rows_, d); it; ++it)
      if (it.col() != d) v -= it.value() * x(n_ + it.col());
    x(n_ + d) = v / h_dd_(i);
  }
  return x;
}

}  // namespace hpcontact::solve
