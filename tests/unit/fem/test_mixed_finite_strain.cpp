// The mixed u–p element: its residual equals central differences of Π_e and its tangent central
// differences of the residual (1e-7 relative), plane strain on a curved sector and axisymmetric
// on a distorted quad away from the axis, compressible (K/μ = 5000) and incompressible (1/K = 0);
// the pressure block at rest; a fold.
#include "hpcontact/fem/mixed_finite_strain.hpp"

#include <gtest/gtest.h>

#include <string>

#include "fem_test_meshes.hpp"
#include "hpcontact/mesh/element_map.hpp"

using namespace hpcontact;

namespace {

struct Setup {
  mesh::Mesh mesh;
  fem::DofMap dofs;
  mesh::ElementMap map;
  fem::ElementValues ev;
  Eigen::MatrixXd psi;
};

Setup setup(mesh::Mesh m, int p) {
  fem::SpaceOptions o;
  o.degrees = {{p, p}};
  fem::DofMap dofs(m, o);
  auto map = mesh::ElementMap::blending(m, 0);
  auto ev = fem::element_values(dofs.element(0), map, p + 2, m, 0);
  auto psi = fem::pressure_modes_at_gauss_points(fem::pressure_degree(dofs.element(0)), p + 2);
  return {std::move(m), std::move(dofs), std::move(map), std::move(ev), std::move(psi)};
}

std::vector<std::pair<std::string, material::RubberConstants>> laws() {
  return {{"neo-hooke", {.C10 = 0.5}},
          {"mooney-rivlin", {.C10 = 0.35, .C01 = 0.15}},
          {"yeoh", {.C10 = 0.5, .C20 = 0.1, .C30 = 0.02}}};
}

struct Case {
  const char* name;
  bool axisymmetric;
  mesh::Mesh mesh;
};

std::vector<Case> cases() {
  mesh::Mesh away({Vec2(1, 0), Vec2(3, 0.3), Vec2(3.4, 1.9), Vec2(0.8, 1.5)}, {1, 2, 3, 4}, {{0, 1, 2, 3}},
                  {1}, {}, "quad away from the axis");
  return {{"plane strain, curved sector", false, fem_test::sector_quad()},
          {"axisymmetric, distorted quad", true, away}};
}

}  // namespace

TEST(MixedFiniteStrain, ResidualIsTheGradientOfPiAndTangentItsJacobian) {
  for (const auto& c : cases())
    for (int p : {2, 4})
      for (const auto& [name, law] : laws())
        for (double inverse_bulk : {1.0 / 5000, 0.0}) {
          const auto s = setup(c.mesh, p);
          const int n = s.ev.n_modes(), m = static_cast<int>(s.psi.rows());
          const fem::OutOfPlane oop(0.7, c.axisymmetric);
          std::srand(7);
          Eigen::VectorXd x(2 * n + m);
          x.head(2 * n) = 0.05 * Eigen::VectorXd::Random(2 * n);
          x.tail(m) = 0.3 * Eigen::VectorXd::Random(m);
          auto element = [&](const Eigen::VectorXd& y, bool tangent) {
            return fem::mixed_finite_strain_element(s.ev, s.psi, law, inverse_bulk, oop, y.head(2 * n),
                                                    y.tail(m), tangent);
          };
          const auto el = element(x, true);
          ASSERT_FALSE(el.inverted());
          const int N = 2 * n + m;
          Eigen::VectorXd f_fd(N);
          Eigen::MatrixXd K_fd(N, N);
          const double h = 1e-6;
          for (int a = 0; a < N; ++a) {
            Eigen::VectorXd xp = x, xm = x;
            xp(a) += h;
            xm(a) -= h;
            const auto ep = element(xp, false), em = element(xm, false);
            f_fd(a) = (ep.energy - em.energy) / (2 * h);
            K_fd.col(a) = (ep.f_int - em.f_int) / (2 * h);
          }
          const std::string what = std::string(c.name) + ", " + name + ", p " + std::to_string(p) +
                                   ", 1/K " + std::to_string(inverse_bulk);
          EXPECT_LT((el.f_int - f_fd).cwiseAbs().maxCoeff(), 1e-7 * el.f_int.cwiseAbs().maxCoeff()) << what;
          EXPECT_LT((el.K - K_fd).cwiseAbs().maxCoeff(), 1e-7 * el.K.cwiseAbs().maxCoeff()) << what;
          EXPECT_LT((el.K - el.K.transpose()).cwiseAbs().maxCoeff(), 1e-12 * el.K.cwiseAbs().maxCoeff()) << what;
        }
}

// Under no displacement and no pressure the residual is zero and the tangent's pressure block is
// −∫ ψ ψᵀ / K dV: with ψ₀ = 1 its (0, 0) entry is −(area × thickness) / K.
TEST(MixedFiniteStrain, PressureBlockIsTheMassOverK) {
  const auto s = setup(fem_test::distorted_quad(), 3);
  const int n = s.ev.n_modes(), m = static_cast<int>(s.psi.rows());
  const double K = 250, t = 2;
  const auto el = fem::mixed_finite_strain_element(s.ev, s.psi, {.C10 = 1}, 1 / K, fem::OutOfPlane(t),
                                                   Eigen::VectorXd::Zero(2 * n), Eigen::VectorXd::Zero(m), true);
  EXPECT_LT(el.f_int.cwiseAbs().maxCoeff(), 1e-14);
  const double area = s.ev.JxW.sum();
  EXPECT_NEAR(el.K(2 * n, 2 * n), -area * t / K, 1e-13 * area * t / K);
}

// Inverted: a fold in the plane is reported as in the displacement element.
TEST(MixedFiniteStrain, FoldIsInverted) {
  const auto s = setup(fem_test::distorted_quad(), 2);
  const int n = s.ev.n_modes(), m = static_cast<int>(s.psi.rows());
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * n);
  u(1) = -5;  // vertex 2 far across vertex 1
  const auto el = fem::mixed_finite_strain_element(s.ev, s.psi, {.C10 = 1}, 0, fem::OutOfPlane(1), u,
                                                   Eigen::VectorXd::Zero(m), true);
  EXPECT_TRUE(el.inverted());
}
