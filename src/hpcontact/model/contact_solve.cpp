// Contact solve: R(u) = K u - lambda f - f_c(u) = 0 over the free dofs, with the penalty contact
// force f_c and its consistent tangent; load steps with cut-back; secant on lambda for a target
// resultant.
#include "hpcontact/model/contact_solve.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <limits>
#include <sstream>

#include "hpcontact/contact/two_body.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/core/roots.hpp"
#include "hpcontact/fem/edge_load.hpp"
#include "hpcontact/fem/elasticity.hpp"
#include "hpcontact/fem/finite_strain.hpp"
#include "hpcontact/model/body_stress.hpp"
#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/model/linear_solve.hpp"
#include "hpcontact/model/parallel.hpp"
#include "hpcontact/model/rigid_motion.hpp"
#include "hpcontact/solve/arc_length.hpp"

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

/// The contact forces of a pair at the state u (all dofs): on its body, and against another
/// body on that one too, with the states of both sides' points and, if t is not null, the
/// triplets of their tangent (all dofs). Against another body both sides are evaluated, each
/// with half weight: no master/slave preference (seed §3.6). With `frozen`, gaps against a rigid
/// obstacle use the normals of those states (see penalty_contact).
struct PairForces {
  Eigen::VectorXd body, other;
  std::vector<contact::PointState> states, other_states;
  /// ∫ traction ds on the pair's body: its points' tractions, and against another body half of
  /// them plus the reactions of half of the other's points.
  Vec2 resultant(const ContactPair& pair) const {
    Vec2 r = Vec2::Zero();
    const double own = pair.other < 0 ? 1.0 : 0.5;
    for (size_t i = 0; i < pair.points.size(); ++i) r += own * pair.points[i].weight * states[i].traction;
    for (size_t i = 0; i < pair.other_points.size(); ++i)
      r -= 0.5 * pair.other_points[i].weight * other_states[i].traction;
    return r;
  }
};

PairForces pair_forces(const Discretization& d, const ContactPair& pair, const Eigen::VectorXd& u,
                       std::vector<Eigen::Triplet<double>>* t,
                       const std::vector<contact::PointState>* frozen = nullptr) {
  const Body& body = d.bodies[pair.body];
  const int n = body.dofs.n_dofs();
  const Eigen::VectorXd ua = u.segment(body.dof_offset, n);
  PairForces f;
  f.body = Eigen::VectorXd::Zero(n);
  contact::FrictionInput fr, fr_other;
  if (pair.memory) {
    fr = {&pair.friction, &pair.memory->points};
    fr_other = {&pair.friction, &pair.memory->other_points};
  }
  if (pair.other < 0) {
    contact::penalty_contact(pair.points, *pair.obstacle, pair.penalty, ua, f.body, t,
                             body.dof_offset, &f.states, frozen, fr);
    return f;
  }
  const Body& other = d.bodies[pair.other];
  const int m = other.dofs.n_dofs();
  const Eigen::VectorXd ub = u.segment(other.dof_offset, m);
  f.other = Eigen::VectorXd::Zero(m);
  pair.boundary->set_displacement(ua);
  pair.other_boundary->set_displacement(ub);
  contact::two_body_contact(pair.points, ua, *pair.other_boundary, pair.penalty, 0.5, f.body, f.other,
                            t, body.dof_offset, other.dof_offset, &f.states, fr);
  contact::two_body_contact(pair.other_points, ub, *pair.boundary, pair.penalty, 0.5, f.other, f.body,
                            t, other.dof_offset, body.dof_offset, &f.other_states, fr_other);
  return f;
}

/// The internal forces of the finite-strain bodies at the state u (all dofs), their tangent's
/// triplets into t if not null. The element values are computed once and kept.
class FiniteStrainForces {
public:
  explicit FiniteStrainForces(const Discretization& d) : d_(d) {
    for (int b = 0; b < static_cast<int>(d.bodies.size()); ++b) {
      const Body& body = d.bodies[b];
      if (!body.finite_strain()) continue;
      for (int q = 0; q < body.mesh.n_quads(); ++q) {
        elements_.push_back({b, q});
        values_.push_back(fem::element_values(body.dofs.element(q), body.maps[q], body.n_gauss[q],
                                              body.mesh, q));
      }
    }
  }
  bool empty() const { return elements_.empty(); }

  /// Adds the internal forces into R (all dofs). Returns false, and says where in `inverted`,
  /// when an element inverts (det F ≤ 0 at a quadrature point).
  bool add(const Eigen::VectorXd& u, Eigen::VectorXd& R, std::vector<Eigen::Triplet<double>>* t,
           std::string* inverted) const {
    const int ne = static_cast<int>(elements_.size());
    std::vector<fem::FiniteStrainElement> el(ne);
    parallel_for(ne, [&](int i) {
      const Body& body = d_.bodies[elements_[i].body];
      const int q = elements_[i].q;
      el[i] = fem::finite_strain_element(values_[i], body.material_of(q), body.law, body.thickness,
                                         body.element_coefficients(q, u), t != nullptr);
    });
    for (int i = 0; i < ne; ++i) {
      const Body& body = d_.bodies[elements_[i].body];
      const int q = elements_[i].q;
      if (el[i].inverted()) {
        if (inverted) {
          const Vec2& X = values_[i].x[el[i].min_J_point];
          std::ostringstream os;
          os << "element " << body.mesh.quad_id(q) << " of body '" << body.name
             << "' inverts: det F = " << el[i].min_J << " at (" << X.x() << ", " << X.y() << ")";
          *inverted = os.str();
        }
        return false;
      }
      const int n = static_cast<int>(el[i].f_int.size());
      for (int a = 0; a < n; ++a) R(body.global_dof(q, a)) += el[i].f_int(a);
      if (!t) continue;
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b)
          t->emplace_back(body.global_dof(q, a), body.global_dof(q, b), el[i].K(a, b));
    }
    return true;
  }

private:
  struct Ref {
    int body, q;
  };
  const Discretization& d_;
  std::vector<Ref> elements_;
  std::vector<fem::ElementValues> values_;
};

/// Anchors and slips of a pair's points after a converged load step (see FrictionHistory).
void commit_friction(const ContactPair& pair, const PairForces& f) {
  if (!pair.memory) return;
  auto update = [&](std::vector<contact::FrictionHistory>& hs,
                    const std::vector<contact::PointState>& states) {
    for (size_t i = 0; i < hs.size(); ++i) {
      auto& h = hs[i];
      const auto& s = states[i];
      if (s.gap > 0 || !std::isfinite(s.gap)) {
        h = contact::FrictionHistory{};
        continue;
      }
      if (h.anchored) {
        h.slip = s.slip;
        continue;
      }
      h.anchored = true;
      h.edge = s.foot_edge;
      h.t = s.foot_t;
      h.anchor = s.foot - pair.obstacle->offset();
      h.tau = s.tau;
      h.slip = 0;
    }
  };
  pair.memory->points_before = pair.memory->points;
  pair.memory->other_points_before = pair.memory->other_points;
  update(pair.memory->points, f.states);
  if (pair.other >= 0) update(pair.memory->other_points, f.other_states);
}

/// The nonlinear system over the unknowns of the elastic operator: with static condensation only
/// the free external dofs, since contact acts on vertex and edge modes alone and the internal
/// modes of the linear elastic elements can be eliminated once, before Newton (not with a
/// finite-strain body, whose internal modes stay unknowns). Finite-strain bodies add their
/// internal forces and tangents at every evaluation.
class ContactSystem final : public solve::NonlinearSystem {
public:
  /// How the Newton tangent is formed: analytic; the seed's differences (normals of the
  /// undisturbed state frozen, symmetrised); plain central differences of the residual (the
  /// exact Jacobian to O(h²), for checking the analytic one).
  enum class Tangent { analytic, seed_difference, central_difference };

  ContactSystem(const Discretization& d, const std::vector<ContactPair>& pairs, bool condense,
                Tangent tangent = Tangent::analytic)
      : d_(d),
        pairs_(pairs),
        op_(assemble_elastic(d, condense && !d.finite_strain())),
        K_uu_(op_.unknown_block(d)),
        finite_(d),
        tangent_(tangent) {}

  /// Why the last evaluation failed (an inverted element), empty if it did not.
  const std::string& failure() const { return failure_; }
  /// Contact points with a pressure at the state last evaluated (both sides of two-body pairs).
  int points_in_contact() const { return points_in_contact_; }

  /// The factors on the prescribed displacements (and obstacle displacements) and on the loads.
  void set_factors(double displacements, double loads) {
    lambda_ = displacements;
    lambda_f_ = loads;
    for (const auto& pair : pairs_)
      if (pair.moving) pair.moving->set_load_factor(displacements);
  }

  /// After a converged load step at x: the friction histories take its anchors and slips.
  void commit(const Eigen::VectorXd& x) const {
    if (!has_friction()) return;
    const Eigen::VectorXd u = full(x);
    for (const auto& pair : pairs_)
      if (pair.memory) commit_friction(pair, pair_forces(d_, pair, u, nullptr));
  }
  /// The load vector on the unknowns (what a unit load factor applies).
  Eigen::VectorXd load_vector() const { return op_.restrict(d_, op_.load); }
  double displacement_factor() const { return lambda_; }
  bool has_friction() const {
    for (const auto& pair : pairs_)
      if (pair.memory) return true;
    return false;
  }
  /// The unknowns' values in a vector of all dofs.
  Eigen::VectorXd unknowns(const Eigen::VectorXd& u) const { return op_.restrict(d_, u); }
  int size() const override { return op_.n_unknowns; }

  /// All dofs from the unknowns (condensed internal modes zero; see solution()).
  Eigen::VectorXd full(const Eigen::VectorXd& x) const { return op_.expand(d_, x, lambda_); }
  /// All dofs, the condensed internal modes recovered.
  Eigen::VectorXd solution(const Eigen::VectorXd& x) const {
    Eigen::VectorXd u = full(x);
    op_.recover_internal(d_, u, lambda_f_);
    return u;
  }

  /// Scale of the residual: the norm of the forces the current load produces, and of the
  /// internal forces at the state x (a load step that starts from a loaded state, e.g. a
  /// displaced obstacle with no other load, must converge relative to those, not to its own
  /// small increment).
  double force_scale(const Eigen::VectorXd& x) const {
    const Eigen::VectorXd f = op_.K * (lambda_ * d_.prescribed);
    const Eigen::VectorXd u = full(x);
    Eigen::VectorXd g = op_.K * u;
    if (!finite_.empty()) finite_.add(u, g, nullptr, nullptr);
    return op_.restrict(d_, f).norm() + std::abs(lambda_f_) * op_.restrict(d_, op_.load).norm() +
           op_.restrict(d_, g).norm();
  }

  void evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, solve::SparseMatrix* K) override {
    if (K && tangent_ != Tangent::analytic) {
      PairStates undisturbed;
      residual(x, r, nullptr, &undisturbed, nullptr);
      *K = finite_difference_tangent(x, tangent_ == Tangent::seed_difference ? &undisturbed : nullptr);
      return;
    }
    std::vector<Eigen::Triplet<double>> t;
    residual(x, r, K ? &t : nullptr, nullptr, nullptr);
    if (!K) return;
    std::vector<Eigen::Triplet<double>> tf;
    tf.reserve(t.size());
    for (const auto& e : t) {
      const int i = op_.unknown(d_, e.row()), j = op_.unknown(d_, e.col());
      if (i >= 0 && j >= 0) tf.emplace_back(i, j, e.value());
    }
    solve::SparseMatrix Kc(size(), size());
    Kc.setFromTriplets(tf.begin(), tf.end());
    *K = K_uu_ + Kc;
  }

private:
  using PairStates = std::vector<std::vector<contact::PointState>>;

  /// R(x) on the unknowns; the contact tangent's triplets (all dofs) into t, the points' states
  /// into states; with `frozen`, gaps use the normals of those states (see penalty_contact).
  void residual(const Eigen::VectorXd& x, Eigen::VectorXd& r, std::vector<Eigen::Triplet<double>>* t,
                PairStates* states, const PairStates* frozen) const {
    const Eigen::VectorXd u = full(x);
    Eigen::VectorXd R = op_.K * u - lambda_f_ * op_.load;
    if (!finite_.empty() && !finite_.add(u, R, t, &failure_)) {
      // An inverted element has no internal force: a not-finite residual makes Newton stop and
      // the load step be cut.
      r = Eigen::VectorXd::Constant(size(), std::numeric_limits<double>::quiet_NaN());
      return;
    }
    if (states) states->resize(pairs_.size());
    points_in_contact_ = 0;
    for (size_t k = 0; k < pairs_.size(); ++k) {
      const ContactPair& pair = pairs_[k];
      PairForces f = pair_forces(d_, pair, u, t, frozen ? &(*frozen)[k] : nullptr);
      for (const auto* side : {&f.states, &f.other_states})
        for (const auto& s : *side) points_in_contact_ += s.pressure > 0;
      R.segment(d_.bodies[pair.body].dof_offset, f.body.size()) -= f.body;
      if (pair.other >= 0) R.segment(d_.bodies[pair.other].dof_offset, f.other.size()) -= f.other;
      if (states) (*states)[k] = std::move(f.states);
    }
    r = op_.restrict(d_, R);
  }

  /// The seed's tangent (eq. 3.35–3.36): column m by central differences of the whole residual
  /// with the step h_m = ν (|x_m| + 1e-3), ν = 1e-6 (< √η; below the seed's 1e-5 because a
  /// column straddling a contact switch is wrong and a small step makes that rare), the normals
  /// of the undisturbed state kept. Without `undisturbed`: plain central differences, not
  /// symmetrised.
  solve::SparseMatrix finite_difference_tangent(const Eigen::VectorXd& x,
                                                const PairStates* undisturbed) const {
    std::vector<Eigen::Triplet<double>> t;
    Eigen::VectorXd xd = x, r_plus, r_minus;
    for (int m = 0; m < size(); ++m) {
      const double h = 1e-6 * (std::abs(x(m)) + 1e-3);
      xd(m) = x(m) + h / 2;
      residual(xd, r_plus, nullptr, nullptr, undisturbed);
      xd(m) = x(m) - h / 2;
      residual(xd, r_minus, nullptr, nullptr, undisturbed);
      xd(m) = x(m);
      for (int i = 0; i < size(); ++i)
        if (const double v = (r_plus(i) - r_minus(i)) / h; v != 0) t.emplace_back(i, m, v);
    }
    solve::SparseMatrix K(size(), size());
    K.setFromTriplets(t.begin(), t.end());
    if (!undisturbed) return K;
    // Central differences are symmetric up to round-off and up to columns straddling a contact
    // switch; the seed solves the symmetric part ("symmetric equation system"), and so do we.
    return solve::SparseMatrix(0.5 * (K + solve::SparseMatrix(K.transpose())));
  }

  const Discretization& d_;
  const std::vector<ContactPair>& pairs_;
  mutable int points_in_contact_ = 0;
  ElasticOperator op_;
  solve::SparseMatrix K_uu_;  ///< the linear bodies' tangent on the unknowns, constant
  FiniteStrainForces finite_;
  mutable std::string failure_;
  Tangent tangent_ = Tangent::analytic;
  double lambda_ = 1.0;    ///< factor on the prescribed displacements
  double lambda_f_ = 1.0;  ///< factor on the loads
};

/// The system on the path of the loads' factor (arc-length), the prescribed displacements held.
class LoadsOnPath final : public solve::LoadPathSystem {
public:
  explicit LoadsOnPath(ContactSystem& s) : s_(s) {}
  int size() const override { return s_.size(); }
  void evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, solve::SparseMatrix* K) override {
    s_.evaluate(x, r, K);
  }
  void set_load_factor(double lambda) override { s_.set_factors(s_.displacement_factor(), lambda); }
  Eigen::VectorXd load_derivative(const Eigen::VectorXd&) override { return -s_.load_vector(); }

private:
  ContactSystem& s_;
};

/// Gap of the deformed boundary at local edge parameter t of element q; the deformed point in
/// x_out, the undeformed one in X_out.
double gap_at(const Body& body, const contact::Obstacle& obstacle, int q, int le, double t,
              const Eigen::VectorXd& u, Vec2* x_out, Vec2* X_out = nullptr) {
  const auto& es = body.dofs.element(q);
  const int n = es.n_modes();
  Eigen::VectorXd N(n);
  const auto r = fem::edge_reference_point(le, t);
  es.evaluate(r[0], r[1], N.data(), nullptr, nullptr);
  const Vec2 X = fem::edge_geometry(body.maps[q], le, t, nullptr, nullptr);
  if (X_out) *X_out = X;
  Vec2 x = X;
  for (int a = 0; a < n; ++a) {
    const int dof = body.dof_offset + 2 * es.modes[a];
    x += N(a) * Vec2(u(dof), u(dof + 1));
  }
  if (x_out) *x_out = x;
  return obstacle.gap(x, nullptr, nullptr);
}

bool shares_node(const mesh::Mesh& m, int a, int b) {
  const auto &ea = m.edge(a), &eb = m.edge(b);
  return ea.v0 == eb.v0 || ea.v0 == eb.v1 || ea.v1 == eb.v0 || ea.v1 == eb.v1;
}

/// Root of the gap between parameters a and b of one edge by the Pegasus method (seed §4.7):
/// the boundary point where the contact zone ends, undeformed (X) and deformed (x).
std::pair<Vec2, Vec2> zone_end(const Body& body, const contact::Obstacle& obstacle, int q, int le,
                               double a, double b, const Eigen::VectorXd& u) {
  Vec2 x, X;
  auto gap = [&](double t) { return gap_at(body, obstacle, q, le, t, u, &x, &X); };
  const double fa = gap(a), fb = gap(b);
  gap(pegasus_root(gap, a, b, fa, fb, 1e-14 * (1 + x.norm())));
  return {X, x};
}

/// -n·σ·n at local edge parameter t of element q, n the outward normal N of the undeformed
/// boundary; under finite strain the Cauchy stress and the deformed normal F⁻ᵀN / |F⁻ᵀN|.
double stress_pressure(const Body& body, int q, int le, double t, const Vec2& N,
                       const Eigen::VectorXd& u) {
  const auto r = fem::edge_reference_point(le, t);
  const auto pv = fem::point_values(body.dofs.element(q), body.maps[q], r[0], r[1]);
  const auto ps = point_stress(body, q, pv, body.element_coefficients(q, u));
  const Vec2 n = body.finite_strain() ? Vec2(ps.F.inverse().transpose() * N).normalized() : N;
  const Eigen::Vector3d& sig = ps.stress;
  return -(n.x() * n.x() * sig(0) + n.y() * n.y() * sig(1) + 2 * n.x() * n.y() * sig(2));
}

/// ∫ traction ds of a pair at the state u, and the states of its points (and of the other
/// body's points into other_states, if given).
Vec2 contact_resultant(const Discretization& d, const ContactPair& pair, const Eigen::VectorXd& u,
                       std::vector<contact::PointState>& states,
                       std::vector<contact::PointState>* other_states = nullptr) {
  PairForces f = pair_forces(d, pair, u, nullptr);
  const Vec2 r = f.resultant(pair);
  states = std::move(f.states);
  if (other_states) *other_states = std::move(f.other_states);
  return r;
}

/// The ends of the contact zone along the contact points of one body (the states' gaps change
/// sign; Pegasus on the gap between them, seed §4.7), and which of them are the outer ends of
/// the active region, by the coordinate along the obstacle (the contact edges need not be
/// listed as one path): the zone end just outside the first and the last closed point, where
/// open points lie beyond them.
ZoneEnds zone_ends(const Body& body, const std::vector<contact::ContactPoint>& points,
                   const std::vector<contact::PointState>& states, const contact::Obstacle& obstacle,
                   const ContactPair& pair, const Eigen::VectorXd& u) {
  ZoneEnds z;
  for (size_t i = 0; i + 1 < points.size(); ++i) {
    if ((states[i].gap < 0) == (states[i + 1].gap < 0)) continue;
    const auto &p0 = points[i], &p1 = points[i + 1];
    const bool same_edge = p0.element == p1.element && p0.local_edge == p1.local_edge;
    std::optional<std::pair<Vec2, Vec2>> end;
    if (same_edge) {
      end = zone_end(body, obstacle, p0.element, p0.local_edge, p0.t, p1.t, u);
    } else if (shares_node(body.mesh, body.mesh.quad_edge(p0.element, p0.local_edge),
                           body.mesh.quad_edge(p1.element, p1.local_edge))) {
      // The zone ends between two edges: on the side whose end gap changes sign (a node
      // placed on Γ*, as rp does, gives a root at the edge end itself).
      for (const auto* cp : {&p0, &p1}) {
        const bool open = states[cp == &p0 ? i : i + 1].gap >= 0;
        const double te = cp->t >= 0 ? 1.0 : -1.0;  // the end at the shared node
        if (!end && (gap_at(body, obstacle, cp->element, cp->local_edge, te, u, nullptr) >= 0) != open)
          end = zone_end(body, obstacle, cp->element, cp->local_edge, cp->t, te, u);
      }
    }
    if (end) {
      z.X.push_back(end->first);
      z.x.push_back(end->second);
    }
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (size_t i = 0; i < points.size(); ++i)
    if (states[i].gap < 0) {
      lo = std::min(lo, pair.coordinate(points[i].X));
      hi = std::max(hi, pair.coordinate(points[i].X));
    }
  int below = -1, above = -1;
  for (int k = 0; k < static_cast<int>(z.X.size()); ++k) {
    const double c = pair.coordinate(z.X[k]);
    if (c <= lo && (below < 0 || c > pair.coordinate(z.X[below]))) below = k;
    if (c >= hi && (above < 0 || c < pair.coordinate(z.X[above]))) above = k;
  }
  if (below >= 0) z.outer.push_back(below);
  if (above >= 0 && above != below) z.outer.push_back(above);
  return z;
}

ContactResult contact_result(const Discretization& d, const ContactPair& pair,
                             const Eigen::VectorXd& u) {
  const Body& body = d.bodies[pair.body];
  ContactResult res;
  res.resultant = contact_resultant(d, pair, u, res.states, &res.other_states);
  for (const auto& cp : pair.points)
    res.stress_pressure.push_back(stress_pressure(body, cp.element, cp.local_edge, cp.t, cp.normal, u));
  for (size_t i = 0; i < pair.points.size(); ++i) {
    res.p_max = std::max(res.p_max, res.states[i].pressure);
    res.max_penetration = std::max(res.max_penetration, -res.states[i].gap);
  }
  ZoneEnds own = zone_ends(body, pair.points, res.states, *pair.obstacle, pair, u);
  res.gamma_star = std::move(own.X);
  res.gamma_star_deformed = std::move(own.x);
  res.outer_ends = std::move(own.outer);
  if (pair.other >= 0)
    res.other_zone_ends = zone_ends(d.bodies[pair.other], pair.other_points, res.other_states,
                                    *pair.boundary, pair, u);
  for (const Vec2& g : res.gamma_star)
    res.half_width = std::max(res.half_width, std::abs(pair.coordinate(g)));
  return res;
}

}  // namespace

ContactResult evaluate_contact(const Discretization& d, const ContactPair& pair,
                               const Eigen::VectorXd& u) {
  return contact_result(d, pair, u);
}

BoundaryPressureProbe::BoundaryPressureProbe(const Discretization& d, const ContactPair& pair,
                                             const Eigen::VectorXd& u)
    : d_(d), pair_(pair), u_(u), coord_(pair.edges.size()) {
  for (size_t k = 0; k < pair.edges.size(); ++k)
    for (int i = 0; i <= kSamples; ++i)
      coord_[k][i] = coordinate(static_cast<int>(k), -1 + 2.0 * i / kSamples);
}

double BoundaryPressureProbe::coordinate(int k, double t) const {
  const Body& body = d_.bodies[pair_.body];
  const auto& edge = body.mesh.edge(pair_.edges[k]);
  const Vec2 X = fem::edge_geometry(body.maps[edge.quads[0]], edge.local_edge[0], t, nullptr, nullptr);
  return pair_.coordinate(X);
}

std::optional<BoundaryPressure> BoundaryPressureProbe::operator()(double s) const {
  const Body& body = d_.bodies[pair_.body];
  const double tol = 1e-12 * (1 + std::abs(s));  // s on a node: round-off must not hide it
  for (size_t k = 0; k < coord_.size(); ++k) {
    for (int i = 0; i < kSamples; ++i) {
      double fa = coord_[k][i] - s, fb = coord_[k][i + 1] - s;
      if (std::abs(fa) <= tol) fa = 0;
      if (std::abs(fb) <= tol) fb = 0;
      if (fa * fb > 0) continue;
      const double t = pegasus_root([&](double r) { return coordinate(static_cast<int>(k), r) - s; },
                                    -1 + 2.0 * i / kSamples, -1 + 2.0 * (i + 1) / kSamples, fa, fb, tol);
      const auto& edge = body.mesh.edge(pair_.edges[k]);
      const int q = edge.quads[0], le = edge.local_edge[0];
      Vec2 normal;
      fem::edge_geometry(body.maps[q], le, t, &normal, nullptr);
      BoundaryPressure bp;
      const double g = gap_at(body, *pair_.obstacle, q, le, t, u_, &bp.x, &bp.X);
      bp.penalty = g < 0 ? -pair_.penalty * g : 0.0;
      bp.from_stress = stress_pressure(body, q, le, t, normal, u_);
      return bp;
    }
  }
  return std::nullopt;
}

namespace {

/// The mesh edges of a body's edge sets, in order; InputError naming `key` for an unknown set.
std::vector<int> edges_named(const Body& body, const std::vector<std::string>& names,
                             const std::string& key) {
  std::vector<int> edges;
  for (const auto& name : names) {
    auto it = body.edge_sets.find(name);
    HPC_REQUIRE(it != body.edge_sets.end(), InputError, key, ": no edge set '", name, "' in body '",
                body.name, "'");
    edges.insert(edges.end(), it->second.begin(), it->second.end());
  }
  return edges;
}

/// The contact points of `edges` in the order of the boundary path(s) they form: edges sorted
/// into chains through shared nodes, the points of each edge running along its chain (zone ends
/// are found between neighbouring points, so the list must follow the boundary whatever the
/// order the edge sets list the edges in). `edges` is reordered the same way.
std::vector<contact::ContactPoint> chained_contact_points(const Body& body, std::vector<int>& edges,
                                                          int quadrature) {
  const auto& m = body.mesh;
  std::map<int, std::vector<int>> at_node;  // node -> positions in `edges`
  for (size_t k = 0; k < edges.size(); ++k)
    for (int v : {m.edge(edges[k]).v0, m.edge(edges[k]).v1}) at_node[v].push_back(static_cast<int>(k));
  std::vector<bool> used(edges.size(), false);
  std::vector<int> ordered;
  std::vector<bool> reversed;  // the edge's own direction v0 -> v1 runs against the chain
  auto walk = [&](int k, int from) {
    while (k >= 0 && !used[k]) {
      used[k] = true;
      const auto& e = m.edge(edges[k]);
      ordered.push_back(edges[k]);
      reversed.push_back(e.v0 != from);
      const int to = e.v0 == from ? e.v1 : e.v0;
      int next = -1;
      for (int j : at_node[to])
        if (!used[j]) next = j;
      k = next;
      from = to;
    }
  };
  // Chains start at a node with one edge; what is left are closed loops.
  for (const auto& [v, ks] : at_node)
    if (ks.size() == 1 && !used[ks[0]]) walk(ks[0], v);
  for (size_t k = 0; k < edges.size(); ++k)
    if (!used[k]) walk(static_cast<int>(k), m.edge(edges[k]).v0);
  edges = ordered;
  std::vector<contact::ContactPoint> points;
  for (size_t k = 0; k < edges.size(); ++k) {
    auto pts = contact::contact_points(m, body.dofs, body.maps, {edges[k]}, quadrature, body.thickness);
    // Local edge parameters run with the element's edge; put them along the chain.
    const auto& e = m.edge(edges[k]);
    const int q = e.quads[0], le = e.local_edge[0];
    const int local_start = m.quad(q)[mesh::kEdgeVertices[le][0]];
    const int chain_start = reversed[k] ? e.v1 : e.v0;
    if (local_start != chain_start) std::reverse(pts.begin(), pts.end());
    points.insert(points.end(), pts.begin(), pts.end());
  }
  return points;
}

}  // namespace

std::vector<ContactPair> make_contact_pairs(const ProblemSpec& spec, const Discretization& d) {
  std::vector<ContactPair> pairs;
  for (const auto& cs : spec.contact) {
    ContactPair pair;
    const Body& body = body_named(d, cs.body, cs.where, &pair.body);
    pair.edges = edges_named(body, cs.edge_sets, cs.where.str() + ".edges");
    HPC_REQUIRE(cs.penalty > 0, InputError, cs.where.str(), ".penalty: must be > 0 (got ",
                cs.penalty, ")");
    pair.penalty = cs.penalty;
    if (cs.friction.law != "none") {
      const std::string key = cs.friction.where.str();
      HPC_REQUIRE(cs.friction.law == "stick" || cs.friction.law == "coulomb", InputError, key,
                  ".law: unknown friction law '", cs.friction.law, "' (expected none, stick or coulomb)");
      HPC_REQUIRE(cs.friction.mu >= 0, InputError, key, ".mu: the friction coefficient must be >= 0 (got ",
                  cs.friction.mu, ")");
      HPC_REQUIRE(cs.friction.penalty > 0, InputError, key,
                  ".penalty: the tangential penalty must be > 0 (got ", cs.friction.penalty, ")");
      pair.friction.kind = cs.friction.law == "stick" ? contact::FrictionLaw::Kind::stick
                                                      : contact::FrictionLaw::Kind::coulomb;
      pair.friction.mu = cs.friction.mu;
      pair.friction.eps_t = cs.friction.penalty;
    }
    const auto& o = cs.obstacle;
    if (o.kind == ObstacleKind::plane) {
      const Vec2 p(o.point[0], o.point[1]), nrm(o.normal[0], o.normal[1]);
      HPC_REQUIRE(nrm.norm() > 0, InputError, cs.where.str(), ".obstacle.normal: must not be zero");
      pair.obstacle = std::make_shared<contact::RigidPlane>(p, nrm);
      pair.reference_point = p;
      pair.tangent = Vec2(nrm.y(), -nrm.x()).normalized();
    } else if (o.kind == ObstacleKind::curve) {
      std::vector<Vec2> points;
      for (const auto& p : o.points) points.emplace_back(p[0], p[1]);
      auto curve = std::make_shared<contact::RigidCurve>(points);
      // Positions along it (half width, pressure curves) are measured from `point` along its
      // chord (along its first tangent if it closes on itself).
      const Vec2 chord = points.back() - points.front();
      pair.reference_point = Vec2(o.point[0], o.point[1]);
      pair.tangent = chord.norm() > 1e-9 * curve->spline().end() ? Vec2(chord.normalized())
                                                                  : Vec2(curve->spline().derivative(0).normalized());
      pair.obstacle = curve;
    } else if (o.kind == ObstacleKind::circle) {
      pair.obstacle = std::make_shared<contact::RigidCircle>(Vec2(o.center[0], o.center[1]),
                                                             o.radius, o.inside);
      pair.reference_point = Vec2(o.center[0], o.center[1]);
    } else {
      const Body& other = body_named(d, o.body, cs.where, &pair.other);
      HPC_REQUIRE(pair.other != pair.body, InputError, cs.where.str(),
                  ".obstacle.body: must be another body than the contact's own");
      const auto other_edges = edges_named(other, o.edge_sets, cs.where.str() + ".obstacle.edges");
      pair.boundary = std::make_shared<contact::DeformableBoundary>(body.mesh, body.dofs, body.maps,
                                                                    pair.edges);
      pair.other_boundary = std::make_shared<contact::DeformableBoundary>(
          other.mesh, other.dofs, other.maps, other_edges);
      pair.obstacle = pair.other_boundary;
      pair.other_edges = other_edges;
      pair.other_points = chained_contact_points(other, pair.other_edges, cs.quadrature);
    }
    pair.points = chained_contact_points(body, pair.edges, cs.quadrature);
    // An obstacle the body starts deep inside (more than 1 % of its size) is a wrong normal or
    // position, not a contact problem: say so before solving.
    if (pair.other < 0) {
      const double size = body.mesh.size();
      const contact::ContactPoint* deepest = nullptr;
      double g_min = 0;
      for (const auto& cp : pair.points)
        if (const double g = pair.obstacle->gap(cp.X, nullptr, nullptr); g < g_min) {
          g_min = g;
          deepest = &cp;
        }
      HPC_REQUIRE(g_min >= -0.01 * size, InputError, cs.where.str(), ".obstacle: the undeformed body ",
                  "lies ", -g_min, " inside ", pair.obstacle->describe(), " at (", deepest->X.x(),
                  ", ", deepest->X.y(), "), more than 1 % of its size (", size,
                  "): is the obstacle's position or normal (pointing towards the body) wrong?");
    }
    if (pair.other < 0 && (o.displacement[0] != 0 || o.displacement[1] != 0)) {
      pair.moving = std::make_shared<contact::DisplacedObstacle>(
          pair.obstacle, Vec2(o.displacement[0], o.displacement[1]));
      pair.moving->set_load_factor(0);
      pair.obstacle = pair.moving;
    }
    if (pair.friction.active()) {
      pair.memory = std::make_shared<ContactPair::FrictionMemory>();
      pair.memory->points.resize(pair.points.size());
      pair.memory->other_points.resize(pair.other_points.size());
    }
    pairs.push_back(std::move(pair));
  }
  return pairs;
}

namespace {

/// Why force control has nothing to scale: the first pair's resultant R at the state u of the
/// displacement factor `factor` has no component `component`. Says which of the usual causes it
/// is: nothing prescribed to scale, the force in the other component, or no contact (and how far
/// the body is from it).
std::string no_force_to_scale(const SolverSpec& ss, const Discretization& d,
                              const ContactPair& pair, const Eigen::VectorXd& u, double factor,
                              const Vec2& R) {
  const auto& tr = *ss.target_resultant;
  const char* axis = tr.component == 0 ? "x" : "y";
  std::ostringstream os;
  os << ss.where.str() << ".target_resultant: the prescribed displacements (factor " << factor
     << ") give the contact resultant (" << R.x() << ", " << R.y() << "), no force in " << axis
     << " to scale to the target " << tr.value << ": ";
  const ContactResult c = contact_result(d, pair, u);
  double closest = std::numeric_limits<double>::infinity();
  for (const auto& st : c.states) closest = std::min(closest, st.gap);
  if (d.prescribed.cwiseAbs().maxCoeff() == 0)
    os << "no displacement is prescribed, and force control scales only prescribed "
          "displacements (give the push as ux or uy)";
  else if (std::abs(R(1 - tr.component)) > 0)
    os << "the force is in " << (tr.component == 0 ? "y" : "x")
       << "; is target_resultant.component right?";
  else if (closest > 0)
    os << "the body does not reach the obstacle (its closest contact point stays " << closest
       << " away): give a larger push, or check the obstacle's position and normal and the push's "
          "sign";
  else
    os << "points touch the obstacle but press on nothing (is the push's sign right?)";
  return os.str();
}

}  // namespace

NonlinearSolution solve_contact(const ProblemSpec& spec, const Discretization& d,
                                const ProgressFn& progress, double initial_factor,
                                const StepFn& on_step) {
  const SolverSpec& ss = spec.solver;
  auto pairs = make_contact_pairs(spec, d);
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
  no.linear_solver = solve::linear_solver_kind(ss.linear, ss.where.str() + ".linear");
  // A finite-difference column that straddles a point's contact switch is inconsistent with
  // its neighbours: the symmetric part can be indefinite, so it is solved by LU.
  if (ss.tangent == "finite-difference") no.linear_solver = solve::LinearSolverKind::lu;
  // Between two bodies the tangent's curvature terms (−p_N M) can make it indefinite away from
  // the solution (a deep first step): symmetric, but solved by LU.
  for (const auto& pair : pairs)
    if (pair.other >= 0) no.linear_solver = solve::LinearSolverKind::lu;
  // The finite-strain tangent is indefinite wherever the body is unstable under compression
  // (and may be on the way to a stable state): solved by LU.
  if (d.finite_strain()) no.linear_solver = solve::LinearSolverKind::lu;

  // The unsymmetric tangent of friction in slip: LU. Stick/slip switches make Newton cycle
  // with a large tangential penalty: the line search is on with friction unless switched off.
  if (system.has_friction()) no.linear_solver = solve::LinearSolverKind::lu;
  // Auto: on with friction (stick/slip switches make plain Newton cycle) and between two bodies
  // (a large trial correction projects points onto far parts of the other boundary: the
  // bilateral Hertz example takes 200 iterations without it, 49 with it, same solution).
  const bool two_bodies = std::any_of(pairs.begin(), pairs.end(), [](const ContactPair& p) { return p.other >= 0; });
  no.line_search = ss.line_search == "on" || (ss.line_search == "auto" && (system.has_friction() || two_bodies));
  HPC_REQUIRE(!system.has_friction() || !ss.target_resultant, InputError, ss.where.str(),
              ".target_resultant: force control goes back and forth along the load path, which a "
              "contact with friction remembers; prescribe the displacements (or use stages)");

  NonlinearSolution sol;
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
  auto record = [&](double displacements, double loads, int iterations, double arc) {
    NonlinearSolution::PathPoint p{displacements, loads, Vec2::Zero(), Vec2::Zero(), iterations, arc};
    const Eigen::VectorXd u = system.solution(x);
    if (monitor_dof >= 0) p.monitor = Vec2(u(monitor_dof), u(monitor_dof + 1));
    if (!pairs.empty()) {
      std::vector<contact::PointState> states;
      p.resultant = contact_resultant(d, pairs.front(), u, states);
    }
    sol.path.push_back(p);
    if (on_step) on_step(u, p, pairs);
  };
  struct Factors {
    double displacements = 0, loads = 0;
  };
  Factors converged;  // the factors of the last converged step
  auto say = [&](const std::string& s) {
    if (progress) progress(s);
  };

  // Load steps along the path parameter from `from` to `target` (factors(s) gives the
  // factors), halving a step that does not converge (at most max_cuts times in a row) and
  // doubling it again, up to the nominal step, after two steps in a row converged.
  auto advance = [&](double from, double target, int steps, const auto& factors) -> bool {
    const double nominal = (target - from) / std::max(1, steps);
    double lambda = from, step = nominal;
    int cuts = 0, in_a_row = 0;
    while (std::abs(target - lambda) > 1e-14 * std::max(1.0, std::abs(target))) {
      const double next = std::abs(target - lambda) < std::abs(step) * (1 + 1e-12) ? target : lambda + step;
      const Factors fn = factors(next);
      system.set_factors(fn.displacements, fn.loads);
      no.reference_norm = system.force_scale(x);
      Eigen::VectorXd trial = x;
      const auto step_start = std::chrono::steady_clock::now();
      solve::IterationCallback each;
      if (progress)
        each = [&](int it, double rn, double dxn) {
          std::ostringstream os;
          os << "  iteration " << it << ": |R| " << rn << ", |dx| " << dxn;
          if (!pairs.empty()) os << ", " << system.points_in_contact() << " points in contact";
          os << ", " << std::chrono::duration<double>(std::chrono::steady_clock::now() - step_start).count()
             << " s";
          say(os.str());
        };
      const auto rep = solve::newton(system, trial, no, each);
      sol.newton_iterations += rep.iterations;
      if (rep.ok()) {
        x = trial;
        lambda = next;
        converged = fn;
        system.commit(x);
        record(fn.displacements, fn.loads, rep.iterations, 0.0);
        ++sol.load_steps;
        std::ostringstream os;
        os << "load step " << sol.load_steps << ": factor " << fn.displacements;
        if (fn.loads != fn.displacements) os << " (loads " << fn.loads << ")";
        os << ", " << rep.iterations << " Newton iterations, |R| " << rep.residual_history.front()
           << " -> " << rep.residual_history.back();
        say(os.str());
        cuts = 0;
        if (++in_a_row >= 2 && std::abs(step) < std::abs(nominal)) {
          step = std::abs(2 * step) < std::abs(nominal) ? 2 * step : nominal;
          in_a_row = 0;
        }
        continue;
      }
      in_a_row = 0;
      std::string why = rep.message;
      if (rep.status == solve::SolveStatus::not_finite && !system.failure().empty())
        why += " (" + system.failure() + ")";
      if (rep.status == solve::SolveStatus::singular) {
        const std::string where = explain_singular(d, rep.singular_row);
        if (!where.empty()) why += " (" + where + ")";
      }
      // A tangent made singular by a body that only contact holds (its constraints leave a
      // rigid motion free) stays singular on a shorter step: no cuts then.
      bool structural = false;
      for (const Body& body : d.bodies) structural = structural || !body.free_rigid_motions.empty();
      if (cuts == ss.max_cuts || (rep.status == solve::SolveStatus::singular && structural)) {
        std::ostringstream os;
        os << "load step " << sol.load_steps + 1 << " (factor " << fn.displacements;
        if (fn.loads != fn.displacements) os << ", loads " << fn.loads;
        os << ") failed after " << cuts << " cuts: " << why << "; residual history:";
        for (double r : rep.residual_history) os << ' ' << r;
        sol.message = os.str();
        return false;
      }
      ++cuts;
      step *= 0.5;
      say("load step did not converge (" + why + "): cutting the step to " +
          std::to_string(step));
    }
    return true;
  };
  auto proportional = [](double lambda) { return Factors{lambda, lambda}; };
  auto advance_to = [&](double from, double target) {
    return advance(from, target, ss.load_steps, proportional);
  };

  // The first factor: 1 (the displacements as prescribed) or, under force control, a factor
  // the caller expects to be close (the previous mesh's, in an adaptive loop).
  const double first = ss.target_resultant && initial_factor > 0 ? initial_factor : 1.0;
  double lambda = 0;
  // A failed run keeps the last converged state, marked not converged.
  auto failed = [&]() {
    system.set_factors(converged.displacements, converged.loads);
    sol.u = system.solution(x);
    sol.load_factor = converged.displacements;
    sol.loads_factor = converged.loads;
    for (const auto& pair : pairs) sol.contact.push_back(contact_result(d, pair, sol.u));
    sol.pairs = pairs;
    return sol;
  };
  // Points in contact in the unloaded state (touching: g = 0) are anchored from the start, so
  // that friction holds them in the first load step already.
  system.set_factors(0, 0);
  system.commit(x);
  if (ss.control == "arc-length") {
    // Prescribed displacements first (loads at 0), then the arc-length path of the loads.
    if (d.prescribed.cwiseAbs().maxCoeff() > 0 &&
        !advance(0.0, 1.0, ss.load_steps, [](double s) { return Factors{s, 0}; }))
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
      converged = {1, st.lambda};
      system.set_factors(1, st.lambda);
      system.commit(x);
      ++sol.load_steps;
      record(1, st.lambda, st.iterations, st.length);
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
  } else if (ss.stages.empty()) {
    if (!advance_to(0.0, first)) return failed();
  } else {
    Factors start;
    for (const auto& stage : ss.stages) {
      const Factors end{stage.displacements, stage.loads};
      auto along = [&](double s) {
        return Factors{start.displacements + s * (end.displacements - start.displacements),
                       start.loads + s * (end.loads - start.loads)};
      };
      if (!advance(0.0, 1.0, stage.steps > 0 ? stage.steps : ss.load_steps, along)) return failed();
      start = end;
    }
  }
  lambda = first;
  if (ss.target_resultant) {
    const auto& tr = *ss.target_resultant;
    HPC_REQUIRE(!pairs.empty(), InputError, ss.where.str(),
                ".target_resultant: needs a contact pair to measure the resultant");
    // The resultant of the last converged step, as record() took it for the load path.
    auto measured = [&]() { return std::abs(sol.path.back().resultant(tr.component)); };
    double l0 = lambda, f0 = measured() - tr.value;
    if (!(f0 + tr.value > 0))
      throw InputError(no_force_to_scale(ss, d, pairs.front(), system.solution(x), l0,
                                         sol.path.back().resultant));
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
  sol.u = system.solution(x);
  sol.load_factor = converged.displacements;
  sol.loads_factor = converged.loads;
  sol.converged = true;
  for (const auto& pair : pairs) sol.contact.push_back(contact_result(d, pair, sol.u));
  sol.pairs = std::move(pairs);
  return sol;
}

namespace {

solve::SparseMatrix tangent_at(const ProblemSpec& spec, const Discretization& d,
                               const NonlinearSolution& sol, ContactSystem::Tangent kind,
                               Eigen::VectorXd* residual) {
  // With friction, the histories the last load step started from: the tangent its Newton
  // iterations converged with (the committed slips would put slipping points on the cone).
  std::vector<ContactPair> pairs = sol.pairs;
  for (auto& pair : pairs)
    if (pair.memory) {
      auto before = std::make_shared<ContactPair::FrictionMemory>(*pair.memory);
      before->points = before->points_before;
      before->other_points = before->other_points_before;
      pair.memory = before;
    }
  ContactSystem system(d, pairs, spec.discretization.condense, kind);
  system.set_factors(sol.load_factor, sol.loads_factor);
  const Eigen::VectorXd x = system.unknowns(sol.u);
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

solve::SparseMatrix residual_jacobian_by_differences(const ProblemSpec& spec, const Discretization& d,
                                                     const NonlinearSolution& sol) {
  return tangent_at(spec, d, sol, ContactSystem::Tangent::central_difference, nullptr);
}

}  // namespace hpcontact::model
