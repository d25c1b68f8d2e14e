// Patch tests of hexahedral p-elasticity: the six uniform strain states are reproduced exactly on
// distorted straight-sided and on curved (triquadratic) hexahedra; the rigid motions are the
// stiffness's null space on whole meshes; bad elements are refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "../unit/mesh/hex_test_meshes.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/fem/hex_assembly.hpp"
#include "hpcontact/fem/hex_elasticity.hpp"
#include "hpcontact/fem/hex_values.hpp"
#include "hpcontact/mesh/hex_topology.hpp"
#include "hpcontact/solve/fixed_dofs.hpp"

using namespace hpcontact;
using mesh::Vec3;

namespace {

material::LinearElastic steel() {
  material::LinearElastic m;
  m.youngs_modulus = 210000;
  m.poisson_ratio = 0.3;
  return m;
}

/// An nx × ny × nz block of hexes with every node moved (up to 0.18 of the spacing in each
/// direction; boundary nodes off the block's planes too), so that no face is a parallelogram and
/// no element is affine; curved: triquadratic maps whose mid-edge, mid-face and centre nodes are
/// moved off their straight places by a smooth function of the straight place (so that
/// neighbours agree on their shared nodes).
struct HexMesh {
  mesh::HexTopology topology;
  std::vector<Vec3> nodes;
  std::vector<mesh::HexMap> maps;
};

HexMesh distorted_block(int nx, int ny, int nz, bool curved) {
  const hex_test::HexBlock block = hex_test::hex_block(nx, ny, nz);
  std::vector<Vec3> nodes;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.18, 0.18);
  for (const auto& g : block.positions) nodes.push_back(Vec3(g[0], g[1], g[2]) + Vec3(u(rng), u(rng), u(rng)));
  HexMesh m{mesh::HexTopology(block.hexes, block.n_nodes(), "distorted block"), nodes, {}};
  for (const auto& h : block.hexes) {
    std::array<Vec3, 8> v;
    for (int i = 0; i < 8; ++i) v[i] = nodes[h[i]];
    const mesh::HexMap straight = mesh::HexMap::trilinear(v);
    if (!curved) {
      m.maps.push_back(straight);
      continue;
    }
    std::array<Vec3, 27> x;
    for (int n = 0; n < 27; ++n) {
      const auto* c = mesh::kHex27Nodes[n];
      x[n] = straight.map(c[0], c[1], c[2]);
      if (n >= 8)
        x[n] += 0.05 * Vec3(std::sin(2.1 * x[n].y() + 1.3 * x[n].z()), std::cos(1.7 * x[n].x() - 0.9 * x[n].z()),
                           std::sin(1.1 * x[n].x() + 2.3 * x[n].y()));
    }
    m.maps.push_back(mesh::HexMap::triquadratic(x));
  }
  return m;
}

/// u(x) = ε x + c + ω × x for the unit Voigt strain `state` (engineering shears: γ = 1 gives
/// ε_ij = ε_ji = 1/2), with a rigid part; state 6..11: the rigid motions alone (translations
/// e_0..e_2, rotations about e_0..e_2).
Vec3 exact_field(int state, const Vec3& x) {
  if (state >= 6) {
    const int r = state - 6;
    return r < 3 ? Vec3::Unit(r) : Vec3(Vec3::Unit(r - 3).cross(x));
  }
  Eigen::Matrix3d eps = Eigen::Matrix3d::Zero();
  const int pairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  const auto [i, j] = pairs[state];
  eps(i, j) = eps(j, i) = i == j ? 1.0 : 0.5;
  return eps * x + Vec3(0.1, -0.2, 0.3) + Vec3(0.05, 0.1, -0.07).cross(x);
}

material::Voigt3 exact_strain(int state) {
  material::Voigt3 e = material::Voigt3::Zero();
  if (state < 6) e(state) = 1;
  return e;
}

/// Global coefficients (3 * mode + component) of the fields `states`, one column each: on every
/// element the local L2 projection onto its space, exact when the field lies in it. Reports the
/// largest disagreement of two elements on a shared mode and the largest misfit of the projection
/// at the Gauss points, both relative to the field's size: round-off if and only if the field lies
/// in the global space.
struct Projection {
  Eigen::MatrixXd coefficients;
  double disagreement = 0, misfit = 0;
};

Projection project(const HexMesh& m, const fem::HexDofMap& dofs, const std::vector<int>& states) {
  Projection out;
  const int n_cases = static_cast<int>(states.size());
  out.coefficients = Eigen::MatrixXd::Constant(dofs.n_dofs(), n_cases, std::nan(""));
  double scale = 0;
  for (int h = 0; h < m.topology.n_hexes(); ++h) {
    const fem::HexElementSpace& space = dofs.element(h);
    const fem::HexValues v =
        fem::hex_values(space.hierarchic, m.maps[h], fem::hex_gauss_points(space.hierarchic, m.maps[h]));
    const int n = v.n_modes(), nq = v.n_points();
    Eigen::MatrixXd values(nq, 3 * n_cases);
    for (int q = 0; q < nq; ++q)
      for (int s = 0; s < n_cases; ++s) values.block(q, 3 * s, 1, 3) = exact_field(states[s], v.x[q]).transpose();
    scale = std::max(scale, values.cwiseAbs().maxCoeff());
    // The least-squares problem min |W^(1/2) (Nᵀ c − values)| by QR: the normal equations (the
    // mass matrix) would square its condition number, which grows fast with p for hierarchic modes.
    const Eigen::VectorXd root_w = v.JxW.cwiseSqrt();
    const Eigen::MatrixXd A = root_w.asDiagonal() * v.N.transpose();
    const Eigen::MatrixXd c = A.colPivHouseholderQr().solve(root_w.asDiagonal() * values);  // n × 3 cases
    out.misfit = std::max(out.misfit, (v.N.transpose() * c - values).cwiseAbs().maxCoeff());
    for (int a = 0; a < n; ++a)
      for (int s = 0; s < n_cases; ++s)
        for (int i = 0; i < 3; ++i) {
          double& g = out.coefficients(3 * space.modes[a] + i, s);
          if (!std::isnan(g)) out.disagreement = std::max(out.disagreement, std::abs(g - c(a, 3 * s + i)));
          g = c(a, 3 * s + i);
        }
  }
  out.disagreement /= scale;
  out.misfit /= scale;
  return out;
}

/// Dofs of the modes on the boundary: vertex, edge and face modes of every boundary face.
std::vector<int> boundary_dofs(const mesh::HexTopology& t, const fem::HexDofMap& dofs) {
  std::set<int> modes;
  for (int f : t.boundary_faces()) {
    const auto& corners = t.face(f).vertices;
    for (int c = 0; c < 4; ++c) {
      modes.insert(dofs.vertex_mode(corners[c]));
      const int e = t.find_edge(corners[c], corners[(c + 1) % 4]);
      for (int k = 2; k <= dofs.edge_degree(e); ++k) modes.insert(dofs.edge_mode(e, k));
    }
    for (int k = 0; k < dofs.n_face_modes(f); ++k) modes.insert(dofs.face_first_mode(f) + k);
  }
  std::vector<int> out;
  for (int a : modes)
    for (int i = 0; i < 3; ++i) out.push_back(3 * a + i);
  return out;
}

/// Largest error, relative to the exact values, of (a) the coefficients of the non-boundary dofs
/// and (b) the stresses at every element's Gauss points, over the six strain states.
struct PatchErrors {
  double coefficients = 0, stresses = 0, projection = 0;
};

/// The exact coefficients on a straight-sided mesh: a field linear in x is trilinear in ξ, so its
/// vertex modes carry the nodal values and every other mode 0.
Eigen::MatrixXd nodal_coefficients(const HexMesh& m, const fem::HexDofMap& dofs, const std::vector<int>& states) {
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(dofs.n_dofs(), states.size());
  for (size_t s = 0; s < states.size(); ++s)
    for (int node = 0; node < m.topology.n_nodes(); ++node)
      c.col(s).segment<3>(3 * dofs.vertex_mode(node)) = exact_field(states[s], m.nodes[node]);
  return c;
}

/// The patch test with the exact coefficients from nodal values (straight-sided meshes) or from
/// the projection (curved ones).
PatchErrors patch_test(const HexMesh& m, int p, basis::Space space, bool condense, bool nodal) {
  fem::HexSpaceOptions options;
  options.space = space;
  options.degrees.assign(m.topology.n_hexes(), {p, p, p});
  const fem::HexDofMap dofs(m.topology, options);
  const std::vector<int> states{0, 1, 2, 3, 4, 5};
  Projection exact = project(m, dofs, states);
  if (nodal) {
    const Eigen::MatrixXd c = nodal_coefficients(m, dofs, states);
    exact.disagreement = std::max(exact.disagreement, (exact.coefficients - c).cwiseAbs().maxCoeff() /
                                                          c.cwiseAbs().maxCoeff());
    exact.coefficients = c;
  }

  fem::HexBody body{&dofs, m.maps, steel(), Vec3::Zero(), "patch"};
  const fem::HexSystem system = fem::assemble_hex_elasticity(body, {condense});
  const std::vector<int> fixed = boundary_dofs(m.topology, dofs);
  Eigen::MatrixXd values(fixed.size(), states.size());
  for (size_t r = 0; r < fixed.size(); ++r) values.row(r) = exact.coefficients.row(fixed[r]);
  const Eigen::MatrixXd u_solved = solve::solve_with_fixed_dofs(system.K, system.f, fixed, values);

  PatchErrors errors;
  errors.projection = std::max(exact.disagreement, exact.misfit);
  const material::Elasticity3 D = steel().D3();
  std::vector<bool> on_boundary(dofs.n_dofs(), false);
  for (int d : fixed) on_boundary[d] = true;
  for (size_t s = 0; s < states.size(); ++s) {
    const Eigen::VectorXd u = system.recover(dofs, u_solved.col(s));
    const Eigen::VectorXd& c = exact.coefficients.col(s);
    const double c_scale = c.cwiseAbs().maxCoeff();
    for (int d = 0; d < dofs.n_dofs(); ++d)
      if (!on_boundary[d]) errors.coefficients = std::max(errors.coefficients, std::abs(u(d) - c(d)) / c_scale);
    const material::Voigt3 sigma_exact = D * exact_strain(states[s]);
    for (int h = 0; h < m.topology.n_hexes(); ++h) {
      const fem::HexElementSpace& es = dofs.element(h);
      const int n = es.n_modes();
      Eigen::VectorXd u_e(3 * n);
      for (int a = 0; a < n; ++a)
        for (int i = 0; i < 3; ++i) u_e(i * n + a) = u(3 * es.modes[a] + i);
      const fem::HexValues v = fem::hex_values(es.hierarchic, m.maps[h], fem::hex_gauss_points(es.hierarchic, m.maps[h]));
      const Eigen::MatrixXd sigma = D * fem::hex_strains(v, u_e);
      errors.stresses = std::max(errors.stresses, (sigma.colwise() - sigma_exact).cwiseAbs().maxCoeff() /
                                                      sigma_exact.cwiseAbs().maxCoeff());
    }
  }
  return errors;
}

}  // namespace

// On distorted straight-sided hexes a linear field is trilinear in ξ, so it lies in every space
// (tensor and trunk, p >= 1), and its coefficients are the nodal values on the vertex modes and 0
// on all others: the elementwise L2 projection (least squares by QR) shall give exactly that (to
// 1e-12 of the field; measured ≤ 5e-13, at tensor p = 8), and the solution with the boundary dofs
// prescribed to those values shall reproduce the interior coefficients and the stresses at every
// Gauss point to 1e-10 relative (measured: coefficients ≤ 1.4e-14, stresses ≤ 1.2e-13), for the
// six unit strain states plus a rigid part, p = 1..8, tensor and trunk. Mesh: 2 × 2 × 2 elements
// (one interior node) for p <= 4, 2 × 2 × 1 (an interior edge and face) for p >= 5 to keep the
// file's time down; internal modes condensed for p >= 3 and not below (both paths are tested).
TEST(HexPatch, UniformStrainOnDistortedStraightHexes) {
  for (auto space : {basis::Space::tensor_product, basis::Space::trunk})
    for (int p = 1; p <= 8; ++p) {
      const HexMesh m = p <= 4 ? distorted_block(2, 2, 2, false) : distorted_block(2, 2, 1, false);
      const std::string where = std::string(space == basis::Space::trunk ? "trunk" : "tensor") + " p " +
                                std::to_string(p);
      const PatchErrors e = patch_test(m, p, space, p >= 3, true);
      EXPECT_LE(e.projection, 1e-12) << where;
      EXPECT_LE(e.coefficients, 1e-10) << where;
      EXPECT_LE(e.stresses, 1e-10) << where;
    }
}

// On curved hexes (triquadratic maps, mid-edge/face/centre nodes moved) u = ε x(ξ) is triquadratic
// in ξ: in the tensor space for p >= 2, in the trunk space (superlinear degree of ξ²η²ζ² is 6)
// for p >= 6. There the patch test shall hold as above, with the coefficients from the projection
// (projection consistent and exact to 1e-12, measured ≤ 3.7e-13; coefficients and stresses to
// 1e-10, measured ≤ 4.4e-13 and ≤ 7.7e-12, both at tensor p = 8). Below
// those degrees the projection shall visibly miss the field (misfit > 1e-4), so the test can tell
// a space that lacks it (measured: 8.6e-3 at tensor p = 1, 3.6e-3 at trunk p = 5). Mesh as above: 2 × 2 × 2 for p <= 4, 2 × 2 × 1 above.
TEST(HexPatch, UniformStrainOnCurvedHexes) {
  struct Case {
    basis::Space space;
    int p;
    bool contained;
  };
  std::vector<Case> cases{{basis::Space::tensor_product, 1, false}, {basis::Space::trunk, 5, false}};
  for (int p = 2; p <= 8; ++p) cases.push_back({basis::Space::tensor_product, p, true});
  for (int p = 6; p <= 8; ++p) cases.push_back({basis::Space::trunk, p, true});
  for (const Case& c : cases) {
    const HexMesh m = c.p <= 4 ? distorted_block(2, 2, 2, true) : distorted_block(2, 2, 1, true);
    const std::string where = std::string(c.space == basis::Space::trunk ? "trunk" : "tensor") + " p " +
                              std::to_string(c.p);
    if (!c.contained) {
      fem::HexSpaceOptions options{c.space, std::vector<std::array<int, 3>>(m.topology.n_hexes(), {c.p, c.p, c.p})};
      const Projection exact = project(m, fem::HexDofMap(m.topology, options), {0, 1, 2, 3, 4, 5});
      EXPECT_GT(exact.misfit, 1e-4) << where;
      continue;
    }
    const PatchErrors e = patch_test(m, c.p, c.space, c.p >= 3, false);
    EXPECT_LE(e.projection, 1e-12) << where;
    EXPECT_LE(e.coefficients, 1e-10) << where;
    EXPECT_LE(e.stresses, 1e-10) << where;
  }
}

// The assembled stiffness of a whole mesh shall annihilate the six rigid motions: |K r| <= 1e-13
// |K|_F |r| (measured ≤ 4e-16), on the distorted straight 2 × 2 × 2 block at p = 1..3 (tensor and
// trunk) and on the curved one at tensor p = 2, 3, with and without condensation.
TEST(HexPatch, RigidMotionsOnMeshes) {
  for (bool curved : {false, true})
    for (auto space : {basis::Space::tensor_product, basis::Space::trunk})
      for (int p = curved ? 2 : 1; p <= 3; ++p) {
        if (curved && space == basis::Space::trunk) continue;
        const HexMesh m = distorted_block(2, 2, 2, curved);
        fem::HexSpaceOptions options{space, std::vector<std::array<int, 3>>(m.topology.n_hexes(), {p, p, p})};
        const fem::HexDofMap dofs(m.topology, options);
        const Projection rigid = project(m, dofs, {6, 7, 8, 9, 10, 11});
        for (bool condense : {false, true}) {
          fem::HexBody body{&dofs, m.maps, steel(), Vec3::Zero(), "rigid"};
          const fem::HexSystem system = fem::assemble_hex_elasticity(body, {condense});
          const int n = static_cast<int>(system.K.rows());
          double worst = 0;
          for (int r = 0; r < 6; ++r) {
            const Eigen::VectorXd x = rigid.coefficients.col(r).head(n);
            worst = std::max(worst, (system.K * x).norm() / (system.K.norm() * x.norm()));
          }
          EXPECT_LE(worst, 1e-13) << "curved " << curved << " p " << p << " condense " << condense;
        }
      }
}

// Assembly shall refuse an inverted element and a degenerate one (a collapsed edge) with a
// MeshError naming the body and the element.
TEST(HexPatch, BadElementsAreRefusedByName) {
  auto message = [](const HexMesh& m) -> std::string {
    fem::HexSpaceOptions options{basis::Space::tensor_product,
                                 std::vector<std::array<int, 3>>(m.topology.n_hexes(), {2, 2, 2})};
    const fem::HexDofMap dofs(m.topology, options);
    fem::HexBody body{&dofs, m.maps, steel(), Vec3::Zero(), "block"};
    try {
      fem::assemble_hex_elasticity(body);
    } catch (const MeshError& e) {
      return e.what();
    }
    return "";
  };
  HexMesh m = distorted_block(2, 1, 1, false);
  EXPECT_EQ(message(m), "");
  // Element 1's vertex V1 (node 2 of the 3 × 2 × 2 grid) pushed past the opposite face x = 1.
  HexMesh inverted = m;
  std::array<Vec3, 8> v;
  for (int i = 0; i < 8; ++i) v[i] = inverted.nodes[inverted.topology.hex(1)[i]];
  v[1].x() = 0.0;
  inverted.maps[1] = mesh::HexMap::trilinear(v);
  const std::string a = message(inverted);
  EXPECT_NE(a.find("block: element 1 has a negative Jacobian determinant"), std::string::npos) << a;
  HexMesh collapsed = m;
  for (int i = 0; i < 8; ++i) v[i] = collapsed.nodes[collapsed.topology.hex(0)[i]];
  v[5] = v[4];
  collapsed.maps[0] = mesh::HexMap::trilinear(v);
  const std::string b = message(collapsed);
  EXPECT_NE(b.find("block: element 0 has a vanishing Jacobian determinant"), std::string::npos) << b;
}
