// Plain Newton–Raphson with a full tangent refactorised every iteration (one equal to the last
// keeps its factors: LinearSolver).
#include "hpcontact/solve/newton.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "hpcontact/core/error.hpp"
#include "hpcontact/core/stop.hpp"

namespace hpcontact::solve {

SolveReport newton(NonlinearSystem& system, Eigen::VectorXd& x, const NewtonOptions& options,
                   const IterationCallback& callback) {
  SolveReport report;
  Eigen::VectorXd r(system.size());
  SparseMatrix K;
  LinearSolver solver(options.linear_solver);
  double scale = 0;
  Eigen::VectorXd dx;
  bool evaluated = false;  // r and K already hold the state x (the line search's full step)
  // A stop inside an iteration (a stop point of the assembly or the factorisation: at high
  // degree one iteration is seconds of work) abandons it: the solve ends as stopped at the last
  // iterate (or, inside the halving of a correction that left the admissible states, at the
  // last state it was halved back to).
  const StoppableWork stoppable;
  int it = 0;
  try {
    for (;; ++it) {
      if (stop_requested()) {
        report.status = SolveStatus::stopped;
        report.message =
            std::string(stop_reason()) + " before Newton iteration " + std::to_string(it);
        report.iterations = it;
        return report;
      }
      if (!evaluated) system.evaluate(x, r, &K);
      evaluated = false;
      double rn = r.norm();
      // A correction that leaves the admissible states (an element turned inside out under finite
      // strain: no residual there) is halved back towards the last state, up to kBacktracks times.
      constexpr int kBacktracks = 12;
      for (int b = 0; b < kBacktracks && it > 0 && !std::isfinite(rn); ++b) {
        dx *= 0.5;
        x -= dx;
        ++report.backtracks;
        system.evaluate(x, r, &K);
        rn = r.norm();
      }
      report.residual_history.push_back(rn);
      if (!std::isfinite(rn)) {
        report.status = SolveStatus::not_finite;
        report.message = "the residual is not finite (NaN or Inf) at iteration " + std::to_string(it);
        return report;
      }
      if (it == 0) scale = std::max(rn, options.reference_norm);
      if (rn == 0.0 || (it > 0 && rn <= options.tolerance * scale && system.settled())) {
        report.status = SolveStatus::converged;
        report.iterations = it;
        return report;
      }
      if (it == options.max_iterations) {
        std::ostringstream os;
        os << "no convergence in " << it << " iterations: |R| = " << rn << " (tolerance "
           << options.tolerance * scale << ")";
        if (const std::string state = system.describe(); !state.empty()) os << "; " << state;
        report.status = SolveStatus::max_iterations;
        report.message = os.str();
        report.iterations = it;
        return report;
      }
      try {
        system.factorize(solver, K);
        report.factorizations = solver.factorizations();
      } catch (const NumericalError& e) {
        report.factorizations = solver.factorizations();
        report.status = SolveStatus::singular;
        report.message = e.what();
        report.singular_row = solver.last_singular_row();
        report.iterations = it;
        return report;
      }
      dx = system.solve(solver, -r);
      double taken = 1;  // of the Newton correction
      if (const double tau = system.admissible_step(x, dx); tau < 1) {
        dx *= tau;
        taken = tau;
        ++report.damped_steps;
      }
      if (options.line_search) {
        // Backtracking on |R|: the full correction unless it fails to reduce the residual, else
        // the first of ½, ¼, ... that does (or the best of them). The full step is evaluated
        // with its tangent, kept for the next iteration when it is taken (the usual case); the
        // shorter ones without.
        Eigen::VectorXd r_full, rt;
        SparseMatrix K_full;
        double best = std::numeric_limits<double>::infinity(), alpha = 1, best_alpha = 1;
        for (int k = 0; k < 10; ++k, alpha *= 0.5) {
          if (k == 0) system.evaluate(x + dx, r_full, &K_full);
          else system.evaluate(x + alpha * dx, rt, nullptr);
          const double rtn = (k == 0 ? r_full : rt).norm();
          if (rtn < best) {
            best = rtn;
            best_alpha = alpha;
          }
          if (rtn <= (1 - 1e-4 * alpha) * rn) break;
        }
        if (best_alpha < 1) {
          ++report.line_searches;
        } else {
          r.swap(r_full);
          K.swap(K_full);
          evaluated = true;
        }
        dx *= best_alpha;
        taken *= best_alpha;
      }
      x += dx;
      if (callback) callback(it + 1, rn, dx.norm(), taken);
    }
  } catch (const Stopped& e) {
    report.status = SolveStatus::stopped;
    report.message = std::string(stop_reason()) + " in Newton iteration " + std::to_string(it) +
                     " (while " + e.doing() + ")";
    report.iterations = it;
    report.factorizations = solver.factorizations();
    return report;
  }
}

}  // namespace hpcontact::solve
