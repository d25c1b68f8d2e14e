// Contact solve: R(u) = K u - lambda f - f_c(u) = 0 over the free dofs, with the penalty contact
// force f_c and its consistent tangent; load steps with cut-back; secant on lambda for a target
// resultant.
#include "hpcontact/model/contact_solve.hpp"


#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/SparseLU>

#include "hpcontact/core/error.hpp"
#include "hpcontact/model/contact_solve_failure.hpp"
#include "hpcontact/model/contact_system.hpp"
#include "hpcontact/model/load_scale.hpp"
#include "hpcontact/model/rigid_motion.hpp"
#include "hpcontact/solve/arc_length.hpp"

namespace hpcontact::model {

namespace {

/// The sparse solver of the tangent's displacement block: the input's (solver.linear), with
/// CHOLMOD giving way to LU when a tangent is not positive definite (the contact's curvature
/// terms — −p_N M between two bodies, a curve obstacle's — at a deep trial penetration: not a
/// missing constraint), and LU outright where the block may be unsymmetric or indefinite: the
/// seed's difference tangent (a column straddling a point's contact switch), finite strain (a
/// body unstable under compression on its way to a stable state), friction in slip, a pair
/// pressing along the mean normal.
solve::LinearSolverKind tangent_solver(const SolverSpec& ss, const Discretization& d,
                                       const ContactSystem& system) {
  const auto kind = solve::linear_solver_kind(ss.linear, ss.where.str() + ".linear");
  if (ss.tangent == "finite-difference" || d.finite_strain() || system.has_unsymmetric_tangent())
    return solve::LinearSolverKind::lu;
  return kind == solve::LinearSolverKind::cholmod ? solve::LinearSolverKind::cholmod_else_lu : kind;
}

}  // namespace

NonlinearSolution solve_contact(const ProblemSpec& spec, const Discretization& d,
                                const ProgressFn& progress, const StartState& start,
                                const StepFn& on_step) {
  const SolverSpec& ss = spec.solver;
  auto pairs = make_contact_pairs(spec, d);
  if (!pairs.empty()) require_force_scale(spec, d, pairs.front().body, pairs.front().other);
  for (const auto& pair : pairs)
    HPC_REQUIRE(pair.other < 0 || ss.tangent == "analytic", InputError, ss.where.str(),
                ".tangent: finite-difference is implemented for rigid obstacles only; contact "
                "between two bodies needs tangent: analytic");
  ContactSystem system(d, pairs, spec.discretization.condense,
                       ss.tangent == "finite-difference" ? ContactSystem::Tangent::seed_difference
                                                         : ContactSystem::Tangent::analytic);
  solve::NewtonOptions no;
  no.max_iterations = ss.max_iterations;
  no.tolerance = ss.tolerance;
  no.linear_solver = tangent_solver(ss, d, system);
  // Auto: on with friction (stick/slip switches make plain Newton cycle) and between two bodies
  // (a large trial correction projects points onto far parts of the other boundary: the
  // bilateral Hertz example takes 200 iterations without it, 49 with it, same solution).
  const bool two_bodies = std::any_of(pairs.begin(), pairs.end(), [](const ContactPair& p) {
    return p.other >= 0 && !p.constraints;
  });
  no.line_search = ss.line_search == "on" || (ss.line_search == "auto" && (system.has_friction() || two_bodies));
  // Force control with friction: the secant on complete solves would go back and forth along
  // the load path, which friction remembers; force-controlled load steps instead (below).
  HPC_REQUIRE(!system.has_friction() || !ss.target_resultant ||
                  (!pairs.empty() && pairs.front().constraints),
              InputError, ss.where.str(),
              ".target_resultant: force control with friction needs the first contact pair "
              "enforced exactly (enforcement: augmented-lagrangian): its factor is then an "
              "unknown of every load step; the penalty's secant on complete solves would go back "
              "and forth along the load path, which friction remembers");

  NonlinearSolution sol;
  sol.elastic = system.elastic();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(system.size());
  // The monitored node's displacement dofs, if any.
  int monitor_dof = -1;
  if (!ss.monitor_body.empty()) {
    int b = -1;
    const Body& body = body_named(d, ss.monitor_body, ss.where, &b);
    const int v = body.mesh.node_index(ss.monitor_node);
    HPC_REQUIRE(v >= 0, InputError, ss.where.str(), ".monitor.node: no node ", ss.monitor_node,
                " in body '", ss.monitor_body, "'");
    monitor_dof = body.dof_offset + 2 * body.dofs.vertex_mode(v);
  }
  struct Factors {
    Vec2 displacements = Vec2::Zero();  ///< on the prescribed displacements' x and y components
    double loads = 0;
    static Factors proportional(double lambda) { return {Vec2(lambda, lambda), lambda}; }
    /// "factor 0.5", "factor 0.5 (loads 1)", "factors (0, 1) (loads 0)"
    std::string describe() const {
      std::ostringstream os;
      if (displacements.x() == displacements.y()) os << "factor " << displacements.x();
      else os << "factors (" << displacements.x() << ", " << displacements.y() << ")";
      if (loads != displacements.x() || displacements.x() != displacements.y()) os << " (loads " << loads << ")";
      return os.str();
    }
  };
  auto record = [&](const Factors& f, int iterations, double arc) {
    NonlinearSolution::PathPoint p{f.displacements.y(), f.loads, f.displacements, Vec2::Zero(),
                                   Vec2::Zero(), iterations, arc};
    const Eigen::VectorXd u = system.solution(x);
    const auto multipliers = system.multipliers(x);
    if (monitor_dof >= 0) p.monitor = Vec2(u(monitor_dof), u(monitor_dof + 1));
    if (!pairs.empty())
      p.resultant = contact_resultant(d, pairs.front(), u,
                                      multipliers[0].size() ? &multipliers[0] : nullptr);
    sol.path.push_back(p);
    if (on_step) on_step(u, p, pairs, multipliers);
  };
  // The contact results at the end (converged or not).
  auto finish = [&]() {
    sol.multipliers = system.multipliers(x);
    // x is the state committed last: its step's slips and the path's were measured then
    const auto& slips = system.step_slips();
    const auto& totals = system.total_slips();
    for (size_t k = 0; k < pairs.size(); ++k)
      sol.contact.push_back(evaluate_contact(d, pairs[k], sol.u, sol.multipliers_of(k),
                                             slips[k].size() ? &slips[k] : nullptr,
                                             totals[k].size() ? &totals[k] : nullptr));
  };
  Factors converged;  // the factors of the last converged step
  auto say = [&](const std::string& s) {
    if (progress) progress(s);
  };

  // A progress line per Newton iteration.
  auto newton_progress = [&]() -> solve::IterationCallback {
    if (!progress) return {};
    const auto began = std::chrono::steady_clock::now();
    return [&, began](int it, double rn, double dxn) {
      std::ostringstream os;
      os << "  iteration " << it << ": |R| " << rn << ", |dx| " << dxn;
      if (!pairs.empty()) os << ", " << system.points_in_contact() << " points in contact";
      os << ", " << std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count()
         << " s";
      say(os.str());
    };
  };

  // Why a Newton solve failed, with the inverted element or the unknown whose pivot vanished.
  auto failure_reason = [&](const solve::SolveReport& rep) {
    return newton_failure_reason(rep, d, pairs, system);
  };

  // Load steps along the path parameter from `from` to `target` (factors(s) gives the
  // factors), halving a step that does not converge and doubling it again, up to the nominal
  // step, after two steps in a row converged; a step is never shorter than the nominal one
  // halved max_cuts times (`cuts` counts the halvings the current step has, not those in a row:
  // a load that cannot be carried beyond some factor, e.g. a shear at the friction's capacity,
  // was otherwise approached by ever shorter steps for ever, 0.75, 0.875, 0.9375, ...). With
  // `force`, force-controlled steps: at s the factor on the prescribed displacements is the
  // unknown of the bordered system whose target is share(s) × value (factors(s) then gives its
  // first guess, and the loads' factor unless they follow the unknown).
  struct ForceControl {
    int component;
    double value;
    double share_from = 0, share_to = 1;  ///< the share of value at s = 0 and s = 1
    bool scales_loads = true;             ///< the loads' factor is the unknown too
    double share(double s) const { return share_from + s * (share_to - share_from); }
  };
  using ForceTarget = std::optional<ForceControl>;
  auto advance = [&](double from, double target, int steps, const auto& factors,
                     const ForceTarget& force = std::nullopt) -> bool {
    const double nominal = (target - from) / std::max(1, steps);
    double lambda = from, step = nominal;
    int cuts = 0, in_a_row = 0;
    std::vector<double> failed_before;  // the residuals of the last attempt that failed
    while (std::abs(target - lambda) > 1e-14 * std::max(1.0, std::abs(target))) {
      const double next = std::abs(target - lambda) < std::abs(step) * (1 + 1e-12) ? target : lambda + step;
      Factors fn = factors(next);
      system.set_factors(fn.displacements, fn.loads);
      Eigen::VectorXd trial = x;
      if (force) {
        system.set_force_target(std::make_pair(force->component, force->share(next) * force->value),
                                force->scales_loads);
        trial.conservativeResize(system.size());
        trial(system.size() - 1) = fn.displacements.y();
      }
      no.reference_norm = system.force_scale(trial);
      if (force) no.reference_norm = std::max(no.reference_norm, force->share(next) * force->value);
      const auto rep = solve::newton(system, trial, no, newton_progress());
      sol.newton_iterations += rep.iterations;
      sol.factorizations += rep.factorizations;
      if (force) {
        const double alpha = system.displacement_factor(trial);
        fn = force->scales_loads ? Factors::proportional(alpha) : Factors{Vec2(alpha, alpha), fn.loads};
        system.set_force_target(std::nullopt);
        trial.conservativeResize(system.size());
        system.set_factors(fn.displacements, fn.loads);
      }
      if (rep.ok()) {
        x = trial;
        lambda = next;
        converged = fn;
        system.commit(x);
 record(fn, rep.iterations, 0.0);
        ++sol.load_steps;
        std::ostringstream os;
        os << "load step " << sol.load_steps << ": " << fn.describe() << ", " << rep.iterations << " Newton iterations, |R| " << rep.residual_history.front()
           << " -> " << rep.residual_history.back();
        say(os.str());
        if (++in_a_row >= 2 && cuts > 0) {
          --cuts;
          step *= 2;
          in_a_row = 0;
        }
        continue;
      }
      in_a_row = 0;
      if (rep.status == solve::SolveStatus::stopped) {  // asked to stop: no cuts, keep what converged
        std::ostringstream os;
        os << "load step " << sol.load_steps + 1 << " (" << fn.describe() << "): " << rep.message;
        sol.message = os.str();
        return false;
      }
      const std::string why = failure_reason(rep);
      // A tangent made singular by a body that only contact holds (its constraints leave a
      // rigid motion free) stays singular on a shorter step when nothing has converged yet (no
      // contact holds it at all): no cuts then. After converged steps a singular tangent in
      // mid-Newton is a near-mechanism of this step (every point slipping on the way to a
      // shear near the friction's capacity, an active set that lost its last node): cut.
      bool structural = false;
      for (const Body& body : d.bodies) structural = structural || !body.free_rigid_motions.empty();
      const bool held_before = sol.load_steps > 0;
      // A shorter step that fails with the residuals of the longer one: what fails does not
      // scale with the load (an interference of the input, a state the step starts from).
      const bool unchanged = same_residuals(failed_before, rep.residual_history);
      failed_before = rep.residual_history;
      if (cuts == ss.max_cuts || unchanged ||
          (rep.status == solve::SolveStatus::singular && structural && !held_before)) {
        const bool at_capacity = cuts == ss.max_cuts && cuts > 0 && lambda != from;
        sol.message = failed_step_message({sol.load_steps + 1, fn.describe(), cuts, ss.max_cuts, why,
                                           unchanged, at_capacity, converged.describe(),
                                           at_capacity ? system.capacity_used() : std::string(),
                                           rep.residual_history});
        return false;
      }
      ++cuts;
      step *= 0.5;
      say("load step did not converge (" + why + "): cutting the step to " +
          std::to_string(step));
    }
    return true;
  };
  auto proportional = [](double lambda) { return Factors::proportional(lambda); };
  auto advance_to = [&](double from, double target) {
    return advance(from, target, ss.load_steps, proportional);
  };

  // The first factor: 1 (the displacements as prescribed) or, under force control, a factor
  // the caller expects to be close (the previous mesh's, in an adaptive loop).
  const double first = ss.target_resultant && start.factor > 0 ? start.factor : 1.0;
  double lambda = 0;
  // A failed run keeps the last converged state, marked not converged.
  std::string first_attempt;  // why force control as one system gave way, if it did
  auto failed = [&]() {
    if (!first_attempt.empty()) sol.message = first_attempt + "; then " + sol.message;
    system.set_force_target(std::nullopt);
    x.conservativeResize(system.size());
    system.set_factors(converged.displacements, converged.loads);
    sol.u = system.solution(x);
    sol.load_factor = converged.displacements.y();
    sol.displacement_factors = converged.displacements;
    sol.loads_factor = converged.loads;
    finish();
    sol.pairs = pairs;
    return sol;
  };
  // Points in contact in the unloaded state (touching: g = 0) are anchored from the start, so
  // that friction holds them in the first load step already.
  system.set_factors(0, 0);
  system.commit(x);
  // A warm start (an adaptive loop's previous solution): its dofs and multipliers, at the
  // factor force control starts from; for exactly enforced pairs without friction (whose path
  // it would skip; the penalty keeps the seed's solves from the undeformed state).
  const bool exact = std::all_of(pairs.begin(), pairs.end(),
                                 [](const ContactPair& p) { return p.constraints != nullptr; });
  const bool warm = start.u.size() == d.n_dofs && !system.has_friction() && exact && !pairs.empty();
  if (warm) {
    system.set_factors(first, first);
    x = system.unknowns(start.u, start.multipliers);
  } else {
    system.activate_touching(x);
  }
  bool secant = ss.target_resultant.has_value();  // force control by the secant on full solves
  if (ss.control == "arc-length") {
    // Prescribed displacements first (loads at 0), then the arc-length path of the loads.
    if (d.prescribed.cwiseAbs().maxCoeff() > 0 &&
        !advance(0.0, 1.0, ss.load_steps, [](double s) { return Factors{Vec2(s, s), 0}; }))
      return failed();
    system.set_factors(1, 0);
    LoadsOnPath path(system);
    solve::ArcLengthOptions ao;
    ao.steps = ss.load_steps;
    ao.max_iterations = ss.max_iterations;
    ao.tolerance = ss.tolerance;
    ao.linear_solver = solve::LinearSolverKind::lu;
    ao.reference_norm = system.load_vector().norm();
    HPC_REQUIRE(ao.reference_norm > 0, InputError, ss.where.str(),
                ".control: arc-length scales the loads, and there are none");
    double lf = 0;
    Eigen::VectorXd xa = x;
    const auto rep = solve::arc_length(path, xa, lf, ao, [&](const Eigen::VectorXd& xs,
                                                              const solve::ArcLengthStep& st) {
      x = xs;
      converged = {Vec2(1, 1), st.lambda};
      system.set_factors(1, st.lambda);
      system.commit(x);
      ++sol.load_steps;
      record(converged, st.iterations, st.length);
      std::ostringstream os;
      os << "arc-length step " << sol.load_steps << ": load factor " << st.lambda << ", "
         << st.iterations << " iterations, length " << st.length;
      say(os.str());
      return true;
    });
    sol.newton_iterations += rep.iterations;
    if (!rep.reached) {
      sol.message = rep.message;
      return failed();
    }
  } else {
    // Force control of an exactly enforced pair: the factor is one more unknown of Newton's
    // system, its equation the target resultant (bordered), from the start at once. Should that
    // not converge, the load-controlled steps and the secant below take over.
    bool bordered = ss.stages.empty() && ss.target_resultant && !pairs.empty() && pairs.front().constraints;
    // The first guess of the factor that carries `share` of the target force in a
    // force-controlled load step: the last step's, scaled by the force it carried.
    auto factor_for = [&](double share) {
      const auto& tr = *ss.target_resultant;
      if (sol.path.empty()) return first * share;
      const auto& last = sol.path.back();
      const double carried = std::abs(last.resultant(tr.component));
      return carried > 0 ? last.displacements * share * tr.value / carried : first * share;
    };
    if (bordered && system.has_friction()) {
      // With friction the path matters: load steps, each to its share of the target force,
      // the factor an unknown of each.
      const auto& tr = *ss.target_resultant;
      auto guess = [&](double s) { return Factors::proportional(factor_for(s)); };
      if (!advance(0.0, 1.0, ss.load_steps, guess, ForceControl{tr.component, tr.value}))
        return failed();
    } else if (bordered) {
      const auto& tr = *ss.target_resultant;
      const Eigen::VectorXd x0 = x;
      system.set_factors(first, first);
      system.set_force_target(std::make_pair(tr.component, tr.value));
      x.conservativeResize(system.size());
      x(system.size() - 1) = first;
      no.reference_norm = std::max(system.force_scale(x), tr.value);
      const auto rep = solve::newton(system, x, no, newton_progress());
      sol.newton_iterations += rep.iterations;
      sol.factorizations += rep.factorizations;
      const double alpha = system.displacement_factor(x);
      system.set_force_target(std::nullopt);
      x.conservativeResize(system.size());
      if (rep.ok()) {
        system.set_factors(alpha, alpha);
        converged = Factors::proportional(alpha);
        record(converged, rep.iterations, 0.0);
        ++sol.load_steps;
        std::ostringstream os;
        os << "load step " << sol.load_steps << ": factor " << alpha << " (force control), "
           << rep.iterations << " Newton iterations, |R| " << rep.residual_history.front()
           << " -> " << rep.residual_history.back();
        say(os.str());
      } else {
        first_attempt = "force control as one Newton system did not converge (" + rep.message + ")";
        say("force control as one Newton system did not converge (" + failure_reason(rep) +
            "): load steps and the secant on the factor instead");
        x = x0;
        bordered = false;
      }
    }
    // Stages under force control (an exactly enforced first pair): a stage's `displacements`
    // is the share of the target force it reaches (the factor is the unknown) while its loads go
    // linearly — e.g. press to the force, then shear at that force held.
    const bool staged_force = !ss.stages.empty() && ss.target_resultant;
    HPC_REQUIRE(!staged_force || (!pairs.empty() && pairs.front().constraints), InputError, ss.where.str(),
                ".target_resultant with stages needs the first contact pair enforced exactly "
                "(enforcement: augmented-lagrangian): the factor on the prescribed displacements is "
                "then an unknown of every load step");
    if (!bordered && ss.stages.empty()) {
      if (!advance_to(0.0, first)) return failed();
    } else if (!bordered) {
      Factors stage_start;
      for (const auto& stage : ss.stages) {
        const Factors end{Vec2(stage.displacements_x(), stage.displacements_y()), stage.loads};
        auto along = [&](double s) {
          Factors f{stage_start.displacements + s * (end.displacements - stage_start.displacements),
                    stage_start.loads + s * (end.loads - stage_start.loads)};
          if (staged_force) f.displacements.setConstant(factor_for(f.displacements.y()));  // a share
          return f;
        };
        const int steps = stage.steps > 0 ? stage.steps : ss.load_steps;
        const ForceTarget force =
            staged_force ? ForceTarget(ForceControl{ss.target_resultant->component, ss.target_resultant->value,
                                                    stage_start.displacements.y(), end.displacements.y(), false})
                         : std::nullopt;
        if (!advance(0.0, 1.0, steps, along, force)) return failed();
        stage_start = end;
      }
    }
    // the secant on complete solves only where no step held the target itself
    secant = ss.target_resultant && !bordered && !staged_force;
  }
  lambda = first;
  if (secant) {
    const auto& tr = *ss.target_resultant;
    HPC_REQUIRE(!pairs.empty(), InputError, ss.where.str(),
                ".target_resultant: needs a contact pair to measure the resultant");
    // The resultant of the last converged step, as record() took it for the load path.
    auto measured = [&]() { return std::abs(sol.path.back().resultant(tr.component)); };
    double l0 = lambda, f0 = measured() - tr.value;
    if (!(f0 + tr.value > 0)) {
      const auto multipliers = system.multipliers(x);
      throw InputError(no_force_to_scale(ss, d, pairs.front(), system.solution(x),
                                         multipliers[0].size() ? &multipliers[0] : nullptr, l0,
                                         sol.path.back().resultant));
    }
    double l1 = l0 * tr.value / (f0 + tr.value);
    for (int it = 0; it < 50; ++it) {
      if (!advance_to(lambda, l1)) return failed();
      lambda = l1;
      const double f1 = measured() - tr.value;
      std::ostringstream os;
      os << "force control: factor " << l1 << ", resultant " << f1 + tr.value << " (target "
         << tr.value << ")";
      say(os.str());
      if (std::abs(f1) <= tr.tolerance * tr.value) break;
      // The resultant grows like a power of the factor as the contact zone widens (Hertz:
      // a little faster than linearly): the secant on log F over log λ, which is exact for a
      // power law, when both points have a force; else the secant on F over λ.
      const double F0 = f0 + tr.value, F1 = f1 + tr.value;
      const double k = std::log(F1 / F0) / std::log(l1 / l0);
      const double l2 = F0 > 0 && F1 > 0 && l0 > 0 && l1 > 0 && std::isfinite(k) && k > 0.2 && k < 5
                            ? l1 * std::pow(tr.value / F1, 1 / k)
                            : l1 - f1 * (l1 - l0) / (f1 - f0);
      l0 = l1;
      f0 = f1;
      l1 = l2;
      if (it == 49) {
        sol.message = "force control did not reach the target resultant in 50 secant iterations";
        return failed();
      }
    }
  }
  system.set_force_target(std::nullopt);
  x.conservativeResize(system.size());
  system.set_factors(converged.displacements, converged.loads);
  sol.u = system.solution(x);
  sol.load_factor = converged.displacements.y();
  sol.displacement_factors = converged.displacements;
  sol.loads_factor = converged.loads;
  sol.converged = true;
  finish();
  sol.pairs = std::move(pairs);
  return sol;
}

namespace {

/// With friction, the pairs with the histories the last load step started from: what its Newton
/// iterations converged with (the committed slips would put slipping points on the cone).
std::vector<ContactPair> pairs_of_last_step(const NonlinearSolution& sol) {
  std::vector<ContactPair> pairs = sol.pairs;
  for (auto& pair : pairs)
    if (pair.memory) {
      auto before = std::make_shared<ContactPair::FrictionMemory>(*pair.memory);
      before->points = before->points_before;
      before->other_points = before->other_points_before;
      pair.memory = before;
    }
  return pairs;
}

solve::SparseMatrix tangent_at(const ProblemSpec& spec, const Discretization& d,
                               const NonlinearSolution& sol, ContactSystem::Tangent kind,
                               Eigen::VectorXd* residual) {
  const std::vector<ContactPair> pairs = pairs_of_last_step(sol);  // the system keeps a reference
  ContactSystem system(d, pairs, spec.discretization.condense, kind);
  system.set_factors(sol.displacement_factors, sol.loads_factor);
  const Eigen::VectorXd x = system.unknowns(sol.u, sol.multipliers);
  Eigen::VectorXd r;
  solve::SparseMatrix K;
  system.evaluate(x, r, &K);
  if (residual) *residual = r;
  return K;
}

}  // namespace

solve::SparseMatrix contact_tangent(const ProblemSpec& spec, const Discretization& d,
                                    const NonlinearSolution& sol, bool finite_difference,
                                    Eigen::VectorXd* residual) {
  return tangent_at(spec, d, sol,
                    finite_difference ? ContactSystem::Tangent::seed_difference
                                      : ContactSystem::Tangent::analytic,
                    residual);
}

Eigen::VectorXd multiplier_adjoint(const ProblemSpec& spec, const Discretization& d,
                                   const NonlinearSolution& sol,
                                   const std::vector<Eigen::VectorXd>& gradient) {
  const std::vector<ContactPair> pairs = pairs_of_last_step(sol);  // the system keeps a reference
  // the solve's own elastic operator (of d), not assembled again
  ContactSystem system(d, pairs, spec.discretization.condense, ContactSystem::Tangent::analytic,
                       sol.elastic);
  system.set_factors(sol.displacement_factors, sol.loads_factor);
  // Force control held the first pair's resultant: the functional's change at a fixed force
  // (through stages the loads at theirs, the factor on the displacements alone the unknown).
  const auto& tr = spec.solver.target_resultant;
  const bool bordered = tr && !sol.pairs.empty() && sol.pairs.front().constraints;
  if (bordered)
    system.set_force_target(std::make_pair(tr->component, tr->value), spec.solver.stages.empty());
  const Eigen::VectorXd x = system.unknowns(sol.u, sol.multipliers);
  Eigen::VectorXd r;
  solve::SparseMatrix A;
  system.evaluate(x, r, &A);
  Eigen::VectorXd g = system.unknowns(Eigen::VectorXd::Zero(sol.u.size()), gradient);
  if (bordered) g(g.size() - 1) = 0;
  // Aᵀ by a sparse LU with pivoting, not by the system's saddle-point solver: that one
  // eliminates the multipliers by a Schur complement equilibrated by its diagonal, built for A's
  // pattern, and on Aᵀ of two cylinders under force control the complement looked singular
  // (reciprocal condition 2e-15) where Aᵀ is not (its smallest singular value 6e-4 of the
  // largest 3e6): the force row has a u-part in Aᵀ and none in A, its diagonal in the complement
  // is a rounding rest (1e-12 beside entries of 161, at p = 2), and the equilibration by the
  // diagonal's root blew that row up (the complement itself: condition 8e6). The goal-oriented
  // weights were then left out.
  const solve::SparseMatrix At = A.transpose();
  Eigen::SparseLU<solve::SparseMatrix, Eigen::COLAMDOrdering<int>> lu;
  lu.compute(At);
  HPC_REQUIRE(lu.info() == Eigen::Success, NumericalError, "the adjoint of the contact problem: its "
              "matrix (the transposed Newton tangent, ", At.rows(), " unknowns) is singular: ",
              lu.lastErrorMessage());
  const Eigen::VectorXd z = lu.solve(g);
  HPC_REQUIRE(z.allFinite(), NumericalError, "the adjoint of the contact problem: its solution is "
              "not finite (the transposed Newton tangent is singular)");
  return system.homogeneous_field(z);
}

solve::SparseMatrix residual_jacobian_by_differences(const ProblemSpec& spec, const Discretization& d,
                                                     const NonlinearSolution& sol) {
  return tangent_at(spec, d, sol, ContactSystem::Tangent::central_difference, nullptr);
}

}  // namespace hpcontact::model
