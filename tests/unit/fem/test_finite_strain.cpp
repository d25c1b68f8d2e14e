// The total Lagrangian element: internal force = dU/du, tangent = df/du (central differences),
// the linear stiffness at u = 0, and inversion detected.
#include "hpcontact/fem/finite_strain.hpp"

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
  return m;
}

struct Setup {
  mesh::Mesh mesh;
  fem::DofMap dofs;
  mesh::ElementMap map;
  fem::ElementValues ev;
};

Setup sector(int p) {
  auto m = fem_test::sector_quad();
  fem::SpaceOptions o;
  o.degrees = {{p, p}};
  fem::DofMap dofs(m, o);
  auto map = mesh::ElementMap::blending(m, 0);
  auto ev = fem::element_values(dofs.element(0), map, p + 2, m, 0);
  return {std::move(m), std::move(dofs), std::move(map), std::move(ev)};
}

/// A smooth, large displacement field's coefficients: random, scaled to keep det F > 0.
Eigen::VectorXd displacement(int size, double scale) {
  std::srand(7);
  return scale * Eigen::VectorXd::Random(size);
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

// K against central differences of f_int (h = 1e-7 of the displacement scale), < 1e-6 of max|K|,
// for p = 2 and 4 on a curved element, every law of laws(); f_int against differences of the energy.
TEST(FiniteStrainElement, TangentAndForceAgreeWithFiniteDifferences) {
  for (int p : {2, 4})
    for (const auto& law : laws(0.3)) {
      const auto s = sector(p);
      const int n = 2 * s.ev.n_modes();
      const Eigen::VectorXd u = displacement(n, 0.05);
      const auto el = fem::finite_strain_element(s.ev, law, 1.0, u, true);
      ASSERT_FALSE(el.inverted()) << "det F " << el.min_J;
      ASSERT_GT(el.min_J, 0.5);  // a large deformation, not a small one
      const double h = 1e-7;
      Eigen::MatrixXd K_fd(n, n);
      Eigen::VectorXd f_fd(n);
      for (int b = 0; b < n; ++b) {
        Eigen::VectorXd up = u, um = u;
        up(b) += h;
        um(b) -= h;
        const auto ep = fem::finite_strain_element(s.ev, law, 1.0, up, false);
        const auto em = fem::finite_strain_element(s.ev, law, 1.0, um, false);
        K_fd.col(b) = (ep.f_int - em.f_int) / (2 * h);
        f_fd(b) = (ep.energy - em.energy) / (2 * h);
      }
      const double scale = el.K.cwiseAbs().maxCoeff();
      EXPECT_LT((K_fd - el.K).cwiseAbs().maxCoeff(), 1e-6 * scale) << material::law_name(law.law) << " p " << p;
      EXPECT_LT((el.K - el.K.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale);
      EXPECT_LT((f_fd - el.f_int).cwiseAbs().maxCoeff(), 1e-6 * el.f_int.cwiseAbs().maxCoeff());
    }
}

// At u = 0 the tangent is the linear stiffness (every law of laws() reduces to D at F = I) and the
// internal force vanishes.
TEST(FiniteStrainElement, TangentAtRestIsLinearStiffness) {
  for (const auto& law : laws(0.3)) {
    const auto s = sector(3);
    const int n = 2 * s.ev.n_modes();
    const auto el = fem::finite_strain_element(s.ev, law, 2.0, Eigen::VectorXd::Zero(n), true);
    const Eigen::MatrixXd K = fem::stiffness(s.ev, elastic(0.3).D(), 2.0);
    EXPECT_LT((el.K - K).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff());
    EXPECT_EQ(el.f_int.norm(), 0.0);
    EXPECT_EQ(el.energy, 0.0);
  }
}

// A displacement that turns the element inside out (u = -2X: x = -X, det F = 1 would pass, so
// u = -1.5 X·e_x folds x over: det F = -0.5) is reported with det F and the point.
TEST(FiniteStrainElement, InversionIsDetected) {
  const auto s = sector(2);
  const int nm = s.ev.n_modes();
  // Coefficients of u = (-1.5 X, 0): the vertex modes carry the nodal values of the linear field
  // only on a straight element, so use the least-squares fit of the values at the points.
  Eigen::VectorXd target(s.ev.n_points());
  for (int k = 0; k < s.ev.n_points(); ++k) target(k) = -1.5 * s.ev.x[k].x();
  const Eigen::VectorXd cx = s.ev.N.transpose().colPivHouseholderQr().solve(target);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * nm);
  u.head(nm) = cx;
  const auto el = fem::finite_strain_element(s.ev, {material::Law::neo_hooke, elastic(0.3)}, 1.0, u, true);
  EXPECT_TRUE(el.inverted());
  EXPECT_NEAR(el.min_J, -0.5, 0.05);
  EXPECT_GE(el.min_J_point, 0);
  EXPECT_EQ(el.f_int.size(), 0);
}
