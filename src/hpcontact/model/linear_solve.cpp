// The elastic operator (with or without static condensation) and the linear solve built on it.
#include "hpcontact/model/linear_solve.hpp"

#include <charconv>
#include <chrono>
#include <cmath>

#include "hpcontact/core/error.hpp"
#include "hpcontact/core/stop.hpp"
#include "hpcontact/fem/elasticity.hpp"
#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/model/parallel.hpp"
#include "hpcontact/model/rigid_motion.hpp"

namespace hpcontact::model {

namespace {
/// The shortest text that reads back as v (0.49999999999999994, not 0.5).
std::string exact(double v) {
  char buffer[32];
  return {buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr};
}

constexpr const char* kOverflow =
    "a load, prescribed displacement, length or material value of the input is too large (or "
    "too small) for double precision";

/// NumericalError if a vector over all dofs holds a value that is not finite; `what` names it.
void require_finite(const Discretization& d, const Eigen::VectorXd& v, const std::string& what) {
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (!std::isfinite(v(i)))
      throw NumericalError(what + " is not finite (" + exact(v(i)) + ") at " +
                           describe_dof(d, static_cast<int>(i)) + ": " + kOverflow);
}

/// A message naming an element and its material, for a stiffness that is broken.
std::string element_failure(const Body& body, int q, const std::string& what) {
  const auto& m = body.material_of(q);
  return body.mesh.context() + ": element " + std::to_string(body.mesh.quad_id(q)) + ": " + what +
         " (E = " + exact(m.youngs_modulus) + ", nu = " + exact(m.poisson_ratio) +
         ", thickness " + exact(body.thickness) + ")";
}

}  // namespace

Eigen::MatrixXd element_stiffness(const Body& body, int q) {
  const auto ev =
      fem::element_values(body.dofs.element(q), body.maps[q], body.n_gauss[q], body.mesh, q);
  if (body.axisymmetric()) return fem::axisymmetric_stiffness(ev, body.material_of(q));
  return fem::stiffness(ev, body.material_of(q).D(), body.thickness);
}

ElasticOperator assemble_elastic(const Discretization& d, bool condense) {
  // Given up when a stop is requested (core/stop.hpp: Stopped): at high degree the elements are
  // seconds of work each, and nothing has converged that the stop would have to keep.
  const StoppableWork stoppable;
  struct Ref {
    int body, q;
  };
  std::vector<Ref> refs;
  for (int b = 0; b < static_cast<int>(d.bodies.size()); ++b)
    if (!d.bodies[b].finite_strain())
      for (int q = 0; q < d.bodies[b].mesh.n_quads(); ++q) refs.push_back({b, q});

  ElasticOperator op;
  op.n_unknowns = condense ? d.n_free_external : d.n_free;
  op.load = d.load;
  // Element work in parallel: stiffness, and condensation with the element's share of the load.
  std::vector<Eigen::MatrixXd> Ke(refs.size());
  std::vector<ElasticOperator::CondensedElement> ce(condense ? refs.size() : 0);
  parallel_for(static_cast<int>(refs.size()), [&](int i) {
    const Body& body = d.bodies[refs[i].body];
    const int q = refs[i].q;
    Ke[i] = element_stiffness(body, q);
    if (!Ke[i].allFinite())
      throw NumericalError(element_failure(body, q, "its stiffness matrix is not finite") + ": " +
                           kOverflow);
    if (!condense) return;
    Eigen::VectorXd fe(Ke[i].rows());
    for (int a = 0; a < fe.size(); ++a) fe(a) = d.load(body.global_dof(q, a));
    const auto& es = body.dofs.element(q);
    try {
      ce[i] = {refs[i].body, q, fem::condense(Ke[i], fe, es.n_modes(), es.n_internal)};
    } catch (const NumericalError& e) {
      throw NumericalError(element_failure(body, q, e.what()) +
                           ": a nu this close to 0.5, or an E or thickness this close to 0, is "
                           "lost to round-off");
    }
  });
  std::vector<Eigen::Triplet<double>> t;
  for (size_t i = 0; i < refs.size(); ++i) {
    const Body& body = d.bodies[refs[i].body];
    const int q = refs[i].q;
    if (!condense) {
      const int n = static_cast<int>(Ke[i].rows());
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b)
          t.emplace_back(body.global_dof(q, a), body.global_dof(q, b), Ke[i](a, b));
      continue;
    }
    const auto& c = ce[i].element;
    const int ne = static_cast<int>(c.external.size());
    for (int a = 0; a < ne; ++a) {
      const int ga = body.global_dof(q, c.external[a]);
      // The condensed load differs from the external part of the element load by the coupling
      // to the internal modes; the external part itself is already in the global load.
      op.load(ga) += c.f(a) - d.load(ga);
      for (int b = 0; b < ne; ++b) t.emplace_back(ga, body.global_dof(q, c.external[b]), c.K(a, b));
    }
  }
  op.condensed = std::move(ce);
  op.K.resize(d.n_dofs, d.n_dofs);
  op.K.setFromTriplets(t.begin(), t.end());
  return op;
}

Eigen::VectorXd ElasticOperator::expand(const Discretization& d, const Eigen::VectorXd& x,
                                        double lambda) const {
  Eigen::VectorXd u = lambda * d.prescribed;
  for (int i = 0; i < d.n_dofs; ++i) {
    if (d.free_index[i] < 0) continue;
    const int k = unknown(d, i);
    u(i) = k >= 0 ? x(k) : 0.0;
  }
  return u;
}

Eigen::VectorXd ElasticOperator::restrict(const Discretization& d, const Eigen::VectorXd& v) const {
  Eigen::VectorXd r(n_unknowns);
  for (int i = 0; i < d.n_dofs; ++i)
    if (const int k = unknown(d, i); k >= 0) r(k) = v(i);
  return r;
}

solve::SparseMatrix ElasticOperator::unknown_block(const Discretization& d) const {
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < K.outerSize(); ++k)
    for (solve::SparseMatrix::InnerIterator it(K, k); it; ++it) {
      const int i = unknown(d, it.row()), j = unknown(d, it.col());
      if (i >= 0 && j >= 0) t.emplace_back(i, j, it.value());
    }
  solve::SparseMatrix A(n_unknowns, n_unknowns);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

void ElasticOperator::recover_internal(const Discretization& d, Eigen::VectorXd& u,
                                       double lambda) const {
  for (const auto& c : condensed) {
    const auto& ce = c.element;
    if (ce.internal.empty()) continue;
    const Body& body = d.bodies[c.body];
    Eigen::VectorXd ue(ce.external.size());
    for (size_t a = 0; a < ce.external.size(); ++a) ue(a) = u(body.global_dof(c.q, ce.external[a]));
    const Eigen::VectorXd local = ce.recover(ue, lambda);
    for (int a : ce.internal) u(body.global_dof(c.q, a)) = local(a);
  }
}

LinearSolution solve_linear(const Discretization& d, const LinearSolveOptions& options) {
  // The assembly and the factorisation are given up when a stop is requested (Stopped).
  const StoppableWork stoppable;
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  require_finite(d, d.load, "the load vector");
  require_finite(d, d.prescribed, "the prescribed displacement");
  const ElasticOperator op = assemble_elastic(d, options.condense);
  const solve::SparseMatrix K = op.unknown_block(d);
  // K_uu x = f_u - K_u,prescribed u_p, i.e. the residual K u - f at x = 0 with its sign turned.
  const Eigen::VectorXd f = op.restrict(d, op.load - op.K * d.prescribed);
  LinearSolution sol;
  sol.assembly_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  const auto t1 = Clock::now();
  solve::LinearSolver solver(options.solver);
  if (K.rows() == 0) {
    // Every dof prescribed (e.g. p = 1 with the whole boundary given): nothing to solve.
    sol.u = op.expand(d, Eigen::VectorXd(0), 1.0);
  } else {
    try {
      solver.factorize(K);
    } catch (const NumericalError& e) {
      const std::string where = explain_singular(d, solver.last_singular_row());
      throw NumericalError(std::string(e.what()) + (where.empty() ? "" : " (" + where + ")"));
    }
    sol.u = op.expand(d, solver.solve(f), 1.0);
  }
  op.recover_internal(d, sol.u, 1.0);
  require_finite(d, sol.u, "the solution");
  sol.solve_seconds = std::chrono::duration<double>(Clock::now() - t1).count();
  sol.n_system = op.n_unknowns;
  return sol;
}

}  // namespace hpcontact::model
