// Contact solve: R(u) = K u - lambda f - f_c(u) = 0 over the free dofs, with the penalty contact
// force f_c and its consistent tangent; load steps with cut-back; force control by the bordered
// system or the secant on lambda for a target resultant; the arc-length method on the loads.
#include "hpcontact/model/contact_solve.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/SparseLU>

#include "hpcontact/core/error.hpp"
#include "hpcontact/model/contact_solve_failure.hpp"
#include "hpcontact/model/contact_system.hpp"
#include "hpcontact/model/follower_forces.hpp"
#include "hpcontact/model/load_scale.hpp"
#include "hpcontact/model/memory_points.hpp"
#include "hpcontact/solve/arc_length.hpp"

namespace hpcontact::model {

namespace {

/// The sparse solver of the tangent's displacement block: the input's (solver.linear), with
/// CHOLMOD giving way to LU at the first tangent that is not symmetric to round-off or not
/// positive definite (solve::LinearSolverKind::cholmod_else_lu): the contact's curvature terms
/// (−p_N M between two bodies, a curve obstacle's) at a deep trial penetration, a finite-strain
/// body unstable under compression on its way to a stable state, friction in slip, a pair
/// pressing along the mean normal. With finite strain the block is symmetric as long as the
/// contact is enforced exactly (its multipliers' unsymmetric rows are the Schur complement's),
/// and CHOLMOD factorises it in about a third of LU's time. LU outright for the seed's
/// difference tangent (a column straddling a point's contact switch), where the input asks for
/// ldlt with finite strain, and for friction or the mean normal at small strain (kept from
/// before the test of symmetry: those paths' Newton iterates, and so their results at the level
/// of Newton's tolerance, stay as they were).
solve::LinearSolverKind tangent_solver(const SolverSpec& ss, const Discretization& d,
                                       const ContactSystem& system) {
  const auto kind = solve::linear_solver_kind(ss.linear, ss.where.str() + ".linear");
  if (ss.tangent == "finite-difference") return solve::LinearSolverKind::lu;
  if (d.finite_strain())
    return kind == solve::LinearSolverKind::cholmod ? solve::LinearSolverKind::cholmod_else_lu
                                                    : solve::LinearSolverKind::lu;
  if (system.has_unsymmetric_tangent()) return solve::LinearSolverKind::lu;
  return kind == solve::LinearSolverKind::cholmod ? solve::LinearSolverKind::cholmod_else_lu : kind;
}

/// The problem's contact pairs, checked against the solver's settings: the target force's scale,
/// the difference tangent for rigid obstacles only.
std::vector<ContactPair> checked_pairs(const ProblemSpec& spec, const Discretization& d) {
  const SolverSpec& ss = spec.solver;
  auto pairs = make_contact_pairs(spec, d);
  if (!pairs.empty()) require_force_scale(spec, d, pairs.front().body, pairs.front().other);
  for (const auto& pair : pairs)
    HPC_REQUIRE(pair.other < 0 || ss.tangent == "analytic", InputError, ss.where.str(),
                ".tangent: finite-difference is implemented for rigid obstacles only; contact "
                "between two bodies needs tangent: analytic");
  return pairs;
}

/// Newton's options for the load steps (its reference norm is set per step).
solve::NewtonOptions newton_options(const SolverSpec& ss, const Discretization& d,
                                    const ContactSystem& system,
                                    const std::vector<ContactPair>& pairs) {
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
  return no;
}

/// The first displacement dof (x, y next to it) of solver.monitor's node, -1 if none.
int monitored_dof(const SolverSpec& ss, const Discretization& d) {
  if (ss.monitor_body.empty()) return -1;
  int b = -1;
  const Body& body = body_named(d, ss.monitor_body, ss.where, &b);
  const int v = body.mesh.node_index(ss.monitor_node);
  HPC_REQUIRE(v >= 0, InputError, ss.where.str(), ".monitor.node: no node ", ss.monitor_node,
              " in body '", ss.monitor_body, "'");
  return body.dof_offset + 2 * body.dofs.vertex_mode(v);
}

/// The factors of a point on the load path.
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
/// The factors at a value of the path parameter.
using FactorsAt = std::function<Factors(double)>;

/// Force-controlled load steps: at the path parameter s the factor on the prescribed
/// displacements is the unknown of the bordered system whose target is share(s) × value.
struct ForceControl {
  int component;
  double value;
  double share_from = 0, share_to = 1;  ///< the share of value at s = 0 and s = 1
  bool scales_loads = true;             ///< the loads' factor is the unknown too
  double share(double s) const { return share_from + s * (share_to - share_from); }
};
using ForceTarget = std::optional<ForceControl>;

/// The secant's next factor towards the target force, from the factors l0, l1 and their
/// resultants' misses f0, f1 (resultant − target).
double secant_factor(double l0, double f0, double l1, double f1, double target) {
  // The resultant grows like a power of the factor as the contact zone widens (Hertz:
  // a little faster than linearly): the secant on log F over log λ, which is exact for a
  // power law, when both points have a force; else the secant on F over λ.
  const double F0 = f0 + target, F1 = f1 + target;
  const double k = std::log(F1 / F0) / std::log(l1 / l0);
  return F0 > 0 && F1 > 0 && l0 > 0 && l1 > 0 && std::isfinite(k) && k > 0.2 && k < 5
             ? l1 * std::pow(target / F1, 1 / k)
             : l1 - f1 * (l1 - l0) / (f1 - f0);
}

/// How the progress names a load step: the input's number (a cut step keeps it, its parts say
/// so), and the input's load steps of the path (0: not known beforehand).
struct StepLabel {
  int number = 0;
  bool part = false;
  int of = 0;
  std::string name() const {
    return "load step " + std::to_string(number) + (part ? " (a part of it, cut)" : "");
  }
};

/// The contact problem along its load path: the contact system, its unknowns and the solution
/// built step by step, which the path's steps share. A failed path keeps the last converged
/// state, marked not converged.
class LoadPath {
public:
  LoadPath(const ProblemSpec& spec, const Discretization& d, const ProgressFn& progress,
           const StartState& start, const StepFn& on_step);
  LoadPath(const LoadPath&) = delete;  // the system keeps a reference to pairs_
  LoadPath& operator=(const LoadPath&) = delete;

  /// Follows the load path to its end (once).
  NonlinearSolution solve();

private:
  // The path's parts, each documented at its definition. Those returning bool: whether they
  // got to their end (if not, sol_.message says why).
  void say(const ProgressEvent& e) const {
    if (progress_) progress_(e);
  }
  void say_step(const StepLabel& label, const std::string& detail, const solve::SolveReport& rep) const;
  int planned_steps() const;
  solve::IterationCallback newton_progress() const;
  solve::SolveReport newton(Eigen::VectorXd& x);
  solve::SolveReport penetrating_newton(Eigen::VectorXd& x);
  void add_force_target(int component, double value, bool scales_loads, Eigen::VectorXd& x,
                        double guess);
  void drop_force_target(Eigen::VectorXd& x);
  void record(const Factors& f, int iterations, double arc);
  void record_stick_slip(const Eigen::VectorXd& u, const std::vector<Eigen::VectorXd>& multipliers);
  void set_out();
  bool advance(double from, double target, int steps, const FactorsAt& factors,
               const ForceTarget& force = std::nullopt);
  bool advance_to(double from, double target) {
    return advance(from, target, ss_.load_steps, Factors::proportional);
  }
  /// A load step's Newton solve: the unknowns it ended at, the factors it reached, its report.
  struct StepAttempt {
    Eigen::VectorXd x;
    Factors factors;
    solve::SolveReport report;
    double s = 0;  ///< the path parameter it ended at
  };
  /// The start state's guess for the step ending at s of the current segment, or null.
  const NonlinearSolution::StepState* path_guess(double s) const;
  /// |R(x)| at the current factors.
  double residual_norm(const Eigen::VectorXd& x);
  /// A converged step of the path: its segment, path parameter and unknowns.
  struct ConvergedStep {
    int segment = -1;
    double s = 0;
    Eigen::VectorXd x;
  };
  /// The last two converged steps (the older first), for the predictor.
  std::vector<ConvergedStep> last_steps_;
  /// The predictor of a finite-strain path: the unknowns at s extrapolated linearly from the
  /// last two converged steps of the current segment; nothing if there are fewer, or no finite
  /// strain (a linear body's first Newton step from the last state is exact already but for
  /// the contact's active set).
  std::optional<Eigen::VectorXd> predicted(double s) const;
  int segment_ = -1;  ///< the path's segment under way (advance() calls so far, less one)
  StepAttempt attempt_step(double s, const FactorsAt& factors, const ForceTarget& force,
                           const Eigen::VectorXd* start = nullptr);
  std::optional<StepAttempt> continue_to(double from, double next, const FactorsAt& factors,
                                         const ForceTarget& force, const std::string& name);
  int input_steps_before_ = 0;  ///< the input's load steps of the stages already solved
  void accept_step(StepAttempt attempt, const StepLabel& name);
  bool arc_length_path();
  bool accept_arc_length_step(const Eigen::VectorXd& x, const solve::ArcLengthStep& st);
  double factor_for(double share) const;
  bool force_controlled_steps();
  bool force_control_at_once();
  bool staged_path();
  bool secant_on_factor();
  NonlinearSolution result(bool converged);

  const SolverSpec& ss_;
  const Discretization& d_;
  const ProgressFn& progress_;
  const StartState& start_;
  const StepFn& on_step_;
  std::vector<ContactPair> pairs_;
  ContactSystem system_;
  solve::NewtonOptions newton_options_;
  NonlinearSolution sol_;
  Eigen::VectorXd x_;    ///< the unknowns: of the last converged step, or of a start state
  int monitor_dof_ = -1;  ///< the monitored node's displacement dofs, if any
  Factors converged_;     ///< the factors of the last converged step
  /// The first factor: 1 (the displacements as prescribed) or, under force control, a factor
  /// the caller expects to be close (the previous mesh's, in an adaptive loop).
  double first_ = 1;
  std::string first_attempt_;  ///< why force control as one system gave way, if it did
  /// When the path set out, for the progress (a solve's elapsed time).
  std::chrono::steady_clock::time_point began_ = std::chrono::steady_clock::now();
};

LoadPath::LoadPath(const ProblemSpec& spec, const Discretization& d, const ProgressFn& progress,
                   const StartState& start, const StepFn& on_step)
    : ss_(spec.solver), d_(d), progress_(progress), start_(start), on_step_(on_step),
      pairs_(checked_pairs(spec, d)),
      system_(d, pairs_, spec.discretization.condense,
              ss_.tangent == "finite-difference" ? ContactSystem::Tangent::seed_difference
                                                 : ContactSystem::Tangent::analytic),
      newton_options_(newton_options(ss_, d, system_, pairs_)) {
  // Force control with friction: the secant on complete solves would go back and forth along
  // the load path, which friction remembers; force-controlled load steps instead (below).
  HPC_REQUIRE(!system_.has_friction() || !ss_.target_resultant ||
                  (!pairs_.empty() && pairs_.front().constraints),
              InputError, ss_.where.str(),
              ".target_resultant: force control with friction needs the first contact pair "
              "enforced exactly (enforcement: augmented-lagrangian): its factor is then an "
              "unknown of every load step; the penalty's secant on complete solves would go back "
              "and forth along the load path, which friction remembers");
  sol_.elastic = system_.elastic();
  x_ = Eigen::VectorXd::Zero(system_.size());
  monitor_dof_ = monitored_dof(ss_, d);
  first_ = ss_.target_resultant && start.factor > 0 ? start.factor : 1.0;
}

NonlinearSolution LoadPath::solve() {
  set_out();
  bool secant = ss_.target_resultant.has_value();  // force control by the secant on full solves
  if (ss_.control == "arc-length") {
    if (!arc_length_path()) return result(false);
  } else {
    // Force control of an exactly enforced pair: the factor is one more unknown of Newton's
    // system, its equation the target resultant (bordered), from the start at once. Should that
    // not converge, the load-controlled steps and the secant below take over.
    bool bordered = ss_.stages.empty() && ss_.target_resultant && !pairs_.empty() && pairs_.front().constraints;
    if (bordered && system_.has_friction()) {
      if (!force_controlled_steps()) return result(false);
    } else if (bordered) {
      bordered = force_control_at_once();
    }
    if (!bordered && (ss_.stages.empty() ? !advance_to(0.0, first_) : !staged_path()))
      return result(false);
    // the secant on complete solves only where no step held the target itself (stages under
    // force control hold it in every step)
    secant = ss_.target_resultant && !bordered && ss_.stages.empty();
  }
  if (secant && !secant_on_factor()) return result(false);
  return result(true);
}

// A progress line per Newton iteration.
solve::IterationCallback LoadPath::newton_progress() const {
  if (!progress_) return {};
  const auto began = std::chrono::steady_clock::now();
  return [this, began](int it, double rn, double dxn, double step) {
    IterationProgress p{it, rn, dxn, pairs_.empty() ? -1 : system_.points_in_contact(),
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count(),
                        step, system_.states_changed()};
    std::ostringstream os;
    os << "  iteration " << it << ": |R| " << rn << ", |dx| " << dxn;
    if (step < 1) os << " (" << step << " of the correction)";
    if (p.points_in_contact >= 0) os << ", " << p.points_in_contact << " points in contact";
    if (p.states_changed >= 0) os << " (" << p.states_changed << " multiplier states changed)";
    os << ", " << p.seconds << " s";
    say({os.str(), p});
  };
}

/// The input's load steps of the path as planned: the stages' or solver.load_steps (the
/// prescribed displacements' steps before an arc-length path); force control as one system
/// takes one.
int LoadPath::planned_steps() const {
  if (ss_.control == "arc-length") return 0;
  if (ss_.stages.empty()) return std::max(1, ss_.load_steps);
  int n = 0;
  for (const auto& stage : ss_.stages) n += std::max(1, stage.steps > 0 ? stage.steps : ss_.load_steps);
  return n;
}

/// A converged load step's progress line "<name>: <detail>" and its figures.
void LoadPath::say_step(const StepLabel& label, const std::string& detail,
                        const solve::SolveReport& rep) const {
  if (!progress_) return;
  LoadStepProgress p;
  p.step = label.number;
  p.of = label.of;
  p.part = label.part;
  p.detail = detail;
  p.newton_iterations = rep.iterations;
  p.residual = rep.residual_history.empty() ? 0.0 : rep.residual_history.back();
  p.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began_).count();
  say({label.name() + ": " + detail, p});
}

/// Newton's method on the system from x, counted in the solution. With pressures that
/// penetrate up to a contact zone, their fronts are held through Newton's iterations and moved
/// between solves to where the converged state puts them, until they stay (penetrating_newton).
solve::SolveReport LoadPath::newton(Eigen::VectorXd& x) {
  // (a pressure not yet applied moves nothing wherever its front is: a squeeze before it)
  if (system_.has_penetration() && system_.loads_factor(x) != 0.0) return penetrating_newton(x);
  const auto rep = solve::newton(system_, x, newton_options_, newton_progress());
  sol_.newton_iterations += rep.iterations;
  sol_.factorizations += rep.factorizations;
  return rep;
}

// Moved within Newton's iterations, a front follows iterates that are not states: one whose
// seal has opened for a moment wets the whole outline, a state an incompressible ring does not
// feel, and Newton settles on it (a seal "leaking" at 4.75 N/mm² whose last step held 6.88).
// Held, each solve is smooth in the load; the front starts where the state the step starts from
// puts it at the step's factors and moves to where each converged state puts it.
solve::SolveReport LoadPath::penetrating_newton(Eigen::VectorXd& x) {
  constexpr int kRounds = 12;
  system_.freeze_wet_ranges_at_next_evaluation();  // Newton's first: the start state's fronts
  Eigen::VectorXd r;
  solve::SolveReport total;
  // A later solve starts from a converged state: its tolerance is the first one's (relative to
  // the step's own residual, not to the round-off it starts from).
  const double reference = newton_options_.reference_norm;
  struct Restore {
    solve::NewtonOptions& o;
    double v;
    ~Restore() { o.reference_norm = v; }
  } restore{newton_options_, reference};
  for (int round = 0;; ++round) {
    auto rep = solve::newton(system_, x, newton_options_, newton_progress());
    if (round == 0 && !rep.residual_history.empty())
      newton_options_.reference_norm = std::max(reference, rep.residual_history.front());
    const std::vector<WetRange> fronts = system_.wet_ranges();
    system_.thaw_wet_ranges();
    sol_.newton_iterations += rep.iterations;
    sol_.factorizations += rep.factorizations;
    rep.iterations += total.iterations;
    rep.factorizations += total.factorizations;
    total = rep;
    if (!rep.ok()) return rep;
    system_.evaluate(x, r, nullptr);
    const auto& moved = system_.wet_ranges();
    bool same = true;
    for (std::size_t i = 0; i < fronts.size(); ++i)
      same = same && fronts[i].from == moved[i].from && fronts[i].to == moved[i].to && fronts[i].leaks == moved[i].leaks;
    if (same) return rep;
    system_.freeze_wet_ranges(moved);
    if (round + 1 == kRounds) {
      system_.thaw_wet_ranges();
      rep.status = solve::SolveStatus::max_iterations;
      std::ostringstream os;
      os << "the fronts of the penetrating pressures did not settle in " << kRounds
         << " solves (each converged state moved them:";
      for (std::size_t i = 0; i < fronts.size(); ++i) {
        const FollowerLoad& L = d_.follower_loads[i];
        const WetExtent a = wetted_extent(d_, L, fronts[i]), b = wetted_extent(d_, L, moved[i]);
        if (a.length != b.length || fronts[i].leaks != moved[i].leaks)
          os << " " << L.where << ": wetted length " << a.length
             << (fronts[i].leaks ? " (leaking)" : "") << " to " << b.length << (moved[i].leaks ? " (leaking)" : "") << ";";
      }
      os << " the contact pressure at the front is about the fluid's: the seal is at its limit there)";
      rep.message = os.str();
      rep.residual_history.clear();  // each solve converged: not a slow Newton
      return rep;
    }
  }
}

/// Makes the factor on the prescribed displacements the unknown of the bordered system, whose
/// row is the target resultant `value` in `component`; x gains that unknown, at `guess`.
void LoadPath::add_force_target(int component, double value, bool scales_loads,
                                Eigen::VectorXd& x, double guess) {
  system_.set_force_target(std::make_pair(component, value), scales_loads);
  x.conservativeResize(system_.size());
  x(system_.size() - 1) = guess;
}

/// Back to load control: x loses the factor's unknown.
void LoadPath::drop_force_target(Eigen::VectorXd& x) {
  system_.set_force_target(std::nullopt);
  x.conservativeResize(system_.size());
}

/// A point of the load path at the converged state x_, passed on to on_step.
void LoadPath::record(const Factors& f, int iterations, double arc) {
  NonlinearSolution::PathPoint p{f.displacements.y(), f.loads, f.displacements, Vec2::Zero(),
                                 Vec2::Zero(), iterations, arc};
  const Eigen::VectorXd u = system_.solution(x_);
  const auto multipliers = system_.multipliers(x_);
  if (monitor_dof_ >= 0) p.monitor = Vec2(u(monitor_dof_), u(monitor_dof_ + 1));
  if (!pairs_.empty())
    p.resultant = contact_resultant(d_, pairs_.front(), u,
                                    multipliers[0].size() ? &multipliers[0] : nullptr);
  sol_.path.push_back(p);
  record_stick_slip(u, multipliers);
  if (on_step_) on_step_(u, p, pairs_, multipliers);
}

/// The stick–slip points of the exact Coulomb pairs at the converged state u (their step's
/// slips committed) and where they stick and slip: NonlinearSolution::stick_slip_history.
void LoadPath::record_stick_slip(const Eigen::VectorXd& u, const std::vector<Eigen::VectorXd>& multipliers) {
  const auto& slips = system_.step_slips();
  NonlinearSolution::StepStickSlip step;
  for (auto* v : {&step.stuck, &step.slipped}) v->resize(pairs_.size());
  step.own.resize(pairs_.size());
  step.other.resize(pairs_.size());
  bool any = false;
  for (size_t k = 0; k < pairs_.size(); ++k) {
    if (slips[k].size() == 0 || multipliers[k].size() == 0) continue;
    const ContactResult c = evaluate_contact(d_, pairs_[k], u, &multipliers[k], &slips[k]);
    step.own[k] = c.stick_slip;
    step.other[k] = c.other_stick_slip;
    for (size_t i = 0; i < c.states.size(); ++i) {
      const auto state = contact::contact_state(c.states[i]);
      if (state == contact::ContactState::stick) step.stuck[k].push_back(c.s[i]);
      if (state == contact::ContactState::slip) step.slipped[k].push_back(c.s[i]);
    }
    any = true;
  }
  if (any) sol_.stick_slip_history.push_back(std::move(step));
}

/// The state the path sets out from: unloaded, or a warm start.
void LoadPath::set_out() {
  // Points in contact in the unloaded state (touching: g = 0) are anchored from the start, so
  // that friction holds them in the first load step already.
  system_.set_factors(0, 0);
  system_.commit(x_);
  // A warm start (an adaptive loop's previous solution): its dofs and multipliers, at the
  // factor force control starts from; for exactly enforced pairs without friction (whose path
  // it would skip; the penalty keeps the seed's solves from the undeformed state).
  const bool exact = std::all_of(pairs_.begin(), pairs_.end(),
                                 [](const ContactPair& p) { return p.constraints != nullptr; });
  const bool warm = start_.u.size() == d_.n_dofs && !system_.has_friction() && exact && !pairs_.empty();
  if (warm) {
    system_.set_factors(first_, first_);
    x_ = system_.unknowns(start_.u, start_.multipliers);
  } else {
    system_.activate_touching(x_);
  }
}

// Load steps along the path parameter from `from` to `target` (factors(s) gives the
// factors), halving a step that does not converge and doubling it again, up to the nominal
// step, after two steps in a row converged; a step is never shorter than the nominal one
// halved max_cuts times (`cuts` counts the halvings the current step has, not those in a row:
// a load that cannot be carried beyond some factor, e.g. a shear at the friction's capacity,
// was otherwise approached by ever shorter steps for ever, 0.75, 0.875, 0.9375, ...). With
// `force`, force-controlled steps (attempt_step).
bool LoadPath::advance(double from, double target, int steps, const FactorsAt& factors,
                       const ForceTarget& force) {
  ++segment_;
  const double nominal = (target - from) / std::max(1, steps);
  double lambda = from, step = nominal;
  int cuts = 0, in_a_row = 0;
  std::vector<double> failed_before;  // the residuals of the last attempt that failed
  // The input's numbering: a step keeps its number when it is cut (its parts say so), and the
  // steps of later stages follow those of earlier ones.
  auto input_step = [&](double next) {
    return input_steps_before_ + std::max(1, static_cast<int>(std::ceil((next - from) / nominal - 1e-9)));
  };
  // (force control by the secant adds paths beyond the planned steps: these count too)
  const int of = std::max(planned_steps(), input_steps_before_ + std::max(1, steps));
  auto step_label = [&](double next) {
    const bool whole = std::abs(std::abs(next - lambda) - std::abs(nominal)) <= 1e-9 * std::abs(nominal);
    return StepLabel{input_step(next), !whole, of};
  };
  auto step_name = [&](double next) { return step_label(next).name(); };
  while (std::abs(target - lambda) > 1e-14 * std::max(1.0, std::abs(target))) {
    const double next = std::abs(target - lambda) < std::abs(step) * (1 + 1e-12) ? target : lambda + step;
    StepAttempt attempt = attempt_step(next, factors, force);
    const solve::SolveReport& rep = attempt.report;
    if (rep.ok()) {
      const StepLabel name = step_label(next);
      lambda = next;
      accept_step(std::move(attempt), name);
      if (++in_a_row >= 2 && cuts > 0) {
        --cuts;
        step *= 2;
        in_a_row = 0;
      }
      continue;
    }
    in_a_row = 0;
    const std::string factors_now = attempt.factors.describe();
    if (rep.status == solve::SolveStatus::stopped) {  // asked to stop: no cuts, keep what converged
      sol_.message = step_name(next) + " (" + factors_now + "): " + rep.message;
      return false;
    }
    // With friction the load path is part of the problem: continuation first, cuts last.
    if (cuts == 0 && system_.has_friction()) {
      const StepLabel name = step_label(next);
      if (auto reached = continue_to(lambda, next, factors, force, name.name())) {
        lambda = next;
        accept_step(std::move(*reached), name);
        continue;
      }
    }
    const std::string why = newton_failure_reason(rep, d_, pairs_, system_);
    // A tangent made singular by a body that only contact holds (its constraints leave a
    // rigid motion free) stays singular on a shorter step when nothing has converged yet (no
    // contact holds it at all): no cuts then. After converged steps a singular tangent in
    // mid-Newton is a near-mechanism of this step (every point slipping on the way to a
    // shear near the friction's capacity, an active set that lost its last node): cut.
    bool structural = false;
    for (const Body& body : d_.bodies) structural = structural || !body.free_rigid_motions.empty();
    const bool held_before = sol_.load_steps > 0;
    // A shorter step that fails with the residuals of the longer one: what fails does not
    // scale with the load (an interference of the input, a state the step starts from).
    const bool unchanged = same_residuals(failed_before, rep.residual_history);
    failed_before = rep.residual_history;
    if (cuts == ss_.max_cuts || unchanged ||
        (rep.status == solve::SolveStatus::singular && structural && !held_before)) {
      const bool at_capacity = cuts == ss_.max_cuts && cuts > 0 && lambda != from;
      const bool slow = rep.status == solve::SolveStatus::max_iterations &&
                        still_converging(rep.residual_history);
      sol_.message = failed_step_message({input_step(next), factors_now, cuts, ss_.max_cuts, why,
                                          unchanged, at_capacity, converged_.describe(),
                                          at_capacity ? system_.capacity_used() : std::string(),
                                          rep.residual_history, slow, ss_.max_iterations});
      return false;
    }
    ++cuts;
    step *= 0.5;
    say("load step did not converge (" + why + "): cutting the step to " + std::to_string(step));
  }
  input_steps_before_ += std::max(1, steps);
  return true;
}

/// Parts a failing load step is split into for continuation (each tried in turn).
constexpr int kContinuationParts[] = {2, 4};

// With friction, a load step whose Newton fails from the last converged state is reached by
// continuation before it is cut (within solver.max_cuts: 2^k parts count as k cuts): the path
// parameters between `from` and `next` in equal parts, each solved from the same committed state
// (the friction's history does not advance: every part is the same incremental problem at a
// smaller load) and each solution the next part's first guess; only the solution at `next` is
// kept and committed. A cut commits its shorter
// steps — another load path, which friction remembers, so that two solves of one problem (an
// adaptive loop's mesh and its estimate) would answer two problems. The attempt at `next`, or
// nothing.
std::optional<LoadPath::StepAttempt> LoadPath::continue_to(double from, double next,
                                                           const FactorsAt& factors,
                                                           const ForceTarget& force,
                                                           const std::string& name) {
  for (const int parts : kContinuationParts) {
    // parts = 2^k count as k cuts: solver.max_cuts bounds how finely a step is divided either way
    if (parts > (1 << std::min(ss_.max_cuts, 20))) break;
    std::optional<StepAttempt> last;
    for (int i = 1; i <= parts; ++i) {
      const double s = i == parts ? next : from + (next - from) * i / parts;
      StepAttempt a = attempt_step(s, factors, force, last ? &last->x : nullptr);
      if (!a.report.ok()) {
        if (a.report.status == solve::SolveStatus::stopped) return std::nullopt;
        last.reset();
        break;
      }
      last = std::move(a);
    }
    if (last) {
      say(name + " reached by continuation in " +
          std::to_string(parts) + " parts from the last converged state (the friction's history "
          "kept: no shorter step committed)");
      return last;
    }
  }
  return std::nullopt;
}

// A load step's Newton solve at the path parameter s, from the last converged state. With
// `force`, force-controlled: the factor on the prescribed displacements is the unknown of the
// bordered system whose target is share(s) × value (factors(s) then gives its first guess, and
// the loads' factor unless they follow the unknown); the factors it reached are the attempt's.
LoadPath::StepAttempt LoadPath::attempt_step(double s, const FactorsAt& factors,
                                             const ForceTarget& force, const Eigen::VectorXd* start) {
  StepAttempt a{start ? *start : x_, factors(s), {}, s};
  system_.set_factors(a.factors.displacements, a.factors.loads);
  const NonlinearSolution::StepState* guess = start ? nullptr : path_guess(s);
  Eigen::VectorXd x_guess;
  if (guess) x_guess = system_.unknowns(guess->u, guess->multipliers);
  if (force) {
    add_force_target(force->component, force->share(s) * force->value, force->scales_loads, a.x,
                     a.factors.displacements.y());
    if (guess) add_force_target(force->component, force->share(s) * force->value, force->scales_loads,
                                x_guess, guess->factor);
  }
  // Newton starts from the other discretisation's state at this step where its residual is the
  // smaller: it is the better start for a step the last converged state is far from (a press),
  // not always for the next of several small steps, which that state is close to.
  if (guess && residual_norm(x_guess) < residual_norm(a.x)) a.x = std::move(x_guess);
  // The extrapolation of the last two steps where its residual is the smaller (a rubber ring
  // squeezed in equal steps: about one Newton iteration less a step). Newton's tolerance stays
  // relative to the residual the step's increment gives at the last state: a predictor that
  // is exact but for round-off (a homogeneous deformation) must not make it round-off itself.
  double unpredicted = 0;
  if (!start && !guess && !force)
    if (auto x_pred = predicted(s)) {
      unpredicted = residual_norm(a.x);
      if (residual_norm(*x_pred) < unpredicted) a.x = std::move(*x_pred);
    }
  newton_options_.reference_norm = std::max(system_.force_scale(a.x), unpredicted);
  if (force)
    newton_options_.reference_norm =
        std::max(newton_options_.reference_norm, force->share(s) * force->value);
  a.report = newton(a.x);
  if (force) {
    const double alpha = system_.displacement_factor(a.x);
    a.factors = force->scales_loads ? Factors::proportional(alpha) : Factors{Vec2(alpha, alpha), a.factors.loads};
    drop_force_target(a.x);
    system_.set_factors(a.factors.displacements, a.factors.loads);
  }
  return a;
}

std::optional<Eigen::VectorXd> LoadPath::predicted(double s) const {
  if (!d_.finite_strain() || last_steps_.size() < 2) return std::nullopt;
  const ConvergedStep &a = last_steps_[0], &b = last_steps_[1];
  if (a.segment != segment_ || b.segment != segment_ || a.x.size() != b.x.size() ||
      b.x.size() != x_.size() || !(std::abs(b.s - a.s) > 0))
    return std::nullopt;
  Eigen::VectorXd x = x_;
  const int n = system_.n_displacements();
  x.head(n) += (s - b.s) / (b.s - a.s) * (b.x.head(n) - a.x.head(n));
  return x;
}

double LoadPath::residual_norm(const Eigen::VectorXd& x) {
  Eigen::VectorXd r;
  system_.evaluate(x, r, nullptr);
  return r.norm();
}

const NonlinearSolution::StepState* LoadPath::path_guess(double s) const {
  for (const auto& g : start_.path)
    if (g.segment == segment_ && std::abs(g.s - s) <= 1e-12 * std::max(1.0, std::abs(s)) &&
        g.u.size() == d_.n_dofs && g.multipliers.size() == pairs_.size())
      return &g;
  return nullptr;
}

/// A converged load step: its state committed (friction's history) and recorded; `name` is how
/// the progress calls it (the input's numbering). With friction its state is kept for a solve
/// of the same problem on another discretisation (StartState::path).
void LoadPath::accept_step(StepAttempt attempt, const StepLabel& name) {
  x_ = std::move(attempt.x);
  converged_ = attempt.factors;
  if (last_steps_.size() == 2) last_steps_.erase(last_steps_.begin());
  last_steps_.push_back({segment_, attempt.s, x_});
  if (system_.has_friction())
    sol_.step_states.push_back({segment_, attempt.s, converged_.displacements.y(), system_.solution(x_),
                                system_.multipliers(x_)});
  system_.commit(x_);
  record(converged_, attempt.report.iterations, 0.0);
  ++sol_.load_steps;
  std::ostringstream os;
  os << converged_.describe() << ", " << attempt.report.iterations << " Newton iterations, |R| "
     << attempt.report.residual_history.front() << " -> " << attempt.report.residual_history.back();
  say_step(name, os.str(), attempt.report);
}

/// Prescribed displacements first (loads at 0), then the arc-length path of the loads.
bool LoadPath::arc_length_path() {
  if (d_.prescribed.cwiseAbs().maxCoeff() > 0 &&
      !advance(0.0, 1.0, ss_.load_steps, [](double s) { return Factors{Vec2(s, s), 0}; }))
    return false;
  system_.set_factors(1, 0);
  LoadsOnPath path(system_);
  solve::ArcLengthOptions ao;
  ao.steps = ss_.load_steps;
  ao.max_iterations = ss_.max_iterations;
  ao.tolerance = ss_.tolerance;
  ao.linear_solver = solve::LinearSolverKind::lu;
  ao.reference_norm = system_.load_vector(x_).norm();  // with the follower loads at the state reached
  HPC_REQUIRE(ao.reference_norm > 0, InputError, ss_.where.str(),
              ".control: arc-length scales the loads, and there are none");
  double lf = 0;
  Eigen::VectorXd xa = x_;
  const auto rep = solve::arc_length(path, xa, lf, ao, [this](const Eigen::VectorXd& xs,
                                                              const solve::ArcLengthStep& st) {
    return accept_arc_length_step(xs, st);
  });
  sol_.newton_iterations += rep.iterations;
  if (rep.reached) return true;
  sol_.message = rep.message;
  return false;
}

/// A converged arc-length step at the state x: committed and recorded; the path goes on.
bool LoadPath::accept_arc_length_step(const Eigen::VectorXd& x, const solve::ArcLengthStep& st) {
  x_ = x;
  converged_ = {Vec2(1, 1), st.lambda};
  system_.set_factors(1, st.lambda);
  system_.commit(x_);
  ++sol_.load_steps;
  record(converged_, st.iterations, st.length);
  std::ostringstream os;
  os << "load factor " << st.lambda << ", " << st.iterations << " iterations, length " << st.length;
  LoadStepProgress p;
  p.step = sol_.load_steps;  // the arc-length method's steps are not known beforehand: of = 0
  p.arc_length = true;
  p.detail = os.str();
  p.newton_iterations = st.iterations;
  p.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began_).count();
  say({"arc-length step " + std::to_string(sol_.load_steps) + ": " + p.detail, p});
  return true;
}

// The first guess of the factor that carries `share` of the target force in a
// force-controlled load step: the last step's, scaled by the force it carried.
double LoadPath::factor_for(double share) const {
  const auto& tr = *ss_.target_resultant;
  if (sol_.path.empty()) return first_ * share;
  const auto& last = sol_.path.back();
  const double carried = std::abs(last.resultant(tr.component));
  return carried > 0 ? last.displacements * share * tr.value / carried : first_ * share;
}

// Force control with friction, where the path matters: load steps, each to its share of the
// target force, the factor an unknown of each.
bool LoadPath::force_controlled_steps() {
  const auto& tr = *ss_.target_resultant;
  auto guess = [&](double s) { return Factors::proportional(factor_for(s)); };
  return advance(0.0, 1.0, ss_.load_steps, guess, ForceControl{tr.component, tr.value});
}

// Force control as one Newton system, the factor its unknown from the first guess on: whether it
// converged (if not, the state it started from is back and the progress says why).
bool LoadPath::force_control_at_once() {
  const auto& tr = *ss_.target_resultant;
  const Eigen::VectorXd x0 = x_;
  system_.set_factors(first_, first_);
  add_force_target(tr.component, tr.value, true, x_, first_);
  newton_options_.reference_norm = std::max(system_.force_scale(x_), tr.value);
  const auto rep = newton(x_);
  const double alpha = system_.displacement_factor(x_);
  drop_force_target(x_);
  if (!rep.ok()) {
    first_attempt_ = "force control as one Newton system did not converge (" + rep.message + ")";
    say("force control as one Newton system did not converge (" +
        newton_failure_reason(rep, d_, pairs_, system_) +
        "): load steps and the secant on the factor instead");
    x_ = x0;
    return false;
  }
  system_.set_factors(alpha, alpha);
  converged_ = Factors::proportional(alpha);
  record(converged_, rep.iterations, 0.0);
  ++sol_.load_steps;
  std::ostringstream os;
  os << "factor " << alpha << " (force control), " << rep.iterations << " Newton iterations, |R| "
     << rep.residual_history.front() << " -> " << rep.residual_history.back();
  say_step({sol_.load_steps, false, 1}, os.str(), rep);
  return true;
}

// The stages one after the other, each from the end of the one before. Under force control (an
// exactly enforced first pair) a stage's `displacements` is the share of the target force it
// reaches (the factor is the unknown) while its loads go linearly — e.g. press to the force,
// then shear at that force held.
bool LoadPath::staged_path() {
  const bool staged_force = !ss_.stages.empty() && ss_.target_resultant;
  HPC_REQUIRE(!staged_force || (!pairs_.empty() && pairs_.front().constraints), InputError, ss_.where.str(),
              ".target_resultant with stages needs the first contact pair enforced exactly "
              "(enforcement: augmented-lagrangian): the factor on the prescribed displacements is "
              "then an unknown of every load step");
  Factors stage_start;
  for (const auto& stage : ss_.stages) {
    const Factors end{Vec2(stage.displacements_x(), stage.displacements_y()), stage.loads};
    auto along = [&](double s) {
      Factors f{stage_start.displacements + s * (end.displacements - stage_start.displacements),
                stage_start.loads + s * (end.loads - stage_start.loads)};
      if (staged_force) f.displacements.setConstant(factor_for(f.displacements.y()));  // a share
      return f;
    };
    const int steps = stage.steps > 0 ? stage.steps : ss_.load_steps;
    const ForceTarget force =
        staged_force ? ForceTarget(ForceControl{ss_.target_resultant->component, ss_.target_resultant->value,
                                                stage_start.displacements.y(), end.displacements.y(), false})
                     : std::nullopt;
    if (!advance(0.0, 1.0, steps, along, force)) return false;
    stage_start = end;
  }
  return true;
}

// Force control by the secant on the factor over complete load-controlled solves, each from the
// last one's state, until the first pair's resultant is the target's to its tolerance.
bool LoadPath::secant_on_factor() {
  const auto& tr = *ss_.target_resultant;
  HPC_REQUIRE(!pairs_.empty(), InputError, ss_.where.str(),
              ".target_resultant: needs a contact pair to measure the resultant");
  // The resultant of the last converged step, as record() took it for the load path.
  auto measured = [&]() { return std::abs(sol_.path.back().resultant(tr.component)); };
  double lambda = first_;
  double l0 = lambda, f0 = measured() - tr.value;
  if (!(f0 + tr.value > 0)) {
    const auto multipliers = system_.multipliers(x_);
    throw InputError(no_force_to_scale(ss_, d_, pairs_.front(), system_.solution(x_),
                                       multipliers[0].size() ? &multipliers[0] : nullptr, l0,
                                       sol_.path.back().resultant));
  }
  double l1 = l0 * tr.value / (f0 + tr.value);
  for (int it = 0; it < 50; ++it) {
    if (!advance_to(lambda, l1)) return false;
    lambda = l1;
    const double f1 = measured() - tr.value;
    std::ostringstream os;
    os << "force control: factor " << l1 << ", resultant " << f1 + tr.value << " (target "
       << tr.value << ")";
    say(os.str());
    if (std::abs(f1) <= tr.tolerance * tr.value) break;
    const double l2 = secant_factor(l0, f0, l1, f1, tr.value);
    l0 = l1;
    f0 = f1;
    l1 = l2;
    if (it == 49) {
      sol_.message = "force control did not reach the target resultant in 50 secant iterations";
      return false;
    }
  }
  return true;
}

// The solution at the last converged state (converged or not), with its contact results.
NonlinearSolution LoadPath::result(bool converged) {
  if (!converged && !first_attempt_.empty()) sol_.message = first_attempt_ + "; then " + sol_.message;
  drop_force_target(x_);
  system_.set_factors(converged_.displacements, converged_.loads);
  sol_.u = system_.solution(x_);
  sol_.load_factor = converged_.displacements.y();
  sol_.displacement_factors = converged_.displacements;
  sol_.loads_factor = converged_.loads;
  sol_.converged = converged;
  sol_.multipliers = system_.multipliers(x_);
  // x_ is the state committed last: its step's slips and the path's were measured then
  const auto& slips = system_.step_slips();
  const auto& totals = system_.total_slips();
  for (size_t k = 0; k < pairs_.size(); ++k)
    sol_.contact.push_back(evaluate_contact(d_, pairs_[k], sol_.u, sol_.multipliers_of(k),
                                            slips[k].size() ? &slips[k] : nullptr,
                                            totals[k].size() ? &totals[k] : nullptr));
  sol_.pairs = std::move(pairs_);
  follower_forces(d_, sol_.pairs, sol_.u, sol_.multipliers, sol_.loads_factor, &sol_.wet_ranges);
  for (size_t k = 0; k < sol_.contact.size(); ++k) {
    const MemoryPoints m = memory_points(sol_, k);
    sol_.contact[k].memory_points = m.own;
    sol_.contact[k].other_memory_points = m.other;
  }
  return std::move(sol_);
}

}  // namespace

NonlinearSolution solve_contact(const ProblemSpec& spec, const Discretization& d,
                                const ProgressFn& progress, const StartState& start,
                                const StepFn& on_step) {
  LoadPath path(spec, d, progress, start, on_step);
  return path.solve();
}
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

namespace {

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
