// Property tests of the element stiffness: symmetry, positive semi-definiteness, rigid-body
// null space, energy of constant strain; p = 1..8 (hierarchic) and Lagrange Q4/Q8/Q9.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <vector>

#include "fem_test_meshes.hpp"
#include "hpcontact/fem/dof_map.hpp"
#include "hpcontact/fem/elasticity.hpp"
#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/material/linear_elastic.hpp"
#include "hpcontact/mesh/element_map.hpp"

using namespace hpcontact;
using basis::LagrangeType;

namespace {

material::LinearElastic steel(material::Plane plane = material::Plane::strain) {
  material::LinearElastic m;
  m.youngs_modulus = 210000;
  m.poisson_ratio = 0.3;
  m.plane = plane;
  return m;
}

fem::SpaceOptions hierarchic(int p, basis::Space space = basis::Space::tensor_product) {
  fem::SpaceOptions o;
  o.space = space;
  o.degrees = {{p, p}};
  return o;
}

fem::SpaceOptions lagrange(LagrangeType type) {
  fem::SpaceOptions o;
  o.lagrange = true;
  o.lagrange_type = type;
  return o;
}

/// Stiffness of the single element of `m`, and what is needed to build rigid-body modes.
struct Element {
  Eigen::MatrixXd K;
  int n_modes = 0;
  std::vector<Vec2> vertices;   ///< physical positions of the vertex modes (first 4 modes)
  std::vector<Vec2> lagrange;   ///< physical positions of all Lagrange nodes (Lagrange only)
  double area = 0;
};

Element element(const mesh::Mesh& m, const fem::SpaceOptions& o, int n_gauss,
                material::Plane plane = material::Plane::strain, double thickness = 1.0) {
  const fem::DofMap dofs(m, o);
  const auto& space = dofs.element(0);
  const auto map = o.lagrange ? mesh::ElementMap::isoparametric(m, 0, o.lagrange_type)
                              : mesh::ElementMap::blending(m, 0);
  const auto ev = fem::element_values(space, map, n_gauss, m, 0);
  Element e;
  e.K = fem::stiffness(ev, steel(plane).D(), thickness);
  e.n_modes = space.n_modes();
  for (int k = 0; k < 4; ++k) e.vertices.push_back(m.node(m.quad(0)[k]));
  e.lagrange = map.lagrange_nodes();
  e.area = ev.JxW.sum();
  return e;
}

/// Rigid translation in direction `comp`: the coefficient 1 on every vertex mode (the bilinear
/// vertex modes sum to one), 0 on edge and internal modes (hierarchic) — or 1 on every node
/// (Lagrange).
Eigen::VectorXd translation(const Element& e, int comp) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * e.n_modes);
  const int n = e.lagrange.empty() ? 4 : static_cast<int>(e.lagrange.size());
  for (int a = 0; a < n; ++a) r(comp * e.n_modes + a) = 1;
  return r;
}

/// Rigid rotation ux = -y, uy = x: exact on the vertex modes of a bilinear map (hierarchic,
/// straight sides) and on the nodes of an isoparametric map (Lagrange).
Eigen::VectorXd rotation(const Element& e) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * e.n_modes);
  const auto& x = e.lagrange.empty() ? e.vertices : e.lagrange;
  for (size_t a = 0; a < x.size(); ++a) {
    r(a) = -x[a].y();
    r(e.n_modes + a) = x[a].x();
  }
  return r;
}

/// Linear field u = A x + c on the same representation as rotation().
Eigen::VectorXd linear_field(const Element& e, const Eigen::Matrix2d& A, const Vec2& c) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * e.n_modes);
  const auto& x = e.lagrange.empty() ? e.vertices : e.lagrange;
  for (size_t a = 0; a < x.size(); ++a) {
    const Vec2 u = A * x[a] + c;
    r(a) = u.x();
    r(e.n_modes + a) = u.y();
  }
  return r;
}

/// Eigenvalues of K (ascending) divided by the largest.
Eigen::VectorXd relative_spectrum(const Eigen::MatrixXd& K) {
  const Eigen::MatrixXd Ks = 0.5 * (K + K.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Ks, Eigen::EigenvaluesOnly);
  return eig.eigenvalues() / eig.eigenvalues().maxCoeff();
}

int count_below(const Eigen::VectorXd& v, double tol) {
  return static_cast<int>((v.array().abs() < tol).count());
}

// Tolerances. Rigid-body modes give |K r| at the level of round-off in the sums of K (1e-16 times
// ||K|| ||r|| times a modest growth): 1e-12. A zero eigenvalue is below 1e-11 λ_max, and the
// smallest nonzero one is above 1e-7 λ_max here (the well-conditioned integrated-Legendre
// modes keep the spectrum within ~1e5 for p <= 8), so the count of zeros is unambiguous.
constexpr double kNullTol = 1e-12, kZeroEig = 1e-11, kNonzeroEig = 1e-7;

void check_element(const Element& e, bool rotation_exact, const std::string& what) {
  const Eigen::MatrixXd& K = e.K;
  const double Knorm = K.norm();
  // Symmetric to 1e-12 relative.
  EXPECT_LE((K - K.transpose()).norm(), 1e-12 * Knorm) << what;
  // Rigid-body modes are in the null space.
  std::vector<Eigen::VectorXd> rigid = {translation(e, 0), translation(e, 1)};
  if (rotation_exact) rigid.push_back(rotation(e));
  for (size_t k = 0; k < rigid.size(); ++k)
    EXPECT_LE((K * rigid[k]).norm(), kNullTol * Knorm * rigid[k].norm()) << what << " mode " << k;
  // Positive semi-definite with exactly 3 zero eigenvalues.
  const Eigen::VectorXd lambda = relative_spectrum(K);
  EXPECT_GT(lambda(0), -kZeroEig) << what;
  if (rotation_exact) {
    EXPECT_EQ(count_below(lambda, kZeroEig), 3) << what << ": spectrum starts " << lambda.head(5).transpose();
    EXPECT_GT(lambda(3), kNonzeroEig) << what << ": spectrum starts " << lambda.head(5).transpose();
  } else {
    // The rotation is not in the space of a curved blending element: the two translations are
    // exact zeros, the third eigenvalue is the energy of the rotation's approximation error
    // (checked by the caller), and nothing else is soft.
    EXPECT_LT(std::abs(lambda(0)), kZeroEig) << what;
    EXPECT_LT(std::abs(lambda(1)), kZeroEig) << what;
    EXPECT_GT(lambda(3), kNonzeroEig) << what << ": spectrum starts " << lambda.head(5).transpose();
  }
}

}  // namespace

// The hierarchic element stiffness of a straight-sided distorted quad shall be symmetric and
// positive semi-definite with exactly the three rigid-body modes in its null space, p = 1..8,
// tensor-product and trunk space.
TEST(ElementStiffness, HierarchicStraightSidedRigidBodyNullSpace) {
  const auto m = fem_test::distorted_quad();
  for (auto space : {basis::Space::tensor_product, basis::Space::trunk})
    for (int p = 1; p <= 8; ++p) {
      const Element e = element(m, hierarchic(p, space), p + 2);
      check_element(e, true, "p = " + std::to_string(p) +
                                 (space == basis::Space::trunk ? " trunk" : " tensor"));
    }
}

// On a curved (annular sector) blending element the stiffness shall be symmetric, positive
// semi-definite, have the two translations as exact null space, and its third eigenvalue (the
// energy of the best approximation of a rotation, which the space cannot represent) shall fall
// exponentially with p — by at least 10× per degree until it reaches round-off (1e-13) — for
// p = 1..8, with no other soft mode.
TEST(ElementStiffness, HierarchicCurvedElementNullSpace) {
  const auto m = fem_test::sector_quad();
  double previous = 1.0;
  for (int p = 1; p <= 8; ++p) {
    const Element e = element(m, hierarchic(p), p + 3);
    const std::string what = "sector p = " + std::to_string(p);
    check_element(e, false, what);
    const double third = relative_spectrum(e.K)(2);
    if (previous > 1e-13) EXPECT_LT(third, 0.1 * previous) << what;
    EXPECT_LT(third, 0.1) << what;
    previous = third;
  }
}

// The isoparametric Q4, Q8, Q9 stiffness shall be symmetric, positive semi-definite with exactly
// the three rigid-body modes as null space, on a straight distorted quad and on a curved sector
// (the isoparametric map reproduces rotations exactly).
TEST(ElementStiffness, LagrangeRigidBodyNullSpace) {
  const std::vector<std::pair<LagrangeType, int>> types = {
      {LagrangeType::q4, 2}, {LagrangeType::q8, 3}, {LagrangeType::q9, 3}};
  for (const auto& m : {fem_test::distorted_quad(), fem_test::sector_quad()})
    for (auto [type, n_gauss] : types) {
      const Element e = element(m, lagrange(type), n_gauss);
      check_element(e, true, m.context() + " Lagrange " + std::to_string(e.n_modes) + " nodes");
    }
}

// For a linear displacement field the strain energy u^T K u / 2 shall equal t·area·eps^T D eps / 2
// to 1e-12 relative, for plane strain and plane stress, hierarchic p = 1..8 and Lagrange.
TEST(ElementStiffness, EnergyOfConstantStrain) {
  Eigen::Matrix2d A;
  A << 2e-3, -5e-4, 1.5e-3, 3e-3;
  // Displacements of the size of the strains, so the round-off of u^T K u (~1e-16 ||K|| ||u||²)
  // stays far below 1e-12 of the energy; a large rigid part would only add cancellation.
  const Vec2 c(1e-3, -2e-3);
  const Eigen::Vector3d eps(A(0, 0), A(1, 1), A(0, 1) + A(1, 0));
  const double t = 2.5;
  const auto m = fem_test::distorted_quad();
  for (auto plane : {material::Plane::strain, material::Plane::stress}) {
    const double density = eps.dot(steel(plane).D() * eps);
    std::vector<std::pair<std::string, fem::SpaceOptions>> spaces;
    for (int p = 1; p <= 8; ++p) spaces.emplace_back("p = " + std::to_string(p), hierarchic(p));
    spaces.emplace_back("Q4", lagrange(LagrangeType::q4));
    spaces.emplace_back("Q8", lagrange(LagrangeType::q8));
    spaces.emplace_back("Q9", lagrange(LagrangeType::q9));
    for (const auto& [name, o] : spaces) {
      const Element e = element(m, o, 10, plane, t);
      const Eigen::VectorXd u = linear_field(e, A, c);
      const double energy = u.dot(e.K * u), exact = t * e.area * density;
      EXPECT_NEAR(energy, exact, 1e-12 * exact) << name;
      // Shoelace area of the straight quad.
      double shoelace = 0;
      for (int k = 0; k < 4; ++k) {
        const Vec2 &a = e.vertices[k], &b = e.vertices[(k + 1) % 4];
        shoelace += 0.5 * (a.x() * b.y() - b.x() * a.y());
      }
      EXPECT_NEAR(e.area, shoelace, 1e-14 * shoelace) << name;
    }
  }
}
