// Property tests of the global mode numbering: counts, minimum rule, trunk space, sharing.
#include "hpcontact/fem/dof_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "fem_test_meshes.hpp"
#include "hpcontact/core/error.hpp"

using namespace hpcontact;

namespace {

fem::SpaceOptions uniform(int p, int n_elements, basis::Space space) {
  fem::SpaceOptions o;
  o.space = space;
  o.degrees.assign(n_elements, {p, p});
  return o;
}

/// Internal modes phi_i phi_j, 2 <= i, j <= p, i + j <= p of the trunk space, counted by hand.
int trunk_internal(int p) { return p < 4 ? 0 : (p - 2) * (p - 3) / 2; }

/// Every global mode is used by some element, each element's modes are distinct, and the last
/// n_internal local modes of every element are its own internal modes (index >= n_external).
void check_numbering(const mesh::Mesh& m, const fem::DofMap& d, const std::string& what) {
  std::vector<int> used(d.n_modes(), 0);
  std::set<int> internal_seen;
  for (int q = 0; q < m.n_quads(); ++q) {
    const auto& es = d.element(q);
    const std::set<int> distinct(es.modes.begin(), es.modes.end());
    EXPECT_EQ(static_cast<int>(distinct.size()), es.n_modes()) << what << " element " << q;
    if (!es.is_lagrange) EXPECT_EQ(es.n_modes(), es.hierarchic.n_modes()) << what;
    for (int a = 0; a < es.n_modes(); ++a) {
      const int g = es.modes[a];
      ASSERT_GE(g, 0);
      ASSERT_LT(g, d.n_modes());
      ++used[g];
      const bool internal = a >= es.n_modes() - es.n_internal;
      EXPECT_EQ(internal, g >= d.n_external_modes()) << what << " element " << q << " mode " << a;
      if (internal) EXPECT_TRUE(internal_seen.insert(g).second) << "internal mode shared";
    }
    for (int k = 0; k < 4; ++k) EXPECT_EQ(es.modes[k], d.vertex_mode(m.quad(q)[k]));
  }
  for (int g = 0; g < d.n_modes(); ++g) EXPECT_GT(used[g], 0) << what << " mode " << g;
  EXPECT_EQ(d.n_dofs(), 2 * d.n_modes());
}

}  // namespace

// On a 2×2 mesh of uniform degree p the tensor-product space shall have 9 vertex modes,
// 12(p−1) edge modes and 4(p−1)² internal modes, p = 1..10.
TEST(DofMapProperties, TensorProductCountsOnTwoByTwo) {
  const auto m = fem_test::mesh_2x2();
  for (int p = 1; p <= 10; ++p) {
    const fem::DofMap d(m, uniform(p, 4, basis::Space::tensor_product));
    EXPECT_EQ(d.n_external_modes(), 9 + 12 * (p - 1)) << "p = " << p;
    EXPECT_EQ(d.n_modes(), 9 + 12 * (p - 1) + 4 * (p - 1) * (p - 1)) << "p = " << p;
    for (int e = 0; e < m.n_edges(); ++e) EXPECT_EQ(d.edge_degree(e), p);
    check_numbering(m, d, "tensor p = " + std::to_string(p));
  }
}

// The trunk space shall keep the vertex and edge modes and have (p−2)(p−3)/2 internal modes per
// element (i + j <= p), p = 1..10.
TEST(DofMapProperties, TrunkSpaceCountsOnTwoByTwo) {
  const auto m = fem_test::mesh_2x2();
  for (int p = 1; p <= 10; ++p) {
    const fem::DofMap d(m, uniform(p, 4, basis::Space::trunk));
    EXPECT_EQ(d.n_external_modes(), 9 + 12 * (p - 1)) << "p = " << p;
    EXPECT_EQ(d.n_modes(), 9 + 12 * (p - 1) + 4 * trunk_internal(p)) << "p = " << p;
    for (int q = 0; q < 4; ++q) EXPECT_EQ(d.element(q).n_internal, trunk_internal(p));
    check_numbering(m, d, "trunk p = " + std::to_string(p));
  }
}

// A shared edge shall get the smaller of its two neighbours' degrees along it (minimum rule),
// and both elements shall use the same global modes for it, in the same order.
TEST(DofMapProperties, MinimumRuleOnSharedEdges) {
  const auto m = fem_test::mesh_2x2();
  // Nodes 0..8 row by row; element 3 is (8, 7, 4, 5): its local xi runs from node 8 to 7.
  fem::SpaceOptions o;
  o.degrees = {{3, 5}, {6, 2}, {4, 4}, {7, 3}};
  const fem::DofMap d(m, o);
  // Expected degree of each edge by hand. Elements 0..2 have xi along +x; element 3 has xi along
  // -x, so its horizontal edges (local E1, E3) carry p_xi = 7 and its vertical ones p_eta = 3.
  struct Expect {
    int a, b, degree;
  };
  const std::vector<Expect> expected = {
      {0, 1, 3},  // bottom of element 0 (p_xi 3)
      {1, 2, 6},  // bottom of element 1 (p_xi 6)
      {0, 3, 5},  // left of element 0 (p_eta 5)
      {1, 4, 2},  // element 0 right (5), element 1 left (2)
      {2, 5, 2},  // right of element 1 (p_eta 2)
      {3, 4, 3},  // element 0 top (3), element 2 bottom (4)
      {4, 5, 6},  // element 1 top (6), element 3 bottom (7)
      {3, 6, 4},  // left of element 2 (4)
      {4, 7, 3},  // element 2 right (4), element 3 (p_eta 3)
      {5, 8, 3},  // right of element 3 (p_eta 3)
      {6, 7, 4},  // top of element 2 (4)
      {7, 8, 7},  // top of element 3 (p_xi 7)
  };
  int total_edge_modes = 0;
  for (const auto& x : expected) {
    const int e = m.find_edge(x.a, x.b);
    ASSERT_GE(e, 0);
    EXPECT_EQ(d.edge_degree(e), x.degree) << "edge " << x.a << "-" << x.b;
    total_edge_modes += x.degree - 1;
  }
  EXPECT_EQ(d.n_external_modes(), 9 + total_edge_modes);
  EXPECT_EQ(d.n_modes(), 9 + total_edge_modes + 2 * 4 + 5 * 1 + 3 * 3 + 6 * 2);
  // Each element sees the edge degree and the shared global modes of every one of its edges.
  for (int q = 0; q < 4; ++q) {
    const auto& es = d.element(q);
    int local = 4;
    for (int le = 0; le < 4; ++le) {
      const int e = m.quad_edge(q, le);
      EXPECT_EQ(es.hierarchic.edge_degree[le], d.edge_degree(e));
      EXPECT_LE(es.hierarchic.edge_degree[le], le % 2 == 0 ? o.degrees[q][0] : o.degrees[q][1]);
      EXPECT_EQ(es.hierarchic.edge_reversed[le], m.quad_edge_reversed(q, le));
      for (int k = 2; k <= d.edge_degree(e); ++k) EXPECT_EQ(es.modes[local++], d.edge_mode(e, k));
    }
  }
  check_numbering(m, d, "minimum rule");
}

// The Lagrange spaces on a 2×2 mesh shall have 9 (Q4), 9 + 12 (Q8) and 9 + 12 + 4 (Q9) modes,
// the Q9 centre nodes being the internal ones.
TEST(DofMapProperties, LagrangeCounts) {
  const auto m = fem_test::mesh_2x2();
  for (auto [type, n, n_ext] : std::vector<std::tuple<basis::LagrangeType, int, int>>{
           {basis::LagrangeType::q4, 9, 9},
           {basis::LagrangeType::q8, 21, 21},
           {basis::LagrangeType::q9, 25, 21}}) {
    fem::SpaceOptions o;
    o.lagrange = true;
    o.lagrange_type = type;
    const fem::DofMap d(m, o);
    EXPECT_EQ(d.n_modes(), n);
    EXPECT_EQ(d.n_external_modes(), n_ext);
    for (int q = 0; q < 4; ++q)
      EXPECT_EQ(d.element(q).n_modes(), basis::lagrange_n_nodes(type));
    check_numbering(m, d, "Lagrange " + std::to_string(n));
  }
}

// Missing or non-positive degrees shall be InputErrors naming the element.
TEST(DofMapProperties, BadDegreesAreRejected) {
  const auto m = fem_test::mesh_2x2();
  fem::SpaceOptions o;
  o.degrees = {{2, 2}, {2, 2}, {2, 2}};
  EXPECT_THROW(fem::DofMap(m, o), InputError);
  o.degrees = {{2, 2}, {2, 0}, {2, 2}, {2, 2}};
  try {
    fem::DofMap d(m, o);
    ADD_FAILURE() << "no InputError for degree 0";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("element 2"), std::string::npos) << e.what();
  }
}
