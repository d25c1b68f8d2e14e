// The rubber laws (neo-hooke-split, mooney-rivlin, yeoh) solved by the finite-strain program on
// blocks against homogeneous closed forms: uniaxial tension and compression of a cylinder
// (axisymmetric, the lateral stretch found by the FE), equibiaxial stretch of a disc
// (axisymmetric), planar tension (plane strain) — each with the free stretch solved here from
// σ = 0 in the free direction —, the approach to the incompressible closed forms as K grows
// (rate 1/K), a patch test on a distorted mesh, and the whole system's tangent with contact.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/material/hyperelastic.hpp"
#include "hpcontact/material/hyperelastic_hoop.hpp"
#include "hpcontact/model/contact_forces.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/post/fields.hpp"
#include "problems.hpp"

using namespace hpcontact;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct NamedLaw {
  const char* model;
  material::RubberConstants k;  ///< MPa
};

/// Constants of a soft filled rubber, K/μ = 50 (compressible enough that the free stretches
/// differ from the incompressible ones by ~1 %).
std::vector<NamedLaw> laws() {
  return {{"neo-hooke-split", {.C10 = 0.5, .K = 50}},
          {"mooney-rivlin", {.C10 = 0.4, .C01 = 0.1, .K = 50}},
          {"yeoh", {.C10 = 0.5, .C20 = 0.02, .C30 = 0.001, .K = 50}}};
}

/// The principal Cauchy stresses of a homogeneous state of principal stretches l, from the
/// principal-stretch form of W = W_iso(Ī₁, Ī₂) + K/2 (J − 1)² (not the library's tensor code):
/// with b̄_i = J^(−2/3) l_i², Ī₁ = Σ b̄_i, Ī₂ = Σ_{i<j} b̄_i b̄_j, β_i = λ̄_i ∂W_iso/∂λ̄_i =
/// 2 b̄_i W₁ + 2 b̄_i (Ī₁ − b̄_i) W₂,  σ_i = (β_i − Σ β_j / 3) / J + K (J − 1).
std::array<double, 3> principal_cauchy(const material::RubberConstants& k, const std::array<double, 3>& l) {
  const double J = l[0] * l[1] * l[2], j23 = std::pow(J, -2.0 / 3.0);
  std::array<double, 3> b{};
  for (int i = 0; i < 3; ++i) b[i] = j23 * l[i] * l[i];
  const double I1 = b[0] + b[1] + b[2], x = I1 - 3;
  const double W1 = k.C10 + 2 * k.C20 * x + 3 * k.C30 * x * x, W2 = k.C01;
  std::array<double, 3> beta{}, sigma{};
  for (int i = 0; i < 3; ++i) beta[i] = 2 * b[i] * W1 + 2 * b[i] * (I1 - b[i]) * W2;
  const double mean = (beta[0] + beta[1] + beta[2]) / 3;
  for (int i = 0; i < 3; ++i) sigma[i] = (beta[i] - mean) / J + k.K * (J - 1);
  return sigma;
}

/// The root of f on [lo, hi] (f(lo) < 0 < f(hi)) by bisection, bracketed to 1e-15 relative.
double root(const std::function<double(double)>& f, double lo, double hi) {
  EXPECT_LT(f(lo), 0);
  EXPECT_GT(f(hi), 0);
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) (f(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
  EXPECT_LE(hi - lo, 1e-15 * hi);
  return 0.5 * (lo + hi);
}

/// A homogeneous state: the principal stretches (1, 2, 3: x or r, y or z, z or θ) and Cauchy
/// stresses.
struct Homogeneous {
  std::array<double, 3> l{}, sigma{};
};

/// The free stretch `free` (with `tied` set equal to it, if ≥ 0) solved from σ_free = 0 to
/// 1e-15 relative, the others given in l; the residual σ_free is checked to 1e-13 of the
/// largest stress (the last bit of the stretch times dσ/dλ ~ K).
Homogeneous solve_free(const material::RubberConstants& k, std::array<double, 3> l, int free, int tied) {
  auto sigma_free = [&](double s) {
    auto m = l;
    m[free] = s;
    if (tied >= 0) m[tied] = s;
    return principal_cauchy(k, m)[free];
  };
  const double s = root(sigma_free, 0.01, 10);
  l[free] = s;
  if (tied >= 0) l[tied] = s;
  Homogeneous h{l, principal_cauchy(k, l)};
  const double scale = std::max({std::abs(h.sigma[0]), std::abs(h.sigma[1]), std::abs(h.sigma[2])});
  EXPECT_LT(std::abs(h.sigma[free]), 1e-13 * scale);
  return h;
}

/// One p = 2 element [0, a] × [0, h] of the law; edge sets left, right, bottom, top.
model::ProblemSpec block(const NamedLaw& law, model::PlaneMode plane, double a, double h) {
  model::ProblemSpec spec;
  spec.file = spec.case_name = "rubber-block";
  auto b = test_problems::body("block", 0, 0);
  b.material.model = law.model;
  b.material.plane = plane;
  b.material.C10 = law.k.C10;
  b.material.C01 = law.k.C01;
  b.material.C20 = law.k.C20;
  b.material.C30 = law.k.C30;
  b.material.K = law.k.K;
  test_problems::add_node(b, 1, 0, 0);
  test_problems::add_node(b, 2, a, 0);
  test_problems::add_node(b, 3, a, h);
  test_problems::add_node(b, 4, 0, h);
  test_problems::add_element(b, 1, 1, 2, 3, 4);
  test_problems::add_edge_set(b, "bottom", {{1, 2}});
  test_problems::add_edge_set(b, "right", {{2, 3}});
  test_problems::add_edge_set(b, "top", {{3, 4}});
  test_problems::add_edge_set(b, "left", {{4, 1}});
  spec.bodies.push_back(b);
  spec.discretization.degree = {2, 2};
  spec.solver.load_steps = 10;
  spec.solver.tolerance = 1e-13;  // the stresses to 1e-8 with room
  return spec;
}

/// A constraint on an edge set; a null component is free.
model::ConstraintSpec hold(const char* edges, const char* ux, const char* uy) {
  model::ConstraintSpec c;
  c.edge_sets = {edges};
  if (ux) c.ux = ux;
  if (uy) c.uy = uy;
  return c;
}

/// The expression "(λ − 1)*var" to all digits: the displacement of a stretch λ along var.
std::string stretched(double l, const char* var) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g*%s", l - 1, var);
  return text;
}

/// The internal force conjugate to moving the side `on` rigidly along `component`: the work of
/// the internal forces on the virtual field that is 1 on that side's vertex modes (1 along the
/// side, 0 on the opposite one) — the side's resultant, totalled over the ring in axisymmetry.
double side_force(const model::Discretization& d, const Eigen::VectorXd& u, int component,
                  const std::function<bool(const Vec2&)>& on) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(d.n_dofs);
  model::FiniteStrainForces(d).add(u, f, nullptr, nullptr);
  const auto& body = d.bodies[0];
  double force = 0;
  for (int v = 0; v < body.mesh.n_nodes(); ++v)
    if (on(body.mesh.node(v))) force += f(body.dof_offset + 2 * body.dofs.vertex_mode(v) + component);
  return force;
}

/// What the FE gives of a homogeneous block: its stretches (from u at the far corner (a, h)),
/// the largest deviation of its Cauchy stresses (xx, yy, xy, zz or θθ) at sample points from
/// `expected` (relative to the largest of them), and the solution.
struct BlockResult {
  double l_x = 1, l_y = 1, stress_error = 0;
  model::Discretization d;
  Eigen::VectorXd u;
};

BlockResult solve_block(const model::ProblemSpec& spec, const std::array<double, 4>& expected) {
  BlockResult r{1, 1, 0, model::discretize(spec), {}};
  const auto sol = model::solve_contact(spec, r.d);
  EXPECT_TRUE(sol.converged) << sol.message;
  r.u = sol.u;
  const auto& body = r.d.bodies[0];
  const auto corner = post::evaluate(body, 0, 1, 1, sol.u);
  r.l_x = 1 + corner.u.x() / corner.x.x();
  r.l_y = 1 + corner.u.y() / corner.x.y();
  const double scale = std::max({std::abs(expected[0]), std::abs(expected[1]), std::abs(expected[3])});
  for (double xi : {-1.0, -0.3, 0.6, 1.0})
    for (double eta : {-1.0, 0.2, 1.0}) {
      const auto p = post::evaluate(body, 0, xi, eta, sol.u);
      const Eigen::Vector4d e(p.stress(0) - expected[0], p.stress(1) - expected[1], p.stress(2) - expected[2],
                              p.stress_zz - expected[3]);
      r.stress_error = std::max(r.stress_error, e.cwiseAbs().maxCoeff() / scale);
    }
  return r;
}

const double kStretches[] = {0.5, 0.8, 1.5, 2.0, 3.0};

/// The largest relative deviations from the closed forms over a test's cases, printed at its end.
struct Worst {
  double stretch = 0, stress = 0, force = 0;
  void add(double fe_stretch, double exact_stretch, double stress_error, double fe_force, double exact_force) {
    stretch = std::max(stretch, std::abs(fe_stretch - exact_stretch) / exact_stretch);
    stress = std::max(stress, stress_error);
    force = std::max(force, std::abs(fe_force - exact_force) / std::abs(exact_force));
  }
  void print(const char* state) const {
    std::printf("%s, largest relative deviation over laws and stretches: free stretch %.1e, "
                "Cauchy stress %.1e, force %.1e\n", state, stretch, stress, force);
  }
};

std::string label(const NamedLaw& law, double l) { return std::string(law.model) + " stretch " + std::to_string(l); }

}  // namespace

// Uniaxial: the cylinder 0 <= R <= a = 1, 0 <= Z <= h = 2 stretched axially by λ (u_z = 0 at
// the bottom, (λ − 1) h at the top, both ends free to slide radially, u_r = 0 on the axis, the
// lateral surface free) is the homogeneous F = diag(λ_r, λ, λ_r): the FE's λ_r (at R = a) is the
// closed form's root of σ_rr = 0 to 1e-9, σ_zz and σ_rr = σ_rz = σ_θθ = 0 at sample points to
// 1e-8 of σ_zz, the top's force π (λ_r a)² σ_zz to 1e-8 relative; λ = 0.5 … 3, each law.
TEST(RubberClosedForms, UniaxialStretchOfACylinder) {
  const double a = 1, h = 2;
  Worst worst;
  for (const auto& law : laws())
    for (double l : kStretches) {
      const auto exact = solve_free(law.k, {1, l, 1}, 0, 2);
      const double sigma = exact.sigma[1], l_r = exact.l[0];
      auto spec = block(law, model::PlaneMode::axisymmetric, a, h);
      spec.bodies[0].constraints = {hold("left", "0", nullptr), hold("bottom", nullptr, "0"),
                                    hold("top", nullptr, stretched(l, "y").c_str())};
      const auto r = solve_block(spec, {0, sigma, 0, 0});
      const std::string what = label(law, l);
      EXPECT_NEAR(r.l_x, l_r, 1e-9 * l_r) << what;
      EXPECT_NEAR(r.l_y, l, 1e-12) << what;
      EXPECT_LT(r.stress_error, 1e-8) << what;
      const double force = kPi * (l_r * a) * (l_r * a) * sigma;
      const double fe_force = side_force(r.d, r.u, 1, [&](const Vec2& X) { return std::abs(X.y() - h) < 1e-12; });
      EXPECT_NEAR(fe_force, force, 1e-8 * std::abs(force)) << what;
      worst.add(r.l_x, l_r, r.stress_error, fe_force, force);
    }
  worst.print("uniaxial");
}

// Equibiaxial: the disc 0 <= R <= a = 1, 0 <= Z <= h = 0.5 stretched radially by λ (u_r =
// (λ − 1) R on R = a, u_r = 0 on the axis, u_z = 0 at the bottom, the top free) is
// F = diag(λ, λ_z, λ): the FE's λ_z the root of σ_zz = 0 to 1e-9, σ_rr = σ_θθ at sample points to
// 1e-8 of σ_rr, and the rim's radial force 2π (λ a)(λ_z h) σ_rr to 1e-8 relative; λ = 0.5 … 3.
TEST(RubberClosedForms, EquibiaxialStretchOfADisc) {
  const double a = 1, h = 0.5;
  Worst worst;
  for (const auto& law : laws())
    for (double l : kStretches) {
      const auto exact = solve_free(law.k, {l, 1, l}, 1, -1);
      const double sigma = exact.sigma[0], l_z = exact.l[1];
      auto spec = block(law, model::PlaneMode::axisymmetric, a, h);
      spec.bodies[0].constraints = {hold("left", "0", nullptr), hold("bottom", nullptr, "0"),
                                    hold("right", stretched(l, "x").c_str(), nullptr)};
      const auto r = solve_block(spec, {sigma, 0, 0, sigma});
      const std::string what = label(law, l);
      EXPECT_NEAR(r.l_y, l_z, 1e-9 * l_z) << what;
      EXPECT_NEAR(r.l_x, l, 1e-12) << what;
      EXPECT_LT(r.stress_error, 1e-8) << what;
      const double force = 2 * kPi * (l * a) * (l_z * h) * sigma;
      const double fe_force = side_force(r.d, r.u, 0, [&](const Vec2& X) { return std::abs(X.x() - a) < 1e-12; });
      EXPECT_NEAR(fe_force, force, 1e-8 * std::abs(force)) << what;
      worst.add(r.l_y, l_z, r.stress_error, fe_force, force);
    }
  worst.print("equibiaxial");
}

// Planar tension (pure shear): the plane-strain block [0, 1] × [0, 0.5] stretched by λ along x
// (u_x = 0 on the left, (λ − 1) x on the right, u_y = 0 at the bottom, the top free; λ₃ = 1) is
// F = diag(λ, λ_y, 1): the FE's λ_y the root of σ_yy = 0 to 1e-9, σ_xx and σ_zz (≠ 0: the
// plane-strain constraint) at sample points to 1e-8 of σ_xx, the right side's force
// (λ_y h) σ_xx per unit thickness to 1e-8 relative; λ = 0.5 … 3.
TEST(RubberClosedForms, PlanarTensionInPlaneStrain) {
  const double a = 1, h = 0.5;
  Worst worst;
  for (const auto& law : laws())
    for (double l : kStretches) {
      const auto exact = solve_free(law.k, {l, 1, 1}, 1, -1);
      const double l_y = exact.l[1];
      auto spec = block(law, model::PlaneMode::plane_strain, a, h);
      spec.bodies[0].constraints = {hold("left", "0", nullptr), hold("bottom", nullptr, "0"),
                                    hold("right", stretched(l, "x").c_str(), nullptr)};
      const auto r = solve_block(spec, {exact.sigma[0], 0, 0, exact.sigma[2]});
      const std::string what = label(law, l);
      EXPECT_NEAR(r.l_y, l_y, 1e-9 * l_y) << what;
      EXPECT_LT(r.stress_error, 1e-8) << what;
      const double force = l_y * h * exact.sigma[0];
      const double fe_force = side_force(r.d, r.u, 0, [&](const Vec2& X) { return std::abs(X.x() - a) < 1e-12; });
      EXPECT_NEAR(fe_force, force, 1e-8 * std::abs(force)) << what;
      worst.add(r.l_y, l_y, r.stress_error, fe_force, force);
    }
  worst.print("planar tension");
}

// As K/μ grows the uniaxial σ_zz of the FE approaches the incompressible closed form
// σ = 2 (λ² − 1/λ)(W₁ + W₂/λ), W₁ = C10 + 2 C20 (I₁ − 3) + 3 C30 (I₁ − 3)², W₂ = C01,
// I₁ = λ² + 2/λ, with the difference falling like 1/K: tenfold (10 ± 0.5) from K/μ = 10³ to
// 10⁴, below 1e-3 relative at 10⁴; Mooney–Rivlin and Yeoh, λ = 0.5 and 2.
TEST(RubberClosedForms, NearlyIncompressibleLimitAtRateOneOverK) {
  const double a = 1, h = 2;
  for (auto law : {laws()[1], laws()[2]})
    for (double l : {0.5, 2.0}) {
      const auto& k = law.k;
      const double x = l * l + 2 / l - 3;
      const double incompressible = 2 * (l * l - 1 / l) * (k.C10 + 2 * k.C20 * x + 3 * k.C30 * x * x + k.C01 / l);
      std::vector<double> difference;
      for (double ratio : {1e3, 1e4}) {
        law.k.K = ratio * k.shear_modulus();
        auto spec = block(law, model::PlaneMode::axisymmetric, a, h);
        spec.bodies[0].constraints = {hold("left", "0", nullptr), hold("bottom", nullptr, "0"),
                                      hold("top", nullptr, stretched(l, "y").c_str())};
        const auto d = model::discretize(spec);
        const auto sol = model::solve_contact(spec, d);
        ASSERT_TRUE(sol.converged) << sol.message;
        const double sigma = post::evaluate(d.bodies[0], 0, 0.3, -0.2, sol.u).stress(1);
        difference.push_back(std::abs(sigma - incompressible) / std::abs(incompressible));
        std::printf("%s, stretch %g, K/mu = %g: |sigma - sigma_incompressible| / |sigma| = %.3e\n",
                    law.model, l, ratio, difference.back());
      }
      EXPECT_NEAR(difference[0] / difference[1], 10, 0.5) << label(law, l);
      EXPECT_LT(difference[1], 1e-3) << label(law, l);
    }
}

// Patch test: every boundary node of the distorted 2 × 2 patch moved by a uniform deformation
// gradient (plane strain F = [[1.3, 0.2], [−0.1, 0.85]]; axisymmetric F = diag(1.25, 0.8, 1.25)
// with u_r = 0 on the axis): the interior follows, and the Cauchy stresses at sample points of
// every element are the material point's at F to 1e-10 of their size; p = 2, 3, each law.
TEST(RubberClosedForms, DistortedPatchReproducesAUniformDeformation) {
  double worst = 0;
  for (const auto& law : laws())
    for (bool axisymmetric : {false, true})
      for (int p : {2, 3}) {
        auto spec = test_problems::distorted_patch(p);
        auto& b = spec.bodies[0];
        b.material = block(law, axisymmetric ? model::PlaneMode::axisymmetric : model::PlaneMode::plane_strain, 1,
                           1).bodies[0].material;
        Eigen::Matrix2d F;
        if (axisymmetric) {
          F << 1.25, 0, 0, 0.8;
          b.constraints = {hold("boundary", "0.25*x", "-0.2*y")};
        } else {
          F << 1.3, 0.2, -0.1, 0.85;
          b.constraints = {hold("boundary", "0.3*x + 0.2*y", "-0.1*x - 0.15*y")};
        }
        spec.solver.load_steps = 4;
        spec.solver.tolerance = 1e-13;
        const auto d = model::discretize(spec);
        const auto sol = model::solve_contact(spec, d);
        ASSERT_TRUE(sol.converged) << sol.message;
        const material::FiniteStrainLaw m{material::Law::yeoh, {}, law.k};  // the constants decide
        Eigen::Vector4d expected;
        if (axisymmetric) {
          double hoop = 0;
          const auto s = material::hoop_cauchy_stress(material::hoop_hyperelastic_state(m, F, F(0, 0)), F, F(0, 0), &hoop);
          expected << s, hoop;
        } else {
          double zz = 0;
          const auto s = material::cauchy_stress(material::hyperelastic_state(m, F), F, &zz);
          expected << s, zz;
        }
        double error = 0;
        for (int q = 0; q < d.bodies[0].mesh.n_quads(); ++q)
          for (auto [xi, eta] : {std::array<double, 2>{-0.9, -0.7}, {0.0, 0.0}, {0.77, 0.61}, {1.0, 1.0}}) {
            const auto r = post::evaluate(d.bodies[0], q, xi, eta, sol.u);
            const Eigen::Vector4d s(r.stress(0), r.stress(1), r.stress(2), r.stress_zz);
            error = std::max(error, (s - expected).cwiseAbs().maxCoeff() / expected.cwiseAbs().maxCoeff());
          }
        EXPECT_LT(error, 1e-10) << law.model << (axisymmetric ? " axisymmetric" : " plane strain") << " p " << p;
        worst = std::max(worst, error);
      }
  std::printf("patch test: largest relative stress deviation %.1e\n", worst);
}

// The analytic tangent of the whole nonlinear system — rubber internal forces (axisymmetric, the
// hoop row included) and penalty contact against the moving plate — equals central differences
// of the residual at the converged state of the Mooney–Rivlin O-ring (p = 2, penalty 1000 N/mm³, no friction) and of
// the same ring made Yeoh (C10 = 1.4, C20 = 0.1, C30 = 0.02): max |difference| below 1e-7 of
// max |K|.
TEST(RubberTangent, ORingAgreesWithCentralDifferences) {
  for (const char* law : {"mooney-rivlin", "yeoh"}) {
    auto spec = io::read_problem(std::string(HPC_SOURCE_DIR) + "/examples/o-ring/o-ring-mooney-rivlin.yaml",
                                 {"contact[0].enforcement=penalty", "contact[0].penalty=1000",
                                  "contact[0].friction.law=none", "discretization.degree=2"});
    auto& m = spec.bodies[0].material;
    if (std::string(law) == "yeoh") {
      m.model = law;
      m.C01 = 0;
      m.C20 = 0.1;
      m.C30 = 0.02;
    }
    const auto d = model::discretize(spec);
    const auto sol = model::solve_contact(spec, d);
    ASSERT_TRUE(sol.converged) << sol.message;
    const double mismatch = test_problems::tangent_mismatch(spec, d, sol);
    std::printf("%s O-ring: max |K_analytic - K_differences| / max |K| = %.3g\n", law, mismatch);
    EXPECT_LT(mismatch, 1e-7) << law;
  }
}
