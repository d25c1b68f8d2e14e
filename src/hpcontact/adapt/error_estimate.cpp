// Error estimation by one degree more on the same mesh: the contact edges and their parameters
// are the same in both solves, so the tractions are compared point by point.
#include "hpcontact/adapt/error_estimate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <initializer_list>
#include <map>

#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/fem/edge_load.hpp"
#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/model/boundary_pressure.hpp"
#include "hpcontact/model/contact_results.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/post/fields.hpp"

namespace hpcontact::adapt {

namespace {
/// A shear below this share of what Coulomb friction could carry, μ‖p‖, is incidental.
constexpr double kIncidentalShear = 0.01;

/// The squared size the shear's error is measured against: the shear's own, unless the contact
/// carries almost no shear — less than kIncidentalShear of its friction's capacity, whose square
/// is `capacity2` (0 under a stick law: no bound) — and the shear is only the numerical rest of a
/// contact loaded normally (two equal bodies pressed together carry none in the linear theory):
/// then the pressure's, its absolute error counting against the traction's size.
double shear_scale2(double shear2, double capacity2, double pressure2) {
  return shear2 > kIncidentalShear * kIncidentalShear * capacity2 ? shear2 : pressure2;
}

/// μ² of a pair's Coulomb law; 0 under a stick law (no capacity bound) or without friction.
double coulomb_mu2(const model::ContactPair& pair) {
  const auto& c = pair.constraints;
  return c && c->friction.kind == contact::FrictionLaw::Kind::coulomb ? c->friction.mu * c->friction.mu : 0.0;
}
}  // namespace

model::ProblemSpec with_degrees_raised(const model::ProblemSpec& spec) {
  model::ProblemSpec raised = spec;
  for (auto& body : raised.bodies) {
    const std::array<int, 2> base = body.degree ? *body.degree : spec.discretization.degree;
    for (const int id : body.element_ids) {
      const auto it = body.element_degrees.find(id);
      std::array<int, 2> p = it != body.element_degrees.end() ? it->second : base;
      HPC_REQUIRE(std::max(p[0], p[1]) < model::kMaxDegree, AdaptError, spec.file, ": element ", id,
                  " of body '", body.name, "' has degree ", std::max(p[0], p[1]), ", the largest "
                  "there is: its error cannot be estimated by one degree more");
      body.element_degrees[id] = {p[0] + 1, p[1] + 1};
    }
  }
  return raised;
}

namespace {

/// Whether X lies within the elements touching a singular point of either result (where the
/// pressure is unbounded and no norm of it converges: the estimate measures it away from them).
bool near_singular_point(const model::ContactPair& pair,
                         std::initializer_list<const model::ContactResult*> results, const Vec2& X) {
  const double s = pair.frame->coordinate(X);
  for (const auto* r : results)
    for (const auto& p : r->singular_points)
      if (std::abs(s - p.s) < p.excluded * (1 + 1e-6)) return true;
  return false;
}

/// The points the estimate integrates over: per pair k and contact edge e the Gauss points of a
/// rule exact for the difference of the two tractions, away from singular points; fn(k, e, X, w,
/// ta, tb, sa, sb, shear) with w the weight times ds/dt, t the pressures and s the tangential
/// tractions of the coarse and the enriched solve (s only where both have them: shear).
template <class Fn>
void for_each_traction_point(const Solved& coarse, const Solved& enriched, const Fn& fn) {
  const auto& a = coarse.solution;
  const auto& b = enriched.solution;
  HPC_REQUIRE(a.pairs.size() == b.pairs.size(), AdaptError,
              "estimate_error: the two solves have different contact pairs");
  for (size_t k = 0; k < a.pairs.size(); ++k) {
    const model::BoundaryPressureProbe pa(coarse.discretization, a.pairs[k], a.u, a.multipliers_of(k));
    const model::BoundaryPressureProbe pb(enriched.discretization, b.pairs[k], b.u, b.multipliers_of(k));
    const bool shear = pa.has_tangential_traction() && pb.has_tangential_traction();
    const auto& body = enriched.discretization.bodies[b.pairs[k].body];
    for (size_t e = 0; e < b.pairs[k].edges.size(); ++e) {
      const auto& edge = body.mesh.edge(b.pairs[k].edges[e]);
      // both tractions are polynomials of degree ≤ p + 1 in t on the edge, (t − t⁺)² ≤ 2p + 2
      const int p = body.dofs.element(edge.quads[0]).max_degree();
      const auto& rule = basis::gauss_legendre(p + 3);
      for (int i = 0; i < rule.size(); ++i) {
        const double t = rule.points[i];
        double ds_dt = 0;
        const Vec2 X = fem::edge_geometry(body.maps[edge.quads[0]], edge.local_edge[0], t, nullptr, &ds_dt);
        if (near_singular_point(b.pairs[k], {&a.contact[k], &b.contact[k]}, X)) continue;
        const int ke = static_cast<int>(e);
        const double sa = shear ? pa.tangential_traction(ke, t) : 0.0;
        const double sb = shear ? pb.tangential_traction(ke, t) : 0.0;
        fn(k, e, X, rule.weights[i] * ds_dt, pa.traction(ke, t), pb.traction(ke, t), sa, sb, shear);
      }
    }
  }
}

}  // namespace

ErrorEstimate estimate_error(const Solved& coarse, const Solved& enriched) {
  double diff2 = 0, norm2 = 0, shear_diff2 = 0, shear_norm2 = 0, capacity2 = 0;
  bool friction = false;
  for_each_traction_point(coarse, enriched, [&](size_t k, size_t, const Vec2&, double w, double ta,
                                                double tb, double sa, double sb, bool shear) {
    diff2 += w * (ta - tb) * (ta - tb);
    norm2 += w * tb * tb;
    if (!shear) return;
    friction = true;
    shear_diff2 += w * (sa - sb) * (sa - sb);
    shear_norm2 += w * sb * sb;
    capacity2 += w * coulomb_mu2(enriched.solution.pairs[k]) * tb * tb;
  });
  ErrorEstimate est;
  if (norm2 > 0) est.pressure = std::sqrt(diff2 / norm2);
  if (friction) {
    const double scale2 = shear_scale2(shear_norm2, capacity2, norm2);
    if (scale2 > 0) est.shear = std::sqrt(shear_diff2 / scale2);
  }
  const double ua = post::strain_energy(coarse.discretization, coarse.solution.u);
  const double ub = post::strain_energy(enriched.discretization, enriched.solution.u);
  if (ub > 0) est.energy = std::sqrt(std::abs(ub - ua) / ub);
  est.dofs = enriched.discretization.n_free;
  est.newton_iterations = enriched.solution.newton_iterations;
  return est;
}

std::optional<ErrorPeak> pressure_error_peak(const Solved& coarse, const Solved& enriched) {
  struct Edge {
    double diff2 = 0, length = 0, peak = -1;
    Vec2 X = Vec2::Zero();
  };
  std::map<std::pair<size_t, size_t>, Edge> edges;
  double total = 0;
  for_each_traction_point(coarse, enriched, [&](size_t k, size_t e, const Vec2& X, double w, double ta,
                                                double tb, double, double, bool) {
    Edge& edge = edges[{k, e}];
    const double d2 = (ta - tb) * (ta - tb);
    edge.diff2 += w * d2;
    edge.length += w;
    total += w * d2;
    if (d2 > edge.peak) {
      edge.peak = d2;
      edge.X = X;
    }
  });
  const auto worst = std::max_element(edges.begin(), edges.end(), [](const auto& a, const auto& b) {
    return a.second.diff2 < b.second.diff2;
  });
  if (worst == edges.end() || !(total > 0)) return std::nullopt;
  const auto& pair = enriched.solution.pairs[worst->first.first];
  const auto& mesh = enriched.discretization.bodies[pair.body].mesh;
  const auto& edge = mesh.edge(pair.edges[worst->first.second]);
  return ErrorPeak{pair.body, worst->second.X, worst->second.diff2 / total, worst->second.length,
                   {mesh.node(edge.v0), mesh.node(edge.v1)}};
}

std::vector<Eigen::VectorXd> traction_error_gradient(const Solved& coarse, const Solved& enriched) {
  const auto& a = coarse.solution;
  const auto& b = enriched.solution;
  std::vector<Eigen::VectorXd> g(b.pairs.size());
  double norm2 = 0, shear_norm2 = 0, capacity2 = 0;
  for (size_t k = 0; k < b.pairs.size(); ++k) {
    const auto& c = b.pairs[k].constraints;
    if (!c) continue;
    const model::BoundaryPressureProbe pa(coarse.discretization, a.pairs[k], a.u, a.multipliers_of(k));
    const model::BoundaryPressureProbe pb(enriched.discretization, b.pairs[k], b.u, b.multipliers_of(k));
    const int n = c->size();
    const bool shear = pa.has_tangential_traction() && pb.has_tangential_traction();
    g[k] = Eigen::VectorXd::Zero(n * (c->has_friction() ? 2 : 1));
    const double mu2 = coulomb_mu2(b.pairs[k]);
    for (int j = 0; j < n; ++j) {
      const auto& node = c->nodes.nodes[j];
      if (near_singular_point(b.pairs[k], {&a.contact[k], &b.contact[k]}, node.X)) continue;
      const double tb = pb.traction(node.edge, node.t);
      g[k](j) = node.weight * (tb - pa.traction(node.edge, node.t));
      norm2 += node.weight * tb * tb;
      if (!shear) continue;
      const double sb = pb.tangential_traction(node.edge, node.t);
      g[k](n + j) = node.weight * (sb - pa.tangential_traction(node.edge, node.t));
      shear_norm2 += node.weight * sb * sb;
      capacity2 += node.weight * mu2 * tb * tb;
    }
  }
  shear_norm2 = shear_scale2(shear_norm2, capacity2, norm2);
  for (size_t k = 0; k < g.size(); ++k) {
    if (!g[k].size()) continue;
    const int n = b.pairs[k].constraints->size();
    if (norm2 > 0) g[k].head(n) /= norm2;
    if (g[k].size() > n && shear_norm2 > 0) g[k].tail(n) /= shear_norm2;
  }
  return g;
}


std::vector<std::vector<double>> surplus_energies(const model::Discretization& coarse,
                                                  const model::Discretization& enriched,
                                                  const Eigen::VectorXd& field) {
  std::vector<std::vector<double>> out(enriched.bodies.size());
  for (size_t b = 0; b < enriched.bodies.size(); ++b) {
    const model::Body& body = enriched.bodies[b];
    out[b].assign(body.mesh.n_quads(), 0.0);
    for (int q = 0; q < body.mesh.n_quads(); ++q) {
      const auto& fine = body.dofs.element(q);
      const auto& mine = coarse.bodies[b].dofs.element(q);
      HPC_REQUIRE(!fine.is_lagrange && !mine.is_lagrange, AdaptError,
                  "surplus_energies: the h-version's Lagrange elements have no hierarchy of modes");
      const auto kept = mine.hierarchic.mode_indices();
      const auto all = fine.hierarchic.mode_indices();
      Eigen::VectorXd ue = body.element_coefficients(q, field);
      const int n = fine.n_modes();
      for (int a = 0; a < n; ++a)
        if (std::find(kept.begin(), kept.end(), all[a]) != kept.end()) ue(a) = ue(a + n) = 0;
      const auto ev = fem::element_values(fine, body.maps[q], body.n_gauss[q], body.mesh, q);
      out[b][q] = post::element_strain_energy(body, q, ev, ue);
    }
  }
  return out;
}

std::vector<std::vector<double>> traction_error_indicators(const Solved& coarse,
                                                           const Solved& enriched,
                                                           const model::ProgressFn& progress,
                                                           std::string* weights_left_out) {
  auto eta = surplus_energies(coarse.discretization, enriched.discretization, enriched.solution.u);
  bool exact = false;
  for (const auto& pair : enriched.solution.pairs) exact = exact || pair.constraints;
  if (!exact) {
    if (weights_left_out) *weights_left_out = "no exactly enforced contact pair (no multipliers to weigh)";
    return eta;
  }
  std::vector<std::vector<double>> weight;
  try {
    weight = post::element_strain_energies(
        enriched.discretization,
        model::multiplier_adjoint(enriched.spec, enriched.discretization, enriched.solution,
                                  traction_error_gradient(coarse, enriched)));
  } catch (const NumericalError& e) {
    if (progress) progress(std::string("goal-oriented weights left out: ") + e.what());
    if (weights_left_out) *weights_left_out = e.what();
    return eta;
  }
  for (size_t b = 0; b < eta.size(); ++b)
    for (size_t q = 0; q < eta[b].size(); ++q) eta[b][q] = std::sqrt(eta[b][q] * weight[b][q]);
  return eta;
}

ErrorEstimate estimate_by_enrichment(const Solved& coarse, const model::ProgressFn& progress,
                                     SolvedPtr* enriched) {
  const auto t0 = std::chrono::steady_clock::now();
  SolvedPtr plus = solve(with_degrees_raised(coarse.spec), progress, &coarse);
  ErrorEstimate est = estimate_error(coarse, *plus);
  est.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (enriched) *enriched = std::move(plus);
  return est;
}

}  // namespace hpcontact::adapt
