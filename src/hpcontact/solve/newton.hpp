// Newton–Raphson for R(x) = 0 with a sparse tangent; knows residuals and tangents, no FE.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/solve/linear_solver.hpp"

namespace hpcontact::solve {

/// A nonlinear system R(x) = 0 and its tangent dR/dx.
class NonlinearSystem {
public:
  virtual ~NonlinearSystem() = default;
  virtual int size() const = 0;
  /// R(x) into r; if K is not null, the tangent dR/dx into *K.
  virtual void evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, SparseMatrix* K) = 0;
  /// Factorises a tangent K that evaluate() formed, with `sparse` (kept by the caller from one
  /// tangent to the next, so a repeated sparsity pattern is analysed once); NumericalError when
  /// it is singular. A system whose tangent has a structure to exploit (multipliers) overrides
  /// this and solve() together.
  virtual void factorize(LinearSolver& sparse, const SparseMatrix& K) { sparse.factorize(K); }
  /// K⁻¹ b with the tangent factorize() took last.
  virtual Eigen::VectorXd solve(const LinearSolver& sparse, const Eigen::VectorXd& b) const {
    return sparse.solve(b);
  }
  /// Whether the piecewise structure of the system (an active set) was the same at the last two
  /// tangents: a semi-smooth system has converged only when the step that led to the current
  /// state was solved with the state's own active set.
  virtual bool settled() const { return true; }
  /// What a failure message should add about the last state evaluated (e.g. the contact
  /// constraints still violated); empty if nothing.
  virtual std::string describe() const { return {}; }
  /// The fraction τ ∈ (0, 1] of the correction dx at x that the system admits (a trust region on
  /// some unknowns); Newton takes τ dx.
  virtual double admissible_step(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) const {
    return 1;
  }
};

struct NewtonOptions {
  int max_iterations = 30;
  /// Converged when ||R|| <= tolerance · max(||R_0||, reference_norm) and the last correction is
  /// small (||dx|| <= tolerance · ||x||), or ||R|| == 0.
  double tolerance = 1e-10;
  double reference_norm = 0;  ///< scale of R when R_0 is tiny (e.g. the norm of the external load)
  LinearSolverKind linear_solver = LinearSolverKind::cholmod;
  /// Backtrack a correction that does not reduce |R| (halving, up to 10 times).
  bool line_search = false;
};

/// stopped: a stop was requested (core/stop.hpp) before an iteration, or inside one (a stop
/// point of its assembly or factorisation: the iteration is abandoned); x is the last iterate
/// (or a correction being halved back towards it, as far as it got).
enum class SolveStatus { converged, max_iterations, not_finite, singular, stopped };

/// Outcome of a solve; non-convergence is a status, not an exception.
struct SolveReport {
  SolveStatus status = SolveStatus::max_iterations;
  std::string message;
  int iterations = 0;
  /// Numeric factorisations of the tangent (LinearSolver::factorizations: a tangent equal to
  /// the last keeps its factors and is not counted).
  int factorizations = 0;
  int backtracks = 0;  ///< corrections halved because the residual was not finite there
  int line_searches = 0;  ///< corrections shortened by the line search
  int damped_steps = 0;   ///< corrections shortened to what the system admits
  std::vector<double> residual_history;  ///< ||R|| before each iteration, and at the end
  int singular_row = -1;  ///< status singular: the unknown whose pivot vanished, if known
  bool ok() const { return status == SolveStatus::converged; }
};

/// Called after each iteration with (iteration, ||R||, ||dx||, the fraction of the Newton
/// correction taken: < 1 where the line search or admissible_step shortened it).
using IterationCallback = std::function<void(int, double, double, double)>;

/// Newton's method from the initial guess in x (updated in place).
SolveReport newton(NonlinearSystem& system, Eigen::VectorXd& x, const NewtonOptions& options,
                   const IterationCallback& callback = {});

}  // namespace hpcontact::solve
