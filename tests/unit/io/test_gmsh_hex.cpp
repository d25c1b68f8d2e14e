// Unit tests of the 3D Gmsh import: hexahedra (8, 20, 27 nodes) and boundary quads read from MSH
// 4.1.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gmsh_box.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/io/gmsh_reader.hpp"

namespace hio = hpcontact::io;
namespace mesh = hpcontact::mesh;
using hpcontact::InputError;
using hpcontact::test::Box;
using hpcontact::test::box_msh;
using hpcontact::test::line_starting;
using mesh::Vec3;

// The 3D parser shall read nodes with their z, hexahedra of 8, 20 and 27 nodes in Gmsh's order
// with their volume's physical groups, and the boundary quads with their surface's groups.
TEST(GmshVolumeReader, ReadsHexahedraAndBoundaryQuads) {
  struct Case {
    int order;
    bool serendipity;
    int type, n_nodes, quad_type, n_grid;
  };
  for (const Case c : {Case{1, false, 5, 8, 3, 27}, Case{2, true, 17, 20, 16, 125},
                       Case{2, false, 12, 27, 10, 125}}) {
    SCOPED_TRACE(c.type);
    Box box;
    box.order = c.order;
    box.serendipity = c.serendipity;
    const std::string text = box_msh(box);
    const hio::GmshVolumeMesh m = hio::parse_gmsh_volume(text, "box.msh");
    EXPECT_EQ(m.file, "box.msh");
    ASSERT_EQ(m.nodes.size(), static_cast<std::size_t>(c.n_grid));
    EXPECT_EQ(m.nodes.at(c.n_grid), (std::array<double, 3>{1, 1, 1}));
    ASSERT_EQ(m.hexes.size(), 8u);
    EXPECT_EQ(m.hexes[0].type, c.type);
    ASSERT_EQ(m.hexes[0].nodes.size(), static_cast<std::size_t>(c.n_nodes));
    EXPECT_EQ(m.hexes[0].groups, std::vector<std::string>{"box"});
    EXPECT_EQ(m.hexes[0].tag, 25);
    EXPECT_EQ(m.hexes[0].line, line_starting(text, "25 "));
    // Node n of the first hexahedron sits at kHex27Nodes[n] in the cell [-1, 0]^3.
    for (std::size_t n = 0; n < m.hexes[0].nodes.size(); ++n)
      for (int d = 0; d < 3; ++d)
        EXPECT_EQ(m.nodes.at(m.hexes[0].nodes[n])[static_cast<std::size_t>(d)],
                  -0.5 + 0.5 * mesh::kHex27Nodes[n][d]);
    ASSERT_EQ(m.quads.size(), 24u);
    EXPECT_EQ(m.quads[5].type, c.quad_type);
    EXPECT_EQ(m.quads[5].entity, 2);
    EXPECT_EQ(m.quads[5].groups, std::vector<std::string>{"x1"});
    EXPECT_TRUE(m.other_volumes.empty());
    ASSERT_EQ(m.groups.size(), 7u);
    EXPECT_EQ(m.groups[6].dim, 3);
    EXPECT_EQ(m.groups[6].name, "box");
  }
}

// The 2D parser shall keep refusing a 3D mesh at its first node off the plane z = 0.
TEST(GmshVolumeReader, TheTwoDimensionalReaderRefusesIt) {
  const std::string text = box_msh({});
  try {
    hio::parse_gmsh(text, "box.msh");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "box.msh:" + std::to_string(line_starting(text, "-1 -1 -1\n")) +
                  ": node 1 is not in the plane z = 0 (z = 1); hpcontact reads 2D meshes in the "
                  "xy plane");
  }
}
