// CHOLMOD supernodal Cholesky through Eigen's wrapper, Eigen's SimplicialLDLT as alternative, and
// UMFPACK's LU for matrices that are not symmetric positive definite.
#include "hpcontact/solve/linear_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <Eigen/UmfPackSupport>

#include "hpcontact/core/error.hpp"

namespace hpcontact::solve {

struct LinearSolver::Impl {
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> cholmod;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt;
  Eigen::UmfPackLU<SparseMatrix> lu;
};

LinearSolverKind linear_solver_kind(const std::string& name, const std::string& where) {
  if (name == "cholmod") return LinearSolverKind::cholmod;
  if (name == "ldlt") return LinearSolverKind::ldlt;
  if (name == "lu") return LinearSolverKind::lu;
  throw InputError(where + ": unknown linear solver '" + name + "' (expected cholmod, ldlt or lu)");
}

LinearSolver::LinearSolver(LinearSolverKind kind) : kind_(kind), impl_(std::make_unique<Impl>()) {
  impl_->cholmod.cholmod().print = 0;  // failures are reported through info(), not printed
}
LinearSolver::~LinearSolver() = default;
LinearSolver::LinearSolver(LinearSolver&&) noexcept = default;
LinearSolver& LinearSolver::operator=(LinearSolver&&) noexcept = default;

void LinearSolver::factorize(const SparseMatrix& A) {
  bool ok;
  if (kind_ == LinearSolverKind::cholmod) {
    impl_->cholmod.compute(A);
    ok = impl_->cholmod.info() == Eigen::Success;
  } else if (kind_ == LinearSolverKind::ldlt) {
    impl_->ldlt.compute(A);
    ok = impl_->ldlt.info() == Eigen::Success && (impl_->ldlt.vectorD().array() > 0).all();
  } else {
    impl_->lu.compute(A);
    ok = impl_->lu.info() == Eigen::Success;
  }
  HPC_REQUIRE(ok, NumericalError,
              "the stiffness matrix is singular or not positive definite: a body is not "
              "constrained against rigid-body motion, or an element is degenerate");
}

Eigen::VectorXd LinearSolver::solve(const Eigen::VectorXd& b) const {
  switch (kind_) {
    case LinearSolverKind::cholmod: return impl_->cholmod.solve(b);
    case LinearSolverKind::ldlt: return impl_->ldlt.solve(b);
    case LinearSolverKind::lu: break;
  }
  return impl_->lu.solve(b);
}

}  // namespace hpcontact::solve
