// Finite strain on whole problems: the patch test (a homogeneous deformation is reproduced
// exactly), objectivity (a rigid rotation stresses nothing), the small-load limit (linear
// elasticity), and the tangent of the nonlinear system with contact against finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

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

/// The Cauchy stress (xx, yy, xy, zz) and the energy per reference volume of a law at F, in the
/// spatial form (from the left Cauchy–Green tensor b = F Fᵀ), derived by hand and independent of
/// the library's route through S and C:
///  - Neo-Hooke: σ = (μ/J)(b − I) + (λ ln J / J) I (push-forward of S = μ(I − C⁻¹) + λ ln J C⁻¹,
///    as F C⁻¹ Fᵀ = I), σzz = λ ln J / J (b33 = 1); W = μ/2 (tr b + 1 − 3) − μ ln J + λ/2 ln² J.
///  - St. Venant–Kirchhoff: S = λ tr E I + 2μ E with F I Fᵀ = b and F E Fᵀ = ½ (b² − b), so
///    σ = (λ tr E b + μ (b² − b)) / J, tr E = (tr b − 2)/2, σzz = S33 / J = λ tr E / J;
///    W = λ/2 (tr E)² + μ E:E.
struct Spatial {
  Eigen::Vector4d sigma;
  double W;
};
Spatial spatial_closed_form(const char* law, double E, double nu, const Eigen::Matrix2d& F) {
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double J = F.determinant();
  const Eigen::Matrix2d b = F * F.transpose(), I = Eigen::Matrix2d::Identity();
  Eigen::Matrix2d s;
  double zz, W;
  if (std::string(law) == "neo-hooke") {
    s = mu / J * (b - I) + lambda * std::log(J) / J * I;
    zz = lambda * std::log(J) / J;
    W = 0.5 * mu * (b.trace() - 2) - mu * std::log(J) + 0.5 * lambda * std::log(J) * std::log(J);
  } else {
    const double trE = (b.trace() - 2) / 2;
    s = (lambda * trE * b + mu * (b * b - b)) / J;
    zz = lambda * trE / J;
    const Eigen::Matrix2d G = 0.5 * (F.transpose() * F - I);
    W = 0.5 * lambda * trE * trE + mu * (G.array() * G.array()).sum();
  }
  return {Eigen::Vector4d(s(0, 0), s(1, 1), s(0, 1), zz), W};
}

}  // namespace

// The load path's predictor: with u = s (F0 − I)X prescribed on the boundary the solution of
// every load step is that field inside, linear in the path parameter s, so the extrapolation
// of the last two converged steps is exact but for round-off. From the third step on Newton
// then needs one iteration (the correction of round-off, to its tolerance relative to the
// step's increment), where the first two, which start from the last state, need more; the
// end state is still the homogeneous one (its strain E0 to 1e-9, p = 2, both laws).
TEST(FiniteStrainPatch, PredictorIsExactOnALinearPath) {
  Eigen::Matrix2d F0;
  F0 << 1.2, 0.3, -0.1, 0.9;
  const Eigen::Matrix2d E0 = 0.5 * (F0.transpose() * F0 - Eigen::Matrix2d::Identity());
  for (const char* law : kLaws) {
    auto spec = homogeneous(2, law, "0.2*x + 0.3*y", "-0.1*x - 0.1*y");
    spec.solver.load_steps = 6;
    model::Discretization d;
    const auto sol = solve_finite(spec, d);
    ASSERT_EQ(sol.path.size(), 6u) << law;
    for (int k = 0; k < 6; ++k) {
      if (k < 2) EXPECT_GT(sol.path[k].iterations, 1) << law << " step " << k + 1;
      else EXPECT_EQ(sol.path[k].iterations, 1) << law << " step " << k + 1;
    }
    for (auto [xi, eta] : sample_points()) {
      const auto r = post::evaluate(d.bodies[0], 0, xi, eta, sol.u);
      EXPECT_LT((r.strain - Eigen::Vector3d(E0(0, 0), E0(1, 1), 2 * E0(0, 1))).norm(), 1e-9) << law;
    }
  }
}

// u = (F0 − I)X + c on the boundary of a distorted patch: the solution is that field inside, so
// the post-processed Green–Lagrange strain and Cauchy stress (σxx, σyy, σxy, σzz) are those of
// F0 at every point — the stress the closed form above gives, to 1e-9 — for both laws and
// three F0: stretch and shear with det F0 = 1.11 (p = 1..4), plane-strain uniaxial stretch
// diag(1.2, 1) (J = 1.2: the 1/J of the push-forward) and simple shear γ = 0.3 (p = 3). The
// energy is W(F0) times the area (4).
TEST(FiniteStrainPatch, HomogeneousDeformationIsExact) {
  struct Case {
    Eigen::Matrix2d F0;
    const char *ux, *uy;
    std::vector<int> degrees;
  };
  Eigen::Matrix2d general, stretch, shear;
  general << 1.2, 0.3, -0.1, 0.9;
  stretch << 1.2, 0, 0, 1;
  shear << 1, 0.3, 0, 1;
  const Case cases[] = {{general, "0.2*x + 0.3*y + 0.01", "-0.1*x - 0.1*y - 0.02", {1, 2, 3, 4}},
                        {stretch, "0.2*x", "0", {3}},
                        {shear, "0.3*y", "0", {3}}};
  for (const auto& c : cases) {
    const Eigen::Matrix2d E0 = 0.5 * (c.F0.transpose() * c.F0 - Eigen::Matrix2d::Identity());
    for (const char* law : kLaws)
      for (int p : c.degrees) {
        const auto spec = homogeneous(p, law, c.ux, c.uy);
        model::Discretization d;
        const auto sol = solve_finite(spec, d);
        const auto& body = d.bodies[0];
        const auto expected = spatial_closed_form(law, body.material.youngs_modulus,
                                                  body.material.poisson_ratio, c.F0);
        for (int q = 0; q < body.mesh.n_quads(); ++q)
          for (auto [xi, eta] : sample_points()) {
            const auto r = post::evaluate(body, q, xi, eta, sol.u);
            EXPECT_LT((r.strain - Eigen::Vector3d(E0(0, 0), E0(1, 1), 2 * E0(0, 1))).norm(), 1e-9)
                << law << " p " << p;
            const Eigen::Vector4d got(r.stress(0), r.stress(1), r.stress(2), r.stress_zz);
            EXPECT_LT((got - expected.sigma).norm(), 1e-9 * expected.sigma.norm())
                << law << " p " << p << " F0\n" << c.F0 << "\ngot " << got.transpose()
                << "\nexpected " << expected.sigma.transpose();
          }
        EXPECT_NEAR(post::strain_energy(d, sol.u), 4 * expected.W, 1e-9 * 4 * expected.W);
      }
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
// 1e-7 of max |K| (measured 1.6e-9 and 8.5e-9: the differences' truncation and round-off).
TEST(FiniteStrainTangent, AxleInRingAgreesWithCentralDifferences) {
  for (const char* name : {"ring2-p4.yaml", "ring12-p4.yaml"}) {
    const auto spec = io::read_problem(std::string(HPC_SOURCE_DIR) + "/examples/axle-ring/" + name,
                                       {"contact[0].enforcement=penalty"});
    const auto d = model::discretize(spec);
    const auto sol = model::solve_contact(spec, d);
    ASSERT_TRUE(sol.converged) << sol.message;
    const double mismatch = test_problems::tangent_mismatch(spec, d, sol);
    std::printf("%s: max |K_analytic - K_differences| / max |K| = %.3g\n", name, mismatch);
    EXPECT_LT(mismatch, 1e-7) << name;
  }
}
