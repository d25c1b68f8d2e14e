// The axisymmetric total Lagrangian element: tangent = df/du and force = dU/du (central
// differences) on an element touching the axis and on a curved one away from it, the linear
// axisymmetric stiffness at u = 0, and a hoop fold detected.
#include "hpcontact/fem/axisymmetric_finite_strain.hpp"

#include <gtest/gtest.h>

#include "fem_test_meshes.hpp"
#include "hpcontact/fem/dof_map.hpp"
#include "hpcontact/fem/elasticity.hpp"
#include "hpcontact/mesh/element_map.hpp"

using namespace hpcontact;

namespace {

material::LinearElastic elastic(double nu) {
  material::LinearElastic m;
  m.youngs_modulus = 1000;
  m.poisson_ratio = nu;
  m.plane = material::Plane::axisymmetric;
  return m;
}

struct Setup {
  mesh::Mesh mesh;
  fem::DofMap dofs;
  mesh::ElementMap map;
  fem::ElementValues ev;
  std::vector<int> on_axis;  ///< local modes not zero on the axis (their u_r must be 0)
};

/// A distorted straight quad with its edge from node 4 to node 1 on the axis R = 0.
mesh::Mesh axis_quad() {
  return mesh::Mesh({Vec2(0, 0), Vec2(2, 0.3), Vec2(2.4, 1.9), Vec2(0, 1.5)}, {1, 2, 3, 4},
                    {{0, 1, 2, 3}}, {1}, {}, "axis quad");
}

Setup setup(mesh::Mesh m, int p) {
  fem::SpaceOptions o;
  o.degrees = {{p, p}};
  fem::DofMap dofs(m, o);
  auto map = mesh::ElementMap::blending(m, 0);
  auto ev = fem::element_values(dofs.element(0), map, p + 2, m, 0);
  std::vector<int> on_axis;
  for (double eta : {-1.0, -0.6, -0.1, 0.3, 0.8, 1.0}) {  // along xi = -1 (nodes 4 to 1)
    const auto pv = fem::point_values(dofs.element(0), map, -1, eta);
    if (std::abs(pv.x.x()) > 1e-14) continue;
    for (int a = 0; a < pv.N.size(); ++a)
      if (std::abs(pv.N(a)) > 1e-14 && std::find(on_axis.begin(), on_axis.end(), a) == on_axis.end())
        on_axis.push_back(a);
  }
  return {std::move(m), std::move(dofs), std::move(map), std::move(ev), on_axis};
}

/// Random coefficients of a large displacement, u_r = 0 on the axis (the body's constraint).
Eigen::VectorXd displacement(const Setup& s, double scale) {
  std::srand(11);
  Eigen::VectorXd u = scale * Eigen::VectorXd::Random(2 * s.ev.n_modes());
  for (int a : s.on_axis) u(a) = 0;
  return u;
}

/// The finite-strain laws at the small-strain constants of elastic(nu) (E = 1000): the two of E, ν
/// and the rubber laws of the same μ and K, their higher constants large enough to matter.
std::vector<material::FiniteStrainLaw> laws(double nu) {
  const auto m = elastic(nu);
  const double mu = m.mu(), K = m.lambda() + 2 * mu / 3;
  material::RubberConstants neo{.C10 = mu / 2, .K = K}, mr = neo, yeoh = neo;
  mr.C10 = 0.35 * mu;
  mr.C01 = 0.15 * mu;
  yeoh.C20 = 0.2 * mu;
  yeoh.C30 = 0.05 * mu;
  return {{material::Law::saint_venant_kirchhoff, m},
          {material::Law::neo_hooke, m},
          {material::Law::neo_hooke_split, m, neo},
          {material::Law::mooney_rivlin, m, mr},
          {material::Law::yeoh, m, yeoh}};
}

}  // namespace

// K against central differences of f_int (h = 1e-7), < 1e-6 of max |K|; f_int against
// differences of the energy, < 1e-6 of max |f|; K symmetric. p = 2 and 4, every finite-strain law
// (the rubber laws of laws() among them), on the element touching the axis (its u_r held there)
// and on the curved sector 1 <= R <= 2.
TEST(AxisymmetricFiniteStrainElement, TangentAndForceAgreeWithFiniteDifferences) {
  for (bool touches_axis : {true, false})
    for (int p : {2, 4})
      for (const auto& law : laws(0.3)) {
        const auto s = setup(touches_axis ? axis_quad() : fem_test::sector_quad(), p);
        EXPECT_EQ(s.on_axis.empty(), !touches_axis);
        const int n = 2 * s.ev.n_modes();
        const Eigen::VectorXd u = displacement(s, 0.05);
        const auto el = fem::axisymmetric_finite_strain_element(s.ev, law, u, true);
        ASSERT_FALSE(el.inverted()) << "det F " << el.min_J;
        ASSERT_LT(el.min_J, 0.95);  // a large deformation, not a small one
        const double h = 1e-7;
        Eigen::MatrixXd K_fd(n, n);
        Eigen::VectorXd f_fd(n);
        for (int b = 0; b < n; ++b) {
          Eigen::VectorXd up = u, um = u;
          up(b) += h;
          um(b) -= h;
          const auto ep = fem::axisymmetric_finite_strain_element(s.ev, law, up, false);
          const auto em = fem::axisymmetric_finite_strain_element(s.ev, law, um, false);
          K_fd.col(b) = (ep.f_int - em.f_int) / (2 * h);
          f_fd(b) = (ep.energy - em.energy) / (2 * h);
        }
        const double scale = el.K.cwiseAbs().maxCoeff();
        const std::string what = std::string(touches_axis ? "axis" : "sector") + " " +
                                 material::law_name(law.law) + " p " + std::to_string(p);
        EXPECT_LT((K_fd - el.K).cwiseAbs().maxCoeff(), 1e-6 * scale) << what;
        EXPECT_LT((el.K - el.K.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale) << what;
        EXPECT_LT((f_fd - el.f_int).cwiseAbs().maxCoeff(), 1e-6 * el.f_int.cwiseAbs().maxCoeff())
            << what;
      }
}

// At u = 0 the tangent is the linear axisymmetric stiffness (hoop row included; the rubber laws
// of the same μ and K too) and the force and energy vanish.
TEST(AxisymmetricFiniteStrainElement, TangentAtRestIsLinearStiffness) {
  for (bool touches_axis : {true, false})
    for (const auto& law : laws(0.3)) {
      const auto s = setup(touches_axis ? axis_quad() : fem_test::sector_quad(), 3);
      const int n = 2 * s.ev.n_modes();
      const auto el = fem::axisymmetric_finite_strain_element(s.ev, law,
                                                              Eigen::VectorXd::Zero(n), true);
      const Eigen::MatrixXd K = fem::axisymmetric_stiffness(s.ev, elastic(0.3));
      EXPECT_LT((el.K - K).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff());
      EXPECT_EQ(el.f_int.norm(), 0.0);
      EXPECT_EQ(el.energy, 0.0);
    }
}

// u_r = −1.5 R folds the ring through the axis: F_θθ = −0.5 while the meridian det F = −0.5
// too, so det F of the 3-D map is +0.25 — the element must still be reported inverted.
TEST(AxisymmetricFiniteStrainElement, HoopFoldIsDetected) {
  const auto s = setup(fem_test::sector_quad(), 2);
  const int nm = s.ev.n_modes();
  Eigen::VectorXd target(s.ev.n_points());
  for (int k = 0; k < s.ev.n_points(); ++k) target(k) = -1.5 * s.ev.x[k].x();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * nm);
  u.head(nm) = s.ev.N.transpose().colPivHouseholderQr().solve(target);
  const auto el = fem::axisymmetric_finite_strain_element(
      s.ev, {material::Law::neo_hooke, elastic(0.3)}, u, true);
  EXPECT_TRUE(el.inverted());
  EXPECT_NEAR(el.min_J, -0.5, 0.05);
  EXPECT_EQ(el.f_int.size(), 0);
}
