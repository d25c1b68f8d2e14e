// Finite strain on whole problems: the patch test (a homogeneous deformation is reproduced
// exactly), objectivity (a rigid rotation stresses nothing), the small-load limit (linear
// elasticity), and the tangent of the nonlinear system with contact against finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/linear_solve.hpp"
#include "hpcontact/post/fields.hpp"
#include "problems.hpp"

using namespace hpcontact;

namespace {

const char* kLaws[] = {"saint-venant-kirchhoff", "neo-hooke"};

std::vector<std::array<double, 2>> sample_points() {
  return {{-0.9, -0.7}, {0.0, 0.0}, {0.3, -0.5}, {0.77, 0.61}, {-0.4, 0.95}, {1.0, 1.0}};
}

model::NonlinearSolution solve_finite(const model::ProblemSpec& spec, model::Discretization& d) {
  d = model::discretize(spec);
  auto sol = model::solve_contact(spec, d);
  EXPECT_TRUE(sol.converged) << sol.message;
  return sol;
}

/// The distorted patch with u = (F0 − I) X + c prescribed on its whole boundary.
model::ProblemSpec homogeneous(int p, const char* law, const std::string& ux, const std::string& uy) {
  auto spec = test_problems::distorted_patch(p);
  spec.bodies[0].material.model = law;
  model::ConstraintSpec c;
  c.edge_sets = {"boundary"};
  c.ux = ux;
  c.uy = uy;
  spec.bodies[0].constraints = {c};
  spec.solver.load_steps = 4;
  return spec;
}

}  // namespace

// u = (F0 − I)X + c on the boundary of a distorted patch: the solution is that field inside, so
// the Green–Lagrange strain and the Cauchy stress are the constant ones of F0 at every point,
// to 1e-9, for p = 1..4 and both laws (F0 stretches 20 %, shears 0.3 and has det F0 = 1.11).
TEST(FiniteStrainPatch, HomogeneousDeformationIsExact) {
  Eigen::Matrix2d F0;
  F0 << 1.2, 0.3, -0.1, 0.9;
  const Eigen::Matrix2d E0 = 0.5 * (F0.transpose() * F0 - Eigen::Matrix2d::Identity());
  for (const char* law : kLaws)
    for (int p = 1; p <= 4; ++p) {
      const auto spec = homogeneous(p, law, "0.2*x + 0.3*y + 0.01", "-0.1*x - 0.1*y - 0.02");
      model::Discretization d;
      const auto sol = solve_finite(spec, d);
      const auto& body = d.bodies[0];
      const auto state = material::hyperelastic_state(body.material, body.law, F0);
      const Eigen::Vector3d sigma = material::cauchy_stress(state, F0, nullptr);
      for (int q = 0; q < body.mesh.n_quads(); ++q)
        for (auto [xi, eta] : sample_points()) {
          const auto r = post::evaluate(body, q, xi, eta, sol.u);
          EXPECT_LT((r.strain - Eigen::Vector3d(E0(0, 0), E0(1, 1), 2 * E0(0, 1))).norm(), 1e-9)
              << law << " p " << p;
          EXPECT_LT((r.stress - sigma).norm(), 1e-9 * sigma.norm()) << law << " p " << p;
        }
      // The energy is W(F0) times the area (4).
      EXPECT_NEAR(post::strain_energy(d, sol.u), 4 * state.W, 1e-9 * 4 * state.W);
    }
}

// A rigid rotation by 40° (u = (R − I) X) prescribed on the boundary: zero energy and stress
// everywhere (to round-off: 1e-15 E per unit area), where linear elasticity would report
// σ ~ 0.23 E and an energy ~ 0.05 E per unit area.
TEST(FiniteStrainPatch, RigidRotationIsStressFree) {
  const double a = 40.0 * M_PI / 180, c = std::cos(a), s = std::sin(a);
  char ux[128], uy[128];
  std::snprintf(ux, sizeof ux, "%.17g*x - %.17g*y", c - 1, s);
  std::snprintf(uy, sizeof uy, "%.17g*x + %.17g*y", s, c - 1);
  for (const char* law : kLaws) {
    const auto spec = homogeneous(3, law, ux, uy);
    model::Discretization d;
    const auto sol = solve_finite(spec, d);
    const auto& body = d.bodies[0];
    const double E = body.material.youngs_modulus;
    EXPECT_LT(std::abs(post::strain_energy(d, sol.u)), 1e-15 * E * 4) << law;
    for (int q = 0; q < body.mesh.n_quads(); ++q)
      for (auto [xi, eta] : sample_points()) {
        const auto r = post::evaluate(body, q, xi, eta, sol.u);
        EXPECT_LT(r.stress.norm(), 1e-10 * E) << law;
        EXPECT_NEAR(r.u.x(), (c - 1) * r.x.x() - s * r.x.y(), 1e-12);
      }
  }
}

// A bar in tension under a traction t: the finite-strain displacements approach the linear ones
// as t → 0, the difference falling like t² (relative: like t). Asserted: relative difference
// below 20 t (the shear part of the load bends the patch: rotations of several t) and the ratio
// of differences for t and t/10 within 10 ± 1 (measured 9.99).
TEST(FiniteStrainPatch, SmallLoadsGiveLinearElasticity) {
  for (const char* law : kLaws) {
    std::vector<double> rel;
    for (double t : {1e-4, 1e-5}) {
      auto spec = test_problems::distorted_patch(3);
      auto& b = spec.bodies[0];
      const double E = b.material.youngs_modulus;
      test_problems::hold_as_bar(b, t * E, 0.3 * t * E);
      model::Discretization dl = model::discretize(spec);
      const auto lin = model::solve_linear(dl, {});
      b.material.model = law;
      model::Discretization dn;
      const auto non = solve_finite(spec, dn);
      rel.push_back((non.u - lin.u).norm() / lin.u.norm());
      EXPECT_LT(rel.back(), 20 * t) << law << " t " << t;
    }
    EXPECT_NEAR(rel[0] / rel[1], 10, 1) << law;
  }
}

// The analytic tangent of the whole nonlinear system — Neo-Hooke internal forces, penalty
// contact against the displaced rigid axle with its curvature terms — equals central differences
// of the residual at the converged state of the axle-in-ring examples: max |difference| below
// 1e-5 of max |K| (the bound; measured values printed).
TEST(FiniteStrainTangent, AxleInRingAgreesWithCentralDifferences) {
  for (const char* name : {"ring2-p4.yaml", "ring12-p4.yaml"}) {
    const auto spec = io::read_problem(std::string(HPC_SOURCE_DIR) + "/examples/axle-ring/" + name);
    const auto d = model::discretize(spec);
    const auto sol = model::solve_contact(spec, d);
    ASSERT_TRUE(sol.converged) << sol.message;
    const double mismatch = test_problems::tangent_mismatch(spec, d, sol);
    std::printf("%s: max |K_analytic - K_differences| / max |K| = %.3g\n", name, mismatch);
    EXPECT_LT(mismatch, 1e-5) << name;
  }
}
