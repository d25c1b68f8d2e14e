// Linear solve, with or without static condensation of the internal modes.
#include "hpcontact/model/linear_solve.hpp"

#include <chrono>
#include <vector>

#include "hpcontact/fem/condensation.hpp"
#include "hpcontact/fem/elasticity.hpp"
#include "hpcontact/fem/element_values.hpp"

namespace hpcontact::model {

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

struct ElementRef {
  int body, q;
};

std::vector<ElementRef> all_elements(const Discretization& d) {
  std::vector<ElementRef> refs;
  for (int b = 0; b < static_cast<int>(d.bodies.size()); ++b)
    for (int q = 0; q < d.bodies[b].mesh.n_quads(); ++q) refs.push_back({b, q});
  return refs;
}
}  // namespace

Eigen::MatrixXd element_stiffness(const Body& body, int q) {
  const auto ev =
      fem::element_values(body.dofs.element(q), body.maps[q], body.n_gauss[q], body.mesh, q);
  return fem::stiffness(ev, body.material.D(), body.thickness);
}

void assemble_linear(const Discretization& d, solve::SparseMatrix& K, Eigen::VectorXd& f) {
  const auto refs = all_elements(d);
  std::vector<Eigen::MatrixXd> Ke(refs.size());
#pragma omp parallel for schedule(dynamic)
  for (int i = 0; i < static_cast<int>(refs.size()); ++i)
    Ke[i] = element_stiffness(d.bodies[refs[i].body], refs[i].q);

  std::vector<Eigen::Triplet<double>> triplets;
  f = Eigen::VectorXd::Zero(d.n_free);
  for (int i = 0; i < d.n_dofs; ++i)
    if (d.free_index[i] >= 0) f(d.free_index[i]) += d.load(i);
  for (size_t i = 0; i < refs.size(); ++i) {
    const Body& body = d.bodies[refs[i].body];
    const int n = static_cast<int>(Ke[i].rows());
    std::vector<int> g(n);
    for (int a = 0; a < n; ++a) g[a] = body.global_dof(refs[i].q, a);
    for (int a = 0; a < n; ++a) {
      const int fa = d.free_index[g[a]];
      if (fa < 0) continue;
      for (int b = 0; b < n; ++b) {
        const int fb = d.free_index[g[b]];
        if (fb >= 0)
          triplets.emplace_back(fa, fb, Ke[i](a, b));
        else
          f(fa) -= Ke[i](a, b) * d.prescribed(g[b]);
      }
    }
  }
  K.resize(d.n_free, d.n_free);
  K.setFromTriplets(triplets.begin(), triplets.end());
}

LinearSolution solve_linear(const Discretization& d, const LinearSolveOptions& options) {
  LinearSolution sol;
  const auto t0 = Clock::now();
  solve::LinearSolver solver(options.solver);
  Eigen::VectorXd u_free;
  if (!options.condense) {
    solve::SparseMatrix K;
    Eigen::VectorXd f;
    assemble_linear(d, K, f);
    sol.assembly_seconds = seconds_since(t0);
    const auto t1 = Clock::now();
    solver.factorize(K);
    u_free = solver.solve(f);
    sol.solve_seconds = seconds_since(t1);
    sol.n_system = d.n_free;
    sol.u = d.prescribed;
    for (int i = 0; i < d.n_dofs; ++i)
      if (d.free_index[i] >= 0) sol.u(i) = u_free(d.free_index[i]);
    return sol;
  }

  // Condensed: every element's internal block is eliminated before assembly (internal modes are
  // never prescribed and belong to one element only).
  const auto refs = all_elements(d);
  std::vector<fem::CondensedElement> ce(refs.size());
#pragma omp parallel for schedule(dynamic)
  for (int i = 0; i < static_cast<int>(refs.size()); ++i) {
    const Body& body = d.bodies[refs[i].body];
    const int q = refs[i].q;
    const Eigen::MatrixXd K = element_stiffness(body, q);
    Eigen::VectorXd fe(K.rows());
    for (int a = 0; a < fe.size(); ++a) fe(a) = d.load(body.global_dof(q, a));
    const auto& es = body.dofs.element(q);
    ce[i] = fem::condense(K, fe, es.n_modes(), es.n_internal);
  }
  const int ns = d.n_free_external;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(ns);
  for (int i = 0; i < d.n_dofs; ++i) {
    const int fi = d.free_index[i];
    if (fi >= 0 && fi < ns) f(fi) += d.load(i);
  }
  std::vector<Eigen::Triplet<double>> triplets;
  for (size_t i = 0; i < refs.size(); ++i) {
    const Body& body = d.bodies[refs[i].body];
    const auto& c = ce[i];
    const int ne = static_cast<int>(c.external.size());
    std::vector<int> g(ne);
    for (int a = 0; a < ne; ++a) g[a] = body.global_dof(refs[i].q, c.external[a]);
    for (int a = 0; a < ne; ++a) {
      const int fa = d.free_index[g[a]];
      if (fa < 0) continue;
      // The condensed load differs from the external part of the element load by the internal
      // coupling; the external part itself is already in f (from d.load).
      f(fa) += c.f(a) - d.load(g[a]);
      for (int b = 0; b < ne; ++b) {
        const int fb = d.free_index[g[b]];
        if (fb >= 0)
          triplets.emplace_back(fa, fb, c.K(a, b));
        else
          f(fa) -= c.K(a, b) * d.prescribed(g[b]);
      }
    }
  }
  solve::SparseMatrix K(ns, ns);
  K.setFromTriplets(triplets.begin(), triplets.end());
  sol.assembly_seconds = seconds_since(t0);
  const auto t1 = Clock::now();
  solver.factorize(K);
  u_free = solver.solve(f);
  sol.solve_seconds = seconds_since(t1);
  sol.n_system = ns;
  sol.u = d.prescribed;
  for (int i = 0; i < d.n_dofs; ++i) {
    const int fi = d.free_index[i];
    if (fi >= 0 && fi < ns) sol.u(i) = u_free(fi);
  }
  for (size_t i = 0; i < refs.size(); ++i) {
    const Body& body = d.bodies[refs[i].body];
    const auto& c = ce[i];
    Eigen::VectorXd ue(c.external.size());
    for (size_t a = 0; a < c.external.size(); ++a)
      ue(a) = sol.u(body.global_dof(refs[i].q, c.external[a]));
    const Eigen::VectorXd full = c.recover(ue);
    for (int ii : c.internal) sol.u(body.global_dof(refs[i].q, ii)) = full(ii);
  }
  return sol;
}

}  // namespace hpcontact::model
