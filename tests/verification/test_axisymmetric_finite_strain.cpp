// Finite strain in axisymmetry (material.plane: axisymmetric with a hyperelastic model): a solid
// cylinder stretched axially with a free lateral surface, and one expanded radially (a hoop
// stress equal to the radial one), are homogeneous states, reproduced to round-off on straight
// and curved elements touching the axis; and at a tiny load the thick sphere is the linear
// axisymmetric one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/contact_forces.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/linear_solve.hpp"
#include "hpcontact/post/fields.hpp"
#include "problems.hpp"

using namespace hpcontact;

namespace {

constexpr double kPi = 3.14159265358979323846;
const char* kLaws[] = {"saint-venant-kirchhoff", "neo-hooke"};

/// The homogeneous uniaxial state F = diag(λ_r, λ, λ_r) (r, z, θ) of an axial stretch λ with
/// S_rr = S_θθ = 0, solved here from the laws' closed forms (not the library's):
///  - St. Venant–Kirchhoff: S_rr = Λ (2 E_r + E_z) + 2μ E_r = 0 gives E_r = −ν E_z
///    (Λ / (2Λ + 2μ) = ν), E = (stretch² − 1)/2; S_zz = Λ (2 E_r + E_z) + 2μ E_z.
///  - Neo-Hooke: S_rr = μ (1 − λ_r⁻²) + Λ ln J λ_r⁻² = 0 with J = λ_r² λ, i.e.
///    μ (λ_r² − 1) + Λ ln(λ_r² λ) = 0, increasing in λ_r: bisection; S_zz = μ (1 − λ⁻²) + Λ ln J λ⁻².
/// The axial force on the section's disc of radius a is π a² P_zz, P_zz = λ S_zz (first
/// Piola–Kirchhoff, per reference area).
struct Uniaxial {
  double lambda_r = 1, S_zz = 0, W = 0;
};
Uniaxial uniaxial(const std::string& law, double E, double nu, double lambda) {
  const double mu = E / (2 * (1 + nu)), L = E * nu / ((1 + nu) * (1 - 2 * nu));
  Uniaxial s;
  if (law == "saint-venant-kirchhoff") {
    const double Ez = (lambda * lambda - 1) / 2, Er = -nu * Ez;
    s.lambda_r = std::sqrt(1 + 2 * Er);
    s.S_zz = L * (2 * Er + Ez) + 2 * mu * Ez;
    s.W = 0.5 * L * (2 * Er + Ez) * (2 * Er + Ez) + mu * (2 * Er * Er + Ez * Ez);
    return s;
  }
  auto g = [&](double lr) { return mu * (lr * lr - 1) + L * std::log(lr * lr * lambda); };
  double lo = 0.1, hi = 2;
  for (int i = 0; i < 200; ++i) (g(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
  s.lambda_r = 0.5 * (lo + hi);
  const double J = s.lambda_r * s.lambda_r * lambda, lnJ = std::log(J);
  s.S_zz = mu * (1 - 1 / (lambda * lambda)) + L * lnJ / (lambda * lambda);
  s.W = 0.5 * mu * (2 * s.lambda_r * s.lambda_r + lambda * lambda - 3) - mu * lnJ + 0.5 * L * lnJ * lnJ;
  return s;
}

/// The distorted patch [0, 2]² as the meridian section of a solid cylinder of radius 2 and
/// height 2 (its left side the axis): u_r = 0 on the axis, u_z = 0 at the bottom and
/// (λ − 1)·2 at the top, both ends free to slide radially, the lateral surface R = 2 free.
/// `curved`: the interior edges 4–5, 2–5 and 5–8 made parabolas (the elements on the axis
/// among those they bound), whose blending map is a polynomial of degree 2, so that for p ≥ 2
/// the linear exact field lies in the space.
model::ProblemSpec stretched_cylinder(int p, const char* law, double lambda, bool curved) {
  auto spec = test_problems::distorted_patch(p);
  auto& b = spec.bodies[0];
  b.material.model = law;
  b.material.plane = model::PlaneMode::axisymmetric;
  b.material.poisson_ratio = 0.3;
  model::ConstraintSpec axis, bottom, top;
  axis.edge_sets = {"left"};
  axis.ux = "0";
  bottom.edge_sets = {"bottom"};
  bottom.uy = "0";
  top.edge_sets = {"top"};
  top.uy = std::to_string(2 * (lambda - 1));
  b.constraints = {axis, bottom, top};
  if (curved) {
    auto parabola = [&](int a, int c, const char* x, const char* y) {
      model::CurveSpec cs;
      cs.node_a = a;
      cs.node_b = c;
      cs.kind = model::CurveKind::parametric;
      cs.x_expr = x;
      cs.y_expr = y;
      b.curves.push_back(cs);
    };
    // nodes 2 (0.9, 0), 4 (0, 1.1), 5 (1.2, 0.75), 8 (1.3, 2)
    parabola(4, 5, "1.2*s", "1.1 - 0.35*s + 0.3*s*(1 - s)");
    parabola(2, 5, "0.9 + 0.3*s + 0.25*s*(1 - s)", "0.75*s");
    parabola(5, 8, "1.2 + 0.1*s - 0.2*s*(1 - s)", "0.75 + 1.25*s");
  }
  spec.solver.load_steps = 3;
  spec.solver.tolerance = 1e-13;  // the stresses to 1e-10: Newton's default 1e-10 leaves ~2e-10
  return spec;
}

/// The internal force conjugate to a rigid shift of the nodes on the side `on` picks along
/// `component` (0: r, 1: z): the work of the internal forces on the virtual field that is 1 there
/// (its vertex modes 1, every other mode 0), which vanishes on the opposite side and whose free
/// dofs carry no residual at equilibrium.
template <class OnSide>
double side_force(const model::Discretization& d, const Eigen::VectorXd& u, int component, const OnSide& on) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(d.n_dofs);
  model::FiniteStrainForces(d).add(u, f, nullptr, nullptr);
  const auto& body = d.bodies[0];
  double force = 0;
  for (int v = 0; v < body.mesh.n_nodes(); ++v)
    if (on(body.mesh.node(v))) force += f(body.dof_offset + 2 * body.dofs.vertex_mode(v) + component);
  return force;
}

/// The axial force on the top z = 2.
double top_force(const model::Discretization& d, const Eigen::VectorXd& u) {
  return side_force(d, u, 1, [](const Vec2& X) { return std::abs(X.y() - 2) < 1e-12; });
}

/// The force on the lateral surface R = 2 along r.
double lateral_force(const model::Discretization& d, const Eigen::VectorXd& u) {
  return side_force(d, u, 0, [](const Vec2& X) { return std::abs(X.x() - 2) < 1e-12; });
}

/// The homogeneous state F = diag(1 + ε, 1, 1 + ε) (r, z, θ) of a uniform radial expansion
/// u_r = ε R with u_z = 0, from the laws' closed forms (not the library's), λ = 1 + ε, J = λ²:
///  - St. Venant–Kirchhoff: E_rr = E_θθ = e = (λ² − 1)/2, E_zz = 0; S_rr = S_θθ = 2Λ e + 2μ e,
///    S_zz = 2Λ e, W = 2Λ e² + 2μ e².
///  - Neo-Hooke: S_rr = S_θθ = μ (1 − λ⁻²) + Λ ln J λ⁻², S_zz = Λ ln J,
///    W = μ (2λ² + 1 − 3)/2 − μ ln J + Λ (ln J)²/2.
/// σ_rr = σ_θθ = λ² S_rr / J, σ_zz = S_zz / J.
struct RadialExpansion {
  double S_rr = 0, S_zz = 0, W = 0;
};
RadialExpansion radial_expansion(const std::string& law, double E, double nu, double eps) {
  const double mu = E / (2 * (1 + nu)), L = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double lambda = 1 + eps, lnJ = 2 * std::log(lambda);
  RadialExpansion s;
  if (law == "saint-venant-kirchhoff") {
    const double e = (lambda * lambda - 1) / 2;
    s.S_rr = 2 * L * e + 2 * mu * e;
    s.S_zz = 2 * L * e;
    s.W = 2 * L * e * e + 2 * mu * e * e;
    return s;
  }
  s.S_rr = mu * (1 - 1 / (lambda * lambda)) + L * lnJ / (lambda * lambda);
  s.S_zz = L * lnJ;
  s.W = 0.5 * mu * (2 * lambda * lambda - 2) - mu * lnJ + 0.5 * L * lnJ * lnJ;
  return s;
}

std::vector<std::array<double, 2>> sample_points() {
  return {{-0.9, -0.7}, {0.0, 0.0}, {0.3, -0.5}, {0.77, 0.61}, {-1.0, -1.0}, {-1.0, 0.4}, {1.0, 1.0}};
}

}  // namespace

// λ = 1.3 (30 % stretch): at every sample point (corners on the axis among them) u = ((λ_r − 1)
// R, (λ − 1) Z) to 1e-10 of |u|max, σ_rr, σ_rz, σ_θθ zero and σ_zz = λ² S_zz / J to 1e-10 of
// σ_zz (1e-9 on the parabolic edges, see below); the axial force π a² λ S_zz and the energy W π a² h to 1e-10 relative. Straight elements
// p = 1…8, parabolic edges p = 2…8; both laws.
TEST(AxisymmetricFiniteStrain, StretchedCylinderIsHomogeneous) {
  const double lambda = 1.3, a = 2, h = 2;
  for (bool curved : {false, true})
    for (const char* law : kLaws)
      for (int p = curved ? 2 : 1; p <= 8; ++p) {
        const auto spec = stretched_cylinder(p, law, lambda, curved);
        const auto d = model::discretize(spec);
        const auto sol = model::solve_contact(spec, d);
        ASSERT_TRUE(sol.converged) << sol.message;
        const auto& body = d.bodies[0];
        const auto exact = uniaxial(law, body.material.youngs_modulus, body.material.poisson_ratio, lambda);
        const double J = exact.lambda_r * exact.lambda_r * lambda;
        const double sigma_zz = lambda * lambda * exact.S_zz / J, u_max = (lambda - 1) * h;
        const std::string what = std::string(law) + (curved ? " curved" : " straight") + " p " +
                                 std::to_string(p);
        double u_error = 0, stress_error = 0;
        for (int q = 0; q < body.mesh.n_quads(); ++q)
          for (auto [xi, eta] : sample_points()) {
            const auto r = post::evaluate(body, q, xi, eta, sol.u);
            const Vec2 u_exact((exact.lambda_r - 1) * r.x.x(), (lambda - 1) * r.x.y());
            u_error = std::max(u_error, (r.u - u_exact).norm() / u_max);
            const Eigen::Vector4d s(r.stress(0), r.stress(1) - sigma_zz, r.stress(2), r.stress_zz);
            stress_error = std::max(stress_error, s.norm() / sigma_zz);
          }
        EXPECT_LT(u_error, 1e-10) << what;
        // a parametric curve's tangent is a central difference (h = 1e-6): its round-off, 1e-10
        // in the map's Jacobian, is in the gradients (measured 3e-10 on the curved mesh)
        EXPECT_LT(stress_error, curved ? 1e-9 : 1e-10) << what;
        const double force = kPi * a * a * lambda * exact.S_zz;
        EXPECT_NEAR(top_force(d, sol.u), force, 1e-10 * force) << what;
        const double U = exact.W * kPi * a * a * h;
        EXPECT_NEAR(post::strain_energy(d, sol.u), U, 1e-10 * U) << what;
      }
}

// The cylinder of StretchedCylinderIsHomogeneous expanded radially instead: u_r = ε R on the
// lateral surface R = 2 (ε = 0.1), u_z = 0 on both ends, free to slide radially, u_r = 0 on the
// axis: the homogeneous state F = diag(1.1, 1, 1.1), whose hoop stress equals the radial one
// (equilibrium of a homogeneous ring needs σ_θθ = σ_rr). At every sample point u = (ε R, 0) to
// 1e-10 of |u|max, σ_rr = σ_θθ and σ_zz the closed forms and σ_rz = 0 to 1e-10 of σ_rr (1e-9 on
// the parabolic edges); the radial force on the lateral surface 2π a h λ S_rr and the energy
// W π a² h to 1e-10 relative. The element's hoop row (δE_θθ = F_θθ N_a / R δu_r) carries a hoop
// stress here, which the stretched cylinder's S_θθ = 0 does not. Straight elements p = 1…6,
// parabolic edges p = 2…6; both laws.
TEST(AxisymmetricFiniteStrain, UniformRadialExpansionIsHomogeneous) {
  const double eps = 0.1, a = 2, h = 2;
  for (bool curved : {false, true})
    for (const char* law : kLaws)
      for (int p = curved ? 2 : 1; p <= 6; ++p) {
        auto spec = stretched_cylinder(p, law, 1.0, curved);  // the ends held at u_z = 0
        model::ConstraintSpec lateral;
        lateral.edge_sets = {"right"};
        lateral.ux = std::to_string(eps * a);
        spec.bodies[0].constraints.push_back(lateral);
        const auto d = model::discretize(spec);
        const auto sol = model::solve_contact(spec, d);
        ASSERT_TRUE(sol.converged) << sol.message;
        const auto& body = d.bodies[0];
        const auto exact = radial_expansion(law, body.material.youngs_modulus, body.material.poisson_ratio, eps);
        const double lambda = 1 + eps, J = lambda * lambda;
        const double sigma_rr = lambda * lambda * exact.S_rr / J, sigma_zz = exact.S_zz / J;
        const std::string what = std::string(law) + (curved ? " curved" : " straight") + " p " +
                                 std::to_string(p);
        double u_error = 0, stress_error = 0;
        for (int q = 0; q < body.mesh.n_quads(); ++q)
          for (auto [xi, eta] : sample_points()) {
            const auto r = post::evaluate(body, q, xi, eta, sol.u);
            u_error = std::max(u_error, (r.u - Vec2(eps * r.x.x(), 0)).norm() / (eps * a));
            const Eigen::Vector4d s(r.stress(0) - sigma_rr, r.stress(1) - sigma_zz, r.stress(2),
                                    r.stress_zz - sigma_rr);
            stress_error = std::max(stress_error, s.norm() / sigma_rr);
          }
        EXPECT_LT(u_error, 1e-10) << what;
        EXPECT_LT(stress_error, curved ? 1e-9 : 1e-10) << what;
        const double force = 2 * kPi * a * h * lambda * exact.S_rr;
        EXPECT_NEAR(lateral_force(d, sol.u), force, 1e-10 * force) << what;
        const double U = exact.W * kPi * a * a * h;
        EXPECT_NEAR(post::strain_energy(d, sol.u), U, 1e-10 * U) << what;
      }
}

// The thick sphere of examples/lame under 0.2 and 0.02 of its pressure (strain scale p/E = 1e-4,
// 1e-5; smaller loads meet the round-off floor of E = ½(FᵀF − I) before Newton's tolerance): the
// finite-strain displacements are the linear axisymmetric ones to O(load) relative: below 10 ×
// the strain scale, and the relative difference falls tenfold with the load (10 ± 1).
TEST(AxisymmetricFiniteStrain, SmallLoadGivesLinearAxisymmetric) {
  const std::string file = std::string(HPC_SOURCE_DIR) + "/examples/lame/thick-sphere.yaml";
  for (const char* law : kLaws) {
    std::vector<double> rel;
    for (double t : {0.2, 0.02}) {
      auto spec = io::read_problem(file, {"discretization.degree=4"});
      for (auto& load : spec.bodies[0].edge_loads) load.value = {t * load.value[0], t * load.value[1]};
      const double strain = t * 100 / spec.bodies[0].material.youngs_modulus;
      const auto dl = model::discretize(spec);
      const auto lin = model::solve_linear(dl, {});
      spec.bodies[0].material.model = law;
      spec.solver.load_steps = 1;
      const auto dn = model::discretize(spec);
      const auto non = model::solve_contact(spec, dn);
      ASSERT_TRUE(non.converged) << non.message;
      rel.push_back((non.u - lin.u).norm() / lin.u.norm());
      std::printf("%s, load factor %g: |u - u_linear| / |u_linear| = %.3g\n", law, t, rel.back());
      EXPECT_LT(rel.back(), 10 * strain) << law;
    }
    EXPECT_NEAR(rel[0] / rel[1], 10, 1) << law;
  }
}
