// Cylindrical arc-length: predictor along the tangent δx_F = K⁻¹ f̂ (f̂ = −∂R/∂λ) with the sign
// that continues the previous step, corrector δx = δx_R + δλ δx_F with δλ from the constraint
// ‖Δx + δx‖² = Δl² (the root whose new increment turns least from the old one).
#include "hpcontact/solve/arc_length.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "hpcontact/core/error.hpp"
#include "hpcontact/core/stop.hpp"

namespace hpcontact::solve {

namespace {

/// One arc-length step of length dl from (x, λ); on success x, λ are the new state.
bool arc_step(LoadPathSystem& system, Eigen::VectorXd& x, double& lambda, double dl,
              const Eigen::VectorXd& previous_dx, const ArcLengthOptions& o, int& iterations,
              std::string& why) {
  LinearSolver solver(o.linear_solver);
  SparseMatrix K;
  Eigen::VectorXd r;
  system.set_load_factor(lambda);
  system.evaluate(x, r, &K);
  const int n = system.path_size();
  try {
    system.factorize(solver, K);
  } catch (const NumericalError& e) {
    why = std::string("singular tangent at the start of the step: ") + e.what();
    return false;
  }
  Eigen::VectorXd f = -system.load_derivative(x);
  Eigen::VectorXd dxF = system.solve(solver, f);
  // Predictor: continue in the direction of the previous step (or of rising λ at the start).
  double sign = previous_dx.size() ? (previous_dx.head(n).dot(dxF.head(n)) >= 0 ? 1.0 : -1.0) : 1.0;
  double dlam = sign * dl / dxF.head(n).norm();
  Eigen::VectorXd Dx = dlam * dxF;
  double Dlam = dlam;
  double scale = 0;
  for (int it = 0; it < o.max_iterations; ++it) {
    system.set_load_factor(lambda + Dlam);
    system.evaluate(x + Dx, r, &K);
    const double rn = r.norm();
    if (!std::isfinite(rn)) {
      why = "the residual is not finite";
      return false;
    }
    if (it == 0) scale = std::max(rn, o.reference_norm);
    ++iterations;
    if (it > 0 && rn <= o.tolerance * scale) {
      x += Dx;
      lambda += Dlam;
      return true;
    }
    try {
      system.factorize(solver, K);
    } catch (const NumericalError& e) {
      why = std::string("singular tangent: ") + e.what();
      return false;
    }
    f = -system.load_derivative(x + Dx);
    dxF = system.solve(solver, f);
    const Eigen::VectorXd dxR = system.solve(solver, -r);
    // ‖Dx + dxR + δλ dxF‖² = dl² over the first n unknowns
    const Eigen::VectorXd u = Dx + dxR;
    const double a = dxF.head(n).squaredNorm(), b = 2 * dxF.head(n).dot(u.head(n)),
                 c = u.head(n).squaredNorm() - dl * dl;
    const double disc = b * b - 4 * a * c;
    if (!(disc >= 0) || a == 0) {
      why = "the arc-length constraint has no real root (the step length is too large here)";
      return false;
    }
    const double s = std::sqrt(disc);
    const double l1 = (-b + s) / (2 * a), l2 = (-b - s) / (2 * a);
    const Eigen::VectorXd d1 = u + l1 * dxF, d2 = u + l2 * dxF;
    const bool first = d1.head(n).dot(Dx.head(n)) >= d2.head(n).dot(Dx.head(n));
    Dx = first ? d1 : d2;
    Dlam += first ? l1 : l2;
  }
  why = "no convergence in " + std::to_string(o.max_iterations) + " iterations";
  return false;
}

}  // namespace

ArcLengthReport arc_length(LoadPathSystem& system, Eigen::VectorXd& x, double& lambda,
                           const ArcLengthOptions& options, const ArcLengthCallback& on_step) {
  ArcLengthReport rep;
  ArcLengthOptions o = options;
  double dl = o.initial_length;
  if (dl <= 0) {
    // The length of a load-controlled step: the tangent displacement for Δλ = target / steps.
    SparseMatrix K;
    Eigen::VectorXd r;
    system.set_load_factor(lambda);
    system.evaluate(x, r, &K);
    LinearSolver solver(o.linear_solver);
    system.factorize(solver, K);
    dl = std::abs((o.target - lambda) / std::max(1, o.steps)) *
         system.solve(solver, -system.load_derivative(x)).head(system.path_size()).norm();
  }
  const double min_length = o.min_length > 0 ? o.min_length : dl / 1024;
  const double max_length = o.max_length > 0 ? o.max_length : 8 * dl;
  Eigen::VectorXd previous_dx;
  while (static_cast<int>(rep.steps.size()) < o.max_steps) {
    if (stop_requested()) {
      std::ostringstream os;
      os << "the arc-length method was " << stop_reason() << " at load factor " << lambda;
      rep.message = os.str();
      return rep;
    }
    Eigen::VectorXd xt = x;
    double lt = lambda;
    int its = 0;
    std::string why;
    if (!arc_step(system, xt, lt, dl, previous_dx, o, its, why)) {
      rep.iterations += its;
      dl *= 0.5;
      if (dl < min_length) {
        std::ostringstream os;
        os << "the arc-length method cannot continue from load factor " << lambda << ": " << why
           << "; the step length fell below " << min_length;
        rep.message = os.str();
        return rep;
      }
      continue;
    }
    rep.iterations += its;
    if ((lt - o.target) * (lambda - o.target) < 0 || lt == o.target) {
      // The target lies inside this step: finish at λ = target under load control from the
      // last state.
      system.set_load_factor(o.target);
      NewtonOptions no;
      no.max_iterations = o.max_iterations;
      no.tolerance = o.tolerance;
      no.reference_norm = o.reference_norm;
      no.linear_solver = o.linear_solver;
      Eigen::VectorXd xn = x + (xt - x) * ((o.target - lambda) / (lt - lambda));
      const auto nr = newton(system, xn, no);
      rep.iterations += nr.iterations;
      if (nr.ok()) {
        x = xn;
        lambda = o.target;
        rep.steps.push_back({lambda, dl, nr.iterations});
        rep.reached = true;
        if (on_step) on_step(x, rep.steps.back());
        return rep;
      }
      // The load-controlled end did not converge: take a shorter arc towards it.
      dl *= 0.5;
      if (dl < min_length) {
        rep.message = "the last step to load factor " + std::to_string(o.target) +
                      " does not converge under load control: " + nr.message;
        return rep;
      }
      continue;
    }
    previous_dx = xt - x;
    x = xt;
    lambda = lt;
    rep.steps.push_back({lambda, dl, its});
    if (on_step && !on_step(x, rep.steps.back())) {
      rep.message = "stopped after step " + std::to_string(rep.steps.size());
      return rep;
    }
    dl = std::clamp(dl * std::sqrt(static_cast<double>(o.desired_iterations) / std::max(1, its)),
                    min_length, max_length);
  }
  rep.message = "the load factor did not reach " + std::to_string(o.target) + " in " +
                std::to_string(o.max_steps) + " arc-length steps (last " + std::to_string(lambda) + ")";
  return rep;
}

}  // namespace hpcontact::solve
