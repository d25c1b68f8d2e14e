// Contact solve: R(u) = K u - lambda f - f_c(u) = 0 over the free dofs, with the penalty contact
// force f_c and its consistent tangent; load steps with cut-back; secant on lambda for a target
// resultant.
#include "hpcontact/model/contact_solve.hpp"

#include <cmath>
#include <sstream>

#include "hpcontact/core/error.hpp"
#include "hpcontact/fem/condensation.hpp"
#include "hpcontact/fem/edge_load.hpp"
#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/model/linear_solve.hpp"

namespace hpcontact::model {

namespace {

const Body& body_named(const Discretization& d, const std::string& name, const SourceRef& where,
                       int* index) {
  for (size_t b = 0; b < d.bodies.size(); ++b)
    if (d.bodies[b].name == name) {
      *index = static_cast<int>(b);
      return d.bodies[b];
    }
  throw InputError(where.str() + ".body: no body named '" + name + "'");
}

/// The contact system over the free dofs, or, with static condensation, over the free external
/// dofs only: contact acts on vertex and edge modes alone, so the internal modes of the linear
/// elastic elements can be eliminated once, before Newton, and recovered after it.
class ContactSystem final : public solve::NonlinearSystem {
public:
  ContactSystem(const Discretization& d, const std::vector<ContactPair>& pairs, bool condense)
      : d_(d), pairs_(pairs), n_(condense ? d.n_free_external : d.n_free), load_(d.load) {
    std::vector<Eigen::Triplet<double>> t;
    for (const Body& body : d.bodies)
      for (int q = 0; q < body.mesh.n_quads(); ++q) {
        const Eigen::MatrixXd Ke = element_stiffness(body, q);
        const int nl = static_cast<int>(Ke.rows());
        if (!condense) {
          for (int a = 0; a < nl; ++a)
            for (int b = 0; b < nl; ++b)
              t.emplace_back(body.global_dof(q, a), body.global_dof(q, b), Ke(a, b));
          continue;
        }
        Eigen::VectorXd fe(nl);
        for (int a = 0; a < nl; ++a) fe(a) = d.load(body.global_dof(q, a));
        const auto& es = body.dofs.element(q);
        auto ce = fem::condense(Ke, fe, es.n_modes(), es.n_internal);
        const int ne = static_cast<int>(ce.external.size());
        for (int a = 0; a < ne; ++a) {
          const int ga = body.global_dof(q, ce.external[a]);
          load_(ga) += ce.f(a) - fe(ce.external[a]);
          for (int b = 0; b < ne; ++b)
            t.emplace_back(ga, body.global_dof(q, ce.external[b]), ce.K(a, b));
        }
        condensed_.push_back({&body, q, std::move(ce)});
      }
    K_.resize(d.n_dofs, d.n_dofs);
    K_.setFromTriplets(t.begin(), t.end());
    std::vector<Eigen::Triplet<double>> tf;
    for (int k = 0; k < K_.outerSize(); ++k)
      for (solve::SparseMatrix::InnerIterator it(K_, k); it; ++it) {
        const int i = unknown(it.row()), j = unknown(it.col());
        if (i >= 0 && j >= 0) tf.emplace_back(i, j, it.value());
      }
    K_ff_.resize(n_, n_);
    K_ff_.setFromTriplets(tf.begin(), tf.end());
  }

  /// Index of a dof among the unknowns, or -1 (prescribed, or internal when condensed).
  int unknown(int dof) const {
    const int f = d_.free_index[dof];
    return f >= 0 && f < n_ ? f : -1;
  }

  /// The internal modes recovered from the external ones (no-op without condensation).
  void recover_internal(Eigen::VectorXd& u) const {
    for (const auto& c : condensed_) {
      const auto& ce = c.element;
      Eigen::VectorXd ue(ce.external.size());
      for (size_t a = 0; a < ce.external.size(); ++a)
        ue(a) = u(c.body->global_dof(c.q, ce.external[a]));
      if (ce.internal.empty()) continue;
      const Eigen::VectorXd ui = lambda_ * ce.Kii_inv_fi - ce.Kii_inv_Kie * ue;
      for (size_t a = 0; a < ce.internal.size(); ++a)
        u(c.body->global_dof(c.q, ce.internal[a])) = ui(a);
    }
  }

  void set_load_factor(double lambda) { lambda_ = lambda; }
  double load_factor() const { return lambda_; }
  int size() const override { return n_; }

  /// All dofs from the unknowns (internal modes zero when condensed; see recover_internal).
  Eigen::VectorXd full(const Eigen::VectorXd& x) const {
    Eigen::VectorXd u = lambda_ * d_.prescribed;
    for (int i = 0; i < d_.n_dofs; ++i) {
      if (d_.free_index[i] < 0) continue;
      const int k = unknown(i);
      u(i) = k >= 0 ? x(k) : 0.0;
    }
    return u;
  }

  Eigen::VectorXd restrict(const Eigen::VectorXd& v) const {
    Eigen::VectorXd r(n_);
    for (int i = 0; i < d_.n_dofs; ++i)
      if (const int k = unknown(i); k >= 0) r(k) = v(i);
    return r;
  }

  /// Scale of the residual: the norm of the forces the current load produces.
  double force_scale() const {
    return restrict(K_ * (lambda_ * d_.prescribed)).norm() + lambda_ * restrict(load_).norm();
  }

  void evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, solve::SparseMatrix* K) override {
    const Eigen::VectorXd u = full(x);
    Eigen::VectorXd R = K_ * u - lambda_ * load_;
    std::vector<Eigen::Triplet<double>> t;
    for (const auto& pair : pairs_) {
      const Body& body = d_.bodies[pair.body];
      const int n = body.dofs.n_dofs();
      Eigen::VectorXd fc = Eigen::VectorXd::Zero(n);
      contact::penalty_contact(pair.points, *pair.obstacle, pair.penalty,
                               u.segment(body.dof_offset, n), fc, K ? &t : nullptr,
                               body.dof_offset, nullptr);
      R.segment(body.dof_offset, n) -= fc;
    }
    r = restrict(R);
    if (!K) return;
    std::vector<Eigen::Triplet<double>> tf;
    tf.reserve(t.size());
    for (const auto& e : t) {
      const int i = unknown(e.row()), j = unknown(e.col());
      if (i >= 0 && j >= 0) tf.emplace_back(i, j, e.value());
    }
    solve::SparseMatrix Kc(n_, n_);
    Kc.setFromTriplets(tf.begin(), tf.end());
    *K = K_ff_ + Kc;
  }

private:
  struct Condensed {
    const Body* body;
    int q;
    fem::CondensedElement element;
  };
  const Discretization& d_;
  const std::vector<ContactPair>& pairs_;
  int n_;                 ///< number of unknowns
  Eigen::VectorXd load_;  ///< external load, condensed when condensing
  solve::SparseMatrix K_, K_ff_;
  std::vector<Condensed> condensed_;
  double lambda_ = 1.0;
};

/// Gap of the deformed boundary at local edge parameter t of element q.
double gap_at(const Body& body, const ContactPair& pair, int q, int le, double t,
              const Eigen::VectorXd& u, Vec2* x_out) {
  const auto& es = body.dofs.element(q);
  const int n = es.n_modes();
  Eigen::VectorXd N(n);
  const auto r = fem::edge_reference_point(le, t);
  es.evaluate(r[0], r[1], N.data(), nullptr, nullptr);
  Vec2 x = fem::edge_geometry(body.maps[q], le, t, nullptr, nullptr);
  for (int a = 0; a < n; ++a) {
    const int dof = body.dof_offset + 2 * es.modes[a];
    x += N(a) * Vec2(u(dof), u(dof + 1));
  }
  if (x_out) *x_out = x;
  return pair.obstacle->gap(x, nullptr, nullptr);
}

/// Root of the gap between parameters a and b of one edge by the Pegasus method (seed §4.7).
Vec2 pegasus(const Body& body, const ContactPair& pair, int q, int le, double a, double b,
             const Eigen::VectorXd& u) {
  Vec2 x;
  double fa = gap_at(body, pair, q, le, a, u, &x), fb = gap_at(body, pair, q, le, b, u, &x);
  for (int it = 0; it < 100 && std::abs(b - a) > 1e-15; ++it) {
    const double c = b - fb * (b - a) / (fb - fa);
    const double fc = gap_at(body, pair, q, le, c, u, &x);
    if (fc == 0) break;
    if (fc * fb < 0) {
      a = b;
      fa = fb;
    } else {
      fa = fa * fb / (fb + fc);
    }
    b = c;
    fb = fc;
    if (std::abs(fc) < 1e-14 * (1 + x.norm())) break;
  }
  return x;
}

/// -n·σ·n at local edge parameter t of element q.
double stress_pressure(const Body& body, int q, int le, double t, const Vec2& n,
                       const Eigen::VectorXd& u) {
  const auto& es = body.dofs.element(q);
  const auto r = fem::edge_reference_point(le, t);
  const auto pv = fem::point_values(es, body.maps[q], r[0], r[1]);
  Eigen::Vector3d eps = Eigen::Vector3d::Zero();
  for (int a = 0; a < es.n_modes(); ++a) {
    const int dof = body.dof_offset + 2 * es.modes[a];
    eps += Eigen::Vector3d(u(dof) * pv.dN_dx(a), u(dof + 1) * pv.dN_dy(a),
                           u(dof) * pv.dN_dy(a) + u(dof + 1) * pv.dN_dx(a));
  }
  const Eigen::Vector3d sig = body.material.D() * eps;
  return -(n.x() * n.x() * sig(0) + n.y() * n.y() * sig(1) + 2 * n.x() * n.y() * sig(2));
}

ContactResult contact_result(const Discretization& d, const ContactPair& pair,
                             const Eigen::VectorXd& u) {
  const Body& body = d.bodies[pair.body];
  const int n = body.dofs.n_dofs();
  Eigen::VectorXd fc = Eigen::VectorXd::Zero(n);
  ContactResult res;
  contact::penalty_contact(pair.points, *pair.obstacle, pair.penalty,
                           u.segment(body.dof_offset, n), fc, nullptr, 0, &res.states);
  for (const auto& cp : pair.points)
    res.stress_pressure.push_back(stress_pressure(body, cp.element, cp.local_edge, cp.t, cp.normal, u));
  for (size_t i = 0; i < pair.points.size(); ++i) {
    const auto& s = res.states[i];
    res.resultant += pair.points[i].weight * s.traction;
    res.p_max = std::max(res.p_max, s.pressure);
    res.max_penetration = std::max(res.max_penetration, -s.gap);
    if (i + 1 < pair.points.size()) {
      const auto &p0 = pair.points[i], &p1 = pair.points[i + 1];
      const bool same_edge = p0.element == p1.element && p0.local_edge == p1.local_edge;
      if (same_edge && (s.gap < 0) != (res.states[i + 1].gap < 0))
        res.gamma_star.push_back(pegasus(body, pair, p0.element, p0.local_edge, p0.t, p1.t, u));
    }
  }
  for (const Vec2& g : res.gamma_star)
    res.half_width = std::max(res.half_width, std::abs((g - pair.reference_point).dot(pair.tangent)));
  return res;
}

}  // namespace

std::optional<BoundaryPressure> pressure_along(const Discretization& d, const ContactPair& pair,
                                               const Eigen::VectorXd& u, double s) {
  const Body& body = d.bodies[pair.body];
  for (int e : pair.edges) {
    const auto& edge = body.mesh.edge(e);
    const int q = edge.quads[0], le = edge.local_edge[0];
    auto coord = [&](double t) {
      Vec2 x;
      gap_at(body, pair, q, le, t, u, &x);
      return (x - pair.reference_point).dot(pair.tangent) - s;
    };
    const int n = 32;
    for (int i = 0; i < n; ++i) {
      double a = -1 + 2.0 * i / n, b = -1 + 2.0 * (i + 1) / n, fa = coord(a), fb = coord(b);
      const double tol = 1e-12 * (1 + std::abs(s));  // s on a node: round-off must not hide it
      if (std::abs(fa) <= tol) fa = 0;
      if (std::abs(fb) <= tol) fb = 0;
      if (fa * fb > 0) continue;
      for (int it = 0; it < 60 && b - a > 1e-15; ++it) {
        const double m = 0.5 * (a + b), fm = coord(m);
        if (fa * fm <= 0) {
          b = m;
        } else {
          a = m;
          fa = fm;
        }
      }
      const double t = 0.5 * (a + b);
      Vec2 normal;
      fem::edge_geometry(body.maps[q], le, t, &normal, nullptr);
      BoundaryPressure bp;
      const double g = gap_at(body, pair, q, le, t, u, &bp.x);
      bp.penalty = g < 0 ? -pair.penalty * g : 0.0;
      bp.from_stress = stress_pressure(body, q, le, t, normal, u);
      return bp;
    }
  }
  return std::nullopt;
}

std::vector<ContactPair> make_contact_pairs(const ProblemSpec& spec, const Discretization& d) {
  std::vector<ContactPair> pairs;
  for (const auto& cs : spec.contact) {
    ContactPair pair;
    const Body& body = body_named(d, cs.body, cs.where, &pair.body);
    for (const auto& name : cs.edge_sets) {
      auto it = body.edge_sets.find(name);
      HPC_REQUIRE(it != body.edge_sets.end(), InputError, cs.where.str(), ".edges: no edge set '",
                  name, "' in body '", body.name, "'");
      pair.edges.insert(pair.edges.end(), it->second.begin(), it->second.end());
    }
    HPC_REQUIRE(cs.penalty > 0, InputError, cs.where.str(), ".penalty: must be > 0 (got ",
                cs.penalty, ")");
    pair.penalty = cs.penalty;
    const auto& o = cs.obstacle;
    if (o.kind == ObstacleKind::plane) {
      const Vec2 p(o.point[0], o.point[1]), nrm(o.normal[0], o.normal[1]);
      HPC_REQUIRE(nrm.norm() > 0, InputError, cs.where.str(), ".obstacle.normal: must not be zero");
      pair.obstacle = std::make_shared<contact::RigidPlane>(p, nrm);
      pair.reference_point = p;
      pair.tangent = Vec2(nrm.y(), -nrm.x()).normalized();
    } else {
      pair.obstacle = std::make_shared<contact::RigidCircle>(Vec2(o.center[0], o.center[1]),
                                                             o.radius, o.inside);
      pair.reference_point = Vec2(o.center[0], o.center[1]);
    }
    pair.points = contact::contact_points(body.mesh, body.dofs, body.maps, pair.edges, cs.quadrature,
                                          body.thickness);
    pairs.push_back(std::move(pair));
  }
  return pairs;
}

NonlinearSolution solve_contact(const ProblemSpec& spec, const Discretization& d,
                                const ProgressFn& progress) {
  const SolverSpec& ss = spec.solver;
  HPC_REQUIRE(ss.tangent == "analytic", InputError, ss.where.str(), "tangent: '", ss.tangent,
              "' is not available yet (use analytic)");
  const auto pairs = make_contact_pairs(spec, d);
  ContactSystem system(d, pairs, spec.discretization.condense);
  solve::NewtonOptions no;
  no.max_iterations = ss.max_iterations;
  no.tolerance = ss.tolerance;
  no.linear_solver = solve::linear_solver_kind(ss.linear, ss.where.str() + "linear");

  NonlinearSolution sol;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(system.size());
  auto say = [&](const std::string& s) {
    if (progress) progress(s);
  };

  // Load steps from the current factor to `target`, halving a step that does not converge.
  auto advance_to = [&](double from, double target) -> bool {
    const int steps = std::max(1, ss.load_steps);
    double lambda = from, step = (target - from) / steps;
    int cuts = 0;
    while (std::abs(target - lambda) > 1e-14 * std::max(1.0, std::abs(target))) {
      const double next = std::abs(target - lambda) < std::abs(step) * (1 + 1e-12) ? target : lambda + step;
      system.set_load_factor(next);
      no.reference_norm = system.force_scale();
      Eigen::VectorXd trial = x;
      const auto rep = solve::newton(system, trial, no);
      sol.newton_iterations += rep.iterations;
      if (rep.ok()) {
        x = trial;
        lambda = next;
        ++sol.load_steps;
        std::ostringstream os;
        os << "load step " << sol.load_steps << ": factor " << next << ", " << rep.iterations
           << " Newton iterations, |R| " << rep.residual_history.front() << " -> "
           << rep.residual_history.back();
        say(os.str());
        continue;
      }
      if (cuts == ss.max_cuts) {
        std::ostringstream os;
        os << "load step " << sol.load_steps + 1 << " (factor " << next << ") failed after " << cuts
           << " cuts: " << rep.message << "; residual history:";
        for (double r : rep.residual_history) os << ' ' << r;
        sol.message = os.str();
        return false;
      }
      ++cuts;
      step *= 0.5;
      say("load step did not converge (" + rep.message + "): cutting the step to " +
          std::to_string(step));
    }
    return true;
  };

  double lambda = 0;
  if (!advance_to(0.0, 1.0)) return sol;
  lambda = 1.0;
  if (ss.target_resultant) {
    const auto& tr = *ss.target_resultant;
    HPC_REQUIRE(!pairs.empty(), InputError, ss.where.str(),
                "target_resultant: needs a contact pair to measure the resultant");
    auto measured = [&]() {
      return std::abs(contact_result(d, pairs.front(), system.full(x)).resultant(tr.component));
    };
    double l0 = lambda, f0 = measured() - tr.value;
    HPC_REQUIRE(f0 + tr.value > 0, InputError, ss.where.str(),
                "target_resultant: the prescribed displacements produce no contact force, so they "
                "cannot be scaled to the target");
    double l1 = l0 * tr.value / (f0 + tr.value);
    for (int it = 0; it < 50; ++it) {
      if (!advance_to(lambda, l1)) return sol;
      lambda = l1;
      const double f1 = measured() - tr.value;
      std::ostringstream os;
      os << "force control: factor " << l1 << ", resultant " << f1 + tr.value << " (target "
         << tr.value << ")";
      say(os.str());
      if (std::abs(f1) <= tr.tolerance * tr.value) break;
      const double l2 = l1 - f1 * (l1 - l0) / (f1 - f0);
      l0 = l1;
      f0 = f1;
      l1 = l2;
      if (it == 49) {
        sol.message = "force control did not reach the target resultant in 50 secant iterations";
        return sol;
      }
    }
  }
  sol.u = system.full(x);
  system.recover_internal(sol.u);
  sol.load_factor = lambda;
  sol.converged = true;
  for (const auto& pair : pairs) sol.contact.push_back(contact_result(d, pair, sol.u));
  return sol;
}

}  // namespace hpcontact::model
