// Unit tests of the Gmsh import: the MSH 4.1 parser, the body made of it (corner order, arcs
// recovered from midside nodes or named, edge sets of physical groups), bodies[].gmsh in a
// problem file, and one-line errors naming the .msh file and line for bad or hostile input.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "edit_text.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/io/gmsh_import.hpp"
#include "hpcontact/io/gmsh_reader.hpp"
#include "hpcontact/io/problem_reader.hpp"

namespace hio = hpcontact::io;
namespace fs = std::filesystem;
using hpcontact::InputError;
using hpcontact::IoError;

namespace {

// Two unit squares side by side, 4-node quads, physical lines "bottom" and "top" and the surface
// "plate". Line numbers matter to the tests: node tags on lines 19-24, coordinates 25-30, the
// quads on lines 41 and 42.
const std::string plate = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
3
1 1 "bottom"
1 2 "top"
2 3 "plate"
$EndPhysicalNames
$Entities
0 2 1 0
1 0 0 0 2 0 0 1 1 0
2 0 1 0 2 1 0 1 2 0
1 0 0 0 2 1 0 1 3 0
$EndEntities
$Nodes
1 6 1 6
2 1 0 6
1
2
3
4
5
6
0 0 0
1 0 0
2 0 0
0 1 0
1 1 0
2 1 0
$EndNodes
$Elements
3 6 1 6
1 1 1 2
1 1 2
2 2 3
1 2 1 2
3 5 4
4 6 5
2 1 3 2
5 1 2 5 4
6 2 3 6 5
$EndElements
)";

using hpcontact::test::with;

/// The message of the InputError that parsing (and importing, with `options`) `text` throws,
/// checked to be one line holding every fragment.
std::string msh_error(const std::string& text, const std::vector<std::string>& fragments,
                      const hio::ImportOptions& options = {}) {
  try {
    hio::import_gmsh_body(hio::parse_gmsh(text, "plate.msh"), options);
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    for (const std::string& f : fragments)
      EXPECT_NE(message.find(f), std::string::npos) << "'" << f << "' not in: " << message;
    return message;
  }
  ADD_FAILURE() << "no InputError; expected " << (fragments.empty() ? "" : fragments[0]);
  return "";
}

/// A quarter annulus 1 <= r <= 2, 0 <= angle <= 90°, of n quads along the angle, as a .msh:
/// order 1 (4-node quads, 2-node lines) or 2 (9-node quads, or 8-node with `serendipity`,
/// 3-node lines). Physical lines "inner" (r = 1), "outer" (r = 2), "bottom" (y = 0), "left"
/// (x = 0); surface "ring". Corner tags 1 + i (n + 1) + j for radius i, angle j.
/// `clockwise`: every quad's nodes listed clockwise.
std::string annulus_msh(int n, int order, bool clockwise = false, bool serendipity = false) {
  const auto corner = [&](int i, int j) { return 1 + i * (n + 1) + j; };
  const auto radial_mid = [&](int j) { return 2 * (n + 1) + 1 + j; };
  const auto arc_mid = [&](int i, int j) { return 3 * (n + 1) + 1 + i * n + j; };
  const auto centre = [&](int j) { return 3 * (n + 1) + 2 * n + 1 + j; };
  const double dt = std::numbers::pi / 2 / n;
  std::vector<std::pair<int, std::array<double, 2>>> nodes;
  const auto polar = [](double r, double t) {
    return std::array<double, 2>{r * std::cos(t), r * std::sin(t)};
  };
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j <= n; ++j) nodes.emplace_back(corner(i, j), polar(1 + i, j * dt));
  if (order == 2) {
    for (int j = 0; j <= n; ++j) nodes.emplace_back(radial_mid(j), polar(1.5, j * dt));
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < n; ++j) nodes.emplace_back(arc_mid(i, j), polar(1 + i, (j + 0.5) * dt));
    if (!serendipity)
      for (int j = 0; j < n; ++j) nodes.emplace_back(centre(j), polar(1.5, (j + 0.5) * dt));
  }
  std::ostringstream os;
  os.precision(17);
  os << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n5\n1 1 \"inner\"\n1 2 "
        "\"outer\"\n1 3 \"bottom\"\n1 4 \"left\"\n2 5 \"ring\"\n$EndPhysicalNames\n"
     << "$Entities\n0 4 1 0\n";
  for (int c = 1; c <= 4; ++c) os << c << " -2 -2 0 2 2 0 1 " << c << " 0\n";
  os << "1 -2 -2 0 2 2 0 1 5 0\n$EndEntities\n";
  os << "$Nodes\n1 " << nodes.size() << " 1 " << nodes.size() << "\n2 1 0 " << nodes.size() << "\n";
  for (const auto& [tag, p] : nodes) os << tag << "\n";
  for (const auto& [tag, p] : nodes) os << p[0] << " " << p[1] << " 0\n";
  os << "$EndNodes\n";
  const int line_type = order == 2 ? 8 : 1;
  const int quad_type = order == 1 ? 3 : serendipity ? 16 : 10;
  os << "$Elements\n5 " << 3 * n + 2 << " 1 " << 3 * n + 2 << "\n";
  int tag = 1;
  for (int i = 0; i < 2; ++i) {
    os << "1 " << i + 1 << " " << line_type << " " << n << "\n";
    for (int j = 0; j < n; ++j) {
      os << tag++ << " " << corner(i, j) << " " << corner(i, j + 1);
      if (order == 2) os << " " << arc_mid(i, j);
      os << "\n";
    }
  }
  for (int k = 0; k < 2; ++k) {
    const int j = k == 0 ? 0 : n;
    os << "1 " << k + 3 << " " << line_type << " 1\n"
       << tag++ << " " << corner(0, j) << " " << corner(1, j);
    if (order == 2) os << " " << radial_mid(j);
    os << "\n";
  }
  os << "2 1 " << quad_type << " " << n << "\n";
  for (int j = 0; j < n; ++j) {
    std::array<int, 4> c{corner(0, j), corner(1, j), corner(1, j + 1), corner(0, j + 1)};
    std::array<int, 4> m{radial_mid(j), arc_mid(1, j), radial_mid(j + 1), arc_mid(0, j)};
    if (clockwise) {
      c = {c[0], c[3], c[2], c[1]};
      m = {m[3], m[2], m[1], m[0]};
    }
    os << tag++;
    for (int v : c) os << " " << v;
    if (order == 2)
      for (int v : m) os << " " << v;
    if (order == 2 && !serendipity) os << " " << centre(j);
    os << "\n";
  }
  os << "$EndElements\n";
  return os.str();
}

/// Twice the signed area of the corner polygon of an imported element.
double area2(const hio::ImportedMesh& m, const std::array<int, 4>& v) {
  std::map<int, std::array<double, 2>> xy(m.nodes.begin(), m.nodes.end());
  double a = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    const auto &p = xy.at(v[k]), &q = xy.at(v[(k + 1) % 4]);
    a += p[0] * q[1] - p[1] * q[0];
  }
  return a;
}

}  // namespace

// The parser shall read nodes, 4-node quads and 2-node lines with their physical group names.
TEST(GmshReader, ReadsFirstOrderQuadsAndPhysicalNames) {
  const hio::GmshMesh m = hio::parse_gmsh(plate, "plate.msh");
  ASSERT_EQ(m.nodes.size(), 6u);
  EXPECT_EQ(m.nodes.at(6), (std::array<double, 2>{2, 1}));
  ASSERT_EQ(m.quads.size(), 2u);
  EXPECT_EQ(m.quads[1].tag, 6);
  EXPECT_EQ(m.quads[1].corners, (std::array<int, 4>{2, 3, 6, 5}));
  EXPECT_EQ(m.quads[1].midside, (std::array<int, 4>{0, 0, 0, 0}));
  EXPECT_EQ(m.quads[1].groups, std::vector<std::string>{"plate"});
  EXPECT_EQ(m.quads[1].line, 42);
  ASSERT_EQ(m.lines.size(), 4u);
  EXPECT_EQ(m.lines[2].ends, (std::array<int, 2>{5, 4}));
  EXPECT_EQ(m.lines[2].groups, std::vector<std::string>{"top"});
  ASSERT_EQ(m.groups.size(), 3u);
  EXPECT_EQ(m.groups[2].name, "plate");
  EXPECT_EQ(m.groups[2].dim, 2);
}

// The body shall be the quads with their corner nodes (gmsh tags as ids), every 1D physical
// group an edge set, a first-order mesh without arcs.
TEST(GmshImport, MakesBodyOfFirstOrderMesh) {
  const hio::ImportedMesh b = hio::import_gmsh_body(hio::parse_gmsh(plate, "plate.msh"), {});
  ASSERT_EQ(b.nodes.size(), 6u);
  EXPECT_EQ(b.nodes[0].first, 1);
  ASSERT_EQ(b.elements.size(), 2u);
  EXPECT_EQ(b.elements[0], (std::pair<int, std::array<int, 4>>{5, {1, 2, 5, 4}}));
  EXPECT_TRUE(b.arcs.empty());
  ASSERT_EQ(b.edge_sets.size(), 2u);
  EXPECT_EQ(b.edge_sets[0].first, "bottom");
  EXPECT_EQ(b.edge_sets[0].second, (std::vector<std::array<int, 2>>{{1, 2}, {2, 3}}));
  EXPECT_EQ(b.edge_sets[1].first, "top");
  EXPECT_DOUBLE_EQ(b.size, std::sqrt(5.0));
}

// Second-order quads (9- and 8-node) shall keep their midside nodes, and every curved edge shall
// become the arc of the circle it lies on: centre and radius to round-off, oriented through its
// midside node; straight edges stay straight.
TEST(GmshImport, RecoversArcsOfSecondOrderQuads) {
  for (bool serendipity : {false, true}) {
    SCOPED_TRACE(serendipity ? "8-node" : "9-node");
    const hio::GmshMesh m = hio::parse_gmsh(annulus_msh(3, 2, false, serendipity), "ring.msh");
    ASSERT_EQ(m.quads.size(), 3u);
    EXPECT_EQ(m.quads[0].type, serendipity ? 16 : 10);
    EXPECT_EQ(m.quads[0].midside, (std::array<int, 4>{9, 16, 10, 13}));
    EXPECT_EQ(m.lines[0].midside, 13);
    const hio::ImportedMesh b = hio::import_gmsh_body(m, {});
    EXPECT_EQ(b.nodes.size(), 8u);  // corners only
    ASSERT_EQ(b.arcs.size(), 6u);
    EXPECT_EQ(b.n_recovered_arcs, 6);
    for (const auto& arc : b.arcs) {
      const bool outer = arc.nodes[0] > 4;  // corner tags 5-8 lie on r = 2
      EXPECT_NEAR(arc.radius, outer ? 2.0 : 1.0, 1e-14);
      EXPECT_NEAR(arc.center[0], 0.0, 1e-14);
      EXPECT_NEAR(arc.center[1], 0.0, 1e-14);
      // The elements run counter-clockwise: along the outer arc with the angle, the inner against.
      EXPECT_EQ(arc.ccw, outer ? 1 : -1);
      EXPECT_EQ(arc.nodes[1] - arc.nodes[0], outer ? 1 : -1);
    }
    EXPECT_EQ(b.edge_sets.size(), 4u);
  }
}

// A single arc's circle through three close nodes is ill-conditioned; neighbouring arcs of one
// circle shall be fitted to one circle, exact to round-off even for short edges.
TEST(GmshImport, FitsOneCircleToNeighbouringArcs) {
  const hio::ImportedMesh b =
      hio::import_gmsh_body(hio::parse_gmsh(annulus_msh(200, 2), "ring.msh"), {});
  ASSERT_EQ(b.arcs.size(), 400u);
  for (const auto& arc : b.arcs) {
    EXPECT_NEAR(arc.radius, arc.nodes[0] > 201 ? 2.0 : 1.0, 1e-13);
    EXPECT_NEAR(std::hypot(arc.center[0], arc.center[1]), 0.0, 1e-13);
  }
}

// Clockwise quads shall be turned counter-clockwise, keeping their edges and arcs.
TEST(GmshImport, TurnsClockwiseQuadsCounterClockwise) {
  for (int order : {1, 2}) {
    const hio::ImportedMesh ccw =
        hio::import_gmsh_body(hio::parse_gmsh(annulus_msh(2, order), "r.msh"), {});
    const hio::ImportedMesh cw =
        hio::import_gmsh_body(hio::parse_gmsh(annulus_msh(2, order, true), "r.msh"), {});
    ASSERT_EQ(cw.elements.size(), 2u);
    for (std::size_t e = 0; e < 2; ++e) {
      EXPECT_GT(area2(cw, cw.elements[e].second), 0);
      EXPECT_EQ(cw.elements[e].second, ccw.elements[e].second);
    }
    ASSERT_EQ(cw.arcs.size(), ccw.arcs.size());
    for (std::size_t a = 0; a < cw.arcs.size(); ++a) {
      EXPECT_EQ(cw.arcs[a].nodes, ccw.arcs[a].nodes);
      EXPECT_EQ(cw.arcs[a].ccw, ccw.arcs[a].ccw);
    }
  }
}

// Arcs named by a physical group shall make every edge of the group an arc; a node off the
// circle, an unknown group or a group of no body edge shall be errors naming the option.
TEST(GmshImport, MakesNamedArcs) {
  const hio::GmshMesh m = hio::parse_gmsh(annulus_msh(4, 1), "ring.msh");
  hio::ImportOptions o;
  o.arcs = {{"outer", {0, 0}, 2}, {"inner", {0, 0}, 1}};
  const hio::ImportedMesh b = hio::import_gmsh_body(m, o);
  ASSERT_EQ(b.arcs.size(), 8u);
  EXPECT_EQ(b.arcs[0].nodes, (std::array<int, 2>{6, 7}));
  EXPECT_EQ(b.arcs[0].radius, 2);
  EXPECT_EQ(b.arcs[0].ccw, 0);
  EXPECT_EQ(b.n_recovered_arcs, 0);
  const auto option_error = [&](const hio::ImportOptions& options, const std::string& key,
                                const std::string& fragment) {
    try {
      hio::import_gmsh_body(m, options);
      ADD_FAILURE() << "no error; expected " << fragment;
    } catch (const hio::GmshOptionError& e) {
      EXPECT_EQ(e.key, key);
      EXPECT_NE(e.what_text.find(fragment), std::string::npos) << e.what_text;
    }
  };
  o.arcs = {{"outer", {0, 0}, 2.1}};
  option_error(o, "arcs[0]", "is at distance 2 from the centre, not on the circle of radius 2.1");
  o.arcs = {{"rim", {0, 0}, 2}};
  option_error(o, "arcs[0].edges",
               "no 1D physical group of that name in ring.msh (defined: inner, outer, bottom, "
               "left) (got 'rim')");
  o.arcs = {{"outer", {0, 0}, 2}, {"outer", {0, 0}, 2}};
  option_error(o, "arcs[1].edges", "already has a curve from arcs[0]");
  o.arcs = {{"outer", {0, 0}, 2}};
  o.edges_with_curves = {{7, 6}};
  option_error(o, "arcs[0].edges", "edge [6, 7] (ring.msh:");
  hio::ImportOptions s;
  s.surface = "disc";
  option_error(s, "surface", "no 2D physical group of that name in ring.msh (defined: ring)");
}

// With `surface`, only that group's quads shall form the body: one file holds two bodies.
TEST(GmshImport, SelectsQuadsOfASurface) {
  std::string text = with(plate, "1 0 0 0 2 1 0 1 3 0", "1 0 0 0 1 1 0 1 3 0\n2 1 0 0 2 1 0 1 4 0");
  text = with(text, "0 2 1 0\n", "0 2 2 0\n");
  text = with(text, "2 3 \"plate\"", "2 3 \"left\"\n2 4 \"right\"");
  text = with(text, "3\n1 1 \"bottom\"", "4\n1 1 \"bottom\"");
  text = with(text, "3 6 1 6\n", "4 6 1 6\n");
  text = with(text, "2 1 3 2\n5 1 2 5 4\n6 2 3 6 5\n", "2 1 3 1\n5 1 2 5 4\n2 2 3 1\n6 2 3 6 5\n");
  const hio::GmshMesh m = hio::parse_gmsh(text, "plate.msh");
  hio::ImportOptions o;
  o.surface = "right";
  const hio::ImportedMesh b = hio::import_gmsh_body(m, o);
  ASSERT_EQ(b.elements.size(), 1u);
  EXPECT_EQ(b.elements[0].first, 6);
  EXPECT_EQ(b.nodes.size(), 4u);
  // Each edge set keeps the group's lines on this body's edges.
  ASSERT_EQ(b.edge_sets.size(), 2u);
  EXPECT_EQ(b.edge_sets[0].second, (std::vector<std::array<int, 2>>{{2, 3}}));
  EXPECT_EQ(b.edge_sets[1].second, (std::vector<std::array<int, 2>>{{6, 5}}));
}

// The format shall be MSH 4.1 ASCII; anything else a one-line error naming file and line.
TEST(GmshReader, RejectsOtherFormats) {
  msh_error(with(plate, "4.1 0 8", "4.1 1 8"),
            {"plate.msh:2: binary .msh is not read; hpcontact reads ASCII (Mesh.Binary = 0)"});
  msh_error(with(plate, "4.1 0 8", "2.2 0 8"),
            {"plate.msh:2: MSH version 2.2 is not read; hpcontact reads MSH 4.1 ASCII (gmsh "
             "-format msh41"});
  msh_error(with(plate, "4.1 0 8", "4 0 8"), {"plate.msh:2: MSH version 4 is not read"});
  msh_error("hello world\n", {"plate.msh:1: not a Gmsh .msh file: expected $MeshFormat on its "
                              "first line (got 'hello world')"});
  msh_error("", {"plate.msh:1: empty file"});
  const char binary[] = "$MeshFormat\n4.1 1 8\n\x01\0\0\0\n$EndMeshFormat\n";
  msh_error(std::string(binary, sizeof binary - 1), {"plate.msh:2: binary"});
}

// Triangles (or quads of order 3+) in the body shall be an error naming the fix.
TEST(GmshImport, RejectsTriangles) {
  const std::string text =
      with(with(plate, "3 6 1 6\n", "4 7 1 7\n"), "$EndElements", "2 1 2 1\n7 1 2 5\n$EndElements");
  msh_error(text, {"plate.msh:44: element 7 is a 3-node triangle (gmsh type 2): hpcontact needs "
                   "quadrilaterals; recombine the mesh (Mesh.RecombineAll = 1)"});
  hio::ImportOptions o;
  o.surface = "plate";
  msh_error(text, {"plate.msh:44: element 7 of surface 'plate' is a 3-node triangle"}, o);
  msh_error(with(with(plate, "3 6 1 6\n", "4 7 1 7\n"), "$EndElements",
                 "2 1 36 1\n7 1 2 3 4 5 6 1 2 3 4 5 6 1 2 3 4\n$EndElements"),
            {"plate.msh:44: element 7 is a 16-node quadrilateral (gmsh type 36): hpcontact reads "
             "quadrilaterals of order 1 and 2"});
  msh_error(with(plate, "2 1 3 2\n5 1 2 5 4\n6 2 3 6 5\n", "2 1 2 2\n5 1 2 5\n6 2 3 6\n"),
            {"plate.msh:41: element 5 is a 3-node triangle"});
}

// Broken files shall be one-line errors naming the file, the line and what was expected.
TEST(GmshReader, RejectsBrokenFiles) {
  msh_error(plate.substr(0, plate.find("3\n4\n5\n6\n0 0 0")),
            {"plate.msh:20: unexpected end of file in $Nodes: expected a node tag"});
  msh_error(with(plate, "5 1 2 5 4", "5 1 2 9 4"),
            {"plate.msh:41: element 5 refers to node 9, which $Nodes does not define"});
  msh_error(
      with(plate, "5 1 2 5 4", "5 1 2 5"),
      {"plate.msh:41: expected 'tag' and 4 node tags of a 4-node quadrilateral (got '5 1 2 5')"});
  msh_error(with(plate, "5 1 2 5 4", "5 1 2 2 4"),
            {"plate.msh:41: element 5 has corner node 2 twice"});
  msh_error(with(plate, "1 6 1 6\n", "1 7 1 6\n"),
            {"plate.msh:17: the header says 7 nodes, the blocks hold 6"});
  // Counts beyond what a problem can hold are refused at the header, before the blocks.
  msh_error(with(plate, "1 6 1 6\n", "1 800001 1 6\n"),
            {"plate.msh:17: the header says 800001 nodes, more than the 800000 a mesh file may "
             "have: a body's mesh becomes part of the problem's YAML tree", "give a coarser mesh"});
  msh_error(with(plate, "1 6 1 6\n", "1 99999999999999 1 6\n"),
            {"plate.msh:17: the header says 99999999999999 nodes, more than the 800000"});
  msh_error(with(plate, "3 6 1 6\n", "3 200001 1 6\n"),
            {"plate.msh:33: the header says 200001 elements, more than the 200000 a mesh file may "
             "have"});
  msh_error(with(plate, "2 1 0 6\n", "2 1 0 99999999999999999\n"),
            {"plate.msh:25: expected one node tag (got '0 0 0')"});
  msh_error(with(plate, "2 1 0 6\n", "2 1 0 -6\n"),
            {"plate.msh:18: expected the number of nodes in the block >= 0 (got '-6')"});
  msh_error(with(plate, "\n3\n4\n5\n", "\n3\n-4\n5\n"),
            {"plate.msh:22: expected a node tag in [1, 2147483647] (got '-4')"});
  msh_error(with(plate, "\n3\n4\n5\n", "\n3\n3\n5\n"), {"plate.msh:22: node tag 3 given twice"});
  msh_error(with(plate, "\n3\n4\n5\n", "\n3\n99999999999\n5\n"),
            {"plate.msh:22: expected a node tag in"});
  msh_error(with(plate, "2 1 0\n$EndNodes", "2 1 0.5\n$EndNodes"),
            {"plate.msh:30: node 6 is not in the plane z = 0 (z = 0.5)"});
  msh_error(with(plate, "1 0 0\n2 0 0", "1 nan 0\n2 0 0"),
            {"plate.msh:26: expected y as a finite number (got 'nan')"});
  msh_error(with(plate, "2 1 3 2\n", "2 7 3 2\n"),
            {"plate.msh:40: element block of 2D entity 7, which $Entities does not define"});
  msh_error(with(plate, "$EndNodes\n", "$EndNode\n"),
            {"plate.msh:31: expected $EndNodes (got '$EndNode')"});
  msh_error(with(plate, "1 1 \"bottom\"", "1 1 bottom"),
            {"plate.msh:6: expected the physical name in double quotes (got '1 1 bottom')"});
  msh_error(with(plate, "2 1 3 2\n", "1 1 3 2\n"),
            {"plate.msh:40: element type 3 (4-node quadrilateral) in a block of dimension 1"});
  msh_error(plate + "$Comments\nsomething\n",
            {"plate.msh:44: section $Comments has no $EndComments line"});
  msh_error(plate + "$Nodes\n0 0 0 0\n$EndNodes\n", {"plate.msh:44: section $Nodes given twice"});
  msh_error(with(plate, "6 2 3 6 5", "5 2 3 6 5"), {"plate.msh:42: element tag 5 given twice"});
}

// Unknown sections, blank lines, CRLF line ends and parametric nodes shall be accepted.
TEST(GmshReader, SkipsWhatItDoesNotNeed) {
  std::string text = with(plate, "$Nodes\n", "$NodeData\n1\n\"x\"\n$EndNodeData\n\n$Nodes\n");
  text = with(text, "2 1 0 6\n1\n2\n3\n4\n5\n6\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0",
              "2 1 1 6\n1\n2\n3\n4\n5\n6\n0 0 0 0 0\n1 0 0 1 0\n2 0 0 2 0\n0 1 0 0 1\n1 1 0 1 "
              "1\n2 1 0 2 1");
  std::string crlf;
  for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const hio::GmshMesh m = hio::parse_gmsh(crlf, "plate.msh");
  EXPECT_EQ(m.nodes.size(), 6u);
  EXPECT_EQ(m.quads.size(), 2u);
}

// Hostile input shall end in an InputError, never in a crash or another exception: every
// truncation of a valid file and a few thousand random byte changes.
TEST(GmshReader, SurvivesTruncatedAndMutatedFiles) {
  const std::string text = annulus_msh(2, 2);
  const auto parse = [](const std::string& t) {
    try {
      hio::import_gmsh_body(hio::parse_gmsh(t, "x.msh"), {});
    } catch (const InputError&) {
    }
  };
  for (std::size_t n = 0; n < text.size(); ++n) EXPECT_NO_THROW(parse(text.substr(0, n))) << n;
  std::mt19937 random(7);
  const std::string alphabet = "0123456789 -.e\n$\"x";
  for (int trial = 0; trial < 3000; ++trial) {
    std::string t = text;
    for (int k = 0; k < 1 + trial % 3; ++k) {
      const std::size_t at = random() % t.size();
      switch (random() % 3) {
        case 0:
          t[at] = alphabet[random() % alphabet.size()];
          break;
        case 1:
          t.erase(at, 1 + random() % 8);
          break;
        default:
          t.insert(at, 1, alphabet[random() % alphabet.size()]);
          break;
      }
    }
    EXPECT_NO_THROW(parse(t)) << t;
  }
}

namespace {

/// A folder of its own below the system's temporary folder, removed at the end.
struct TempFolder {
  fs::path path;
  TempFolder() {
    path = fs::temp_directory_path() /
           ("hpc-gmsh-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name) << text;
  }
};

const std::string ring_case = R"(case: ring
bodies:
  - name: ring
    material: {E: 1000, nu: 0.3}
    gmsh: {file: ring.msh, surface: ring}
    constraints:
      - {edges: [bottom], uy: 0}
      - {edges: [left], ux: 0}
    loads:
      - {edges: [inner], pressure: 1}
)";

}  // namespace

// bodies[].gmsh shall stand for the nodes, elements, curves and edge sets of the file, found
// relative to the problem file; the effective input lists them instead and reads back the same.
TEST(ProblemReaderGmsh, ExpandsTheMesh) {
  const TempFolder dir;
  dir.write("ring.msh", annulus_msh(3, 2));
  const std::string label = (dir.path / "ring.yaml").string();
  const hio::ReadResult r = hio::parse_problem_full(ring_case, label);
  const auto& b = r.spec.bodies.at(0);
  EXPECT_EQ(b.node_ids, (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8}));
  EXPECT_EQ(b.element_ids, (std::vector<int>{9, 10, 11}));
  EXPECT_EQ(b.elements[0], (std::array<int, 4>{1, 5, 6, 2}));
  ASSERT_EQ(b.curves.size(), 6u);
  EXPECT_NEAR(b.curves[0].radius, 2, 1e-14);  // edges in element order: the outer arc first
  ASSERT_EQ(b.edge_sets.size(), 4u);
  EXPECT_EQ(b.edge_sets[1].name, "outer");
  EXPECT_EQ(b.edge_sets[1].where.origin, "from " + (dir.path / "ring.msh").string());
  EXPECT_EQ(r.effective_yaml.find("gmsh:"), std::string::npos);
  EXPECT_NE(r.effective_yaml.find("#   bodies[0] (ring): mesh of "), std::string::npos);
  EXPECT_NE(r.effective_yaml.find("3 elements, 6 arcs recovered from midside nodes, edge sets "
                                  "inner outer bottom left"),
            std::string::npos)
      << r.effective_yaml;
  // The mesh takes the place of the gmsh key.
  EXPECT_LT(r.effective_yaml.find("nodes:"), r.effective_yaml.find("constraints:"));

  const hio::ReadResult again = hio::parse_problem_full(r.effective_yaml, label);
  const auto& c = again.spec.bodies.at(0);
  EXPECT_EQ(c.nodes, b.nodes);
  EXPECT_EQ(c.elements, b.elements);
  ASSERT_EQ(c.curves.size(), b.curves.size());
  for (std::size_t k = 0; k < c.curves.size(); ++k) {
    EXPECT_EQ(c.curves[k].center, b.curves[k].center);
    EXPECT_EQ(c.curves[k].radius, b.curves[k].radius);
    EXPECT_EQ(c.curves[k].ccw, b.curves[k].ccw);
  }
  EXPECT_EQ(again.effective_yaml.substr(again.effective_yaml.find('\n')),
            r.effective_yaml.substr(r.effective_yaml.find("\ncase:")));
}

// A label without a folder shall find the mesh in the current directory; hand-given curves and
// edge sets shall join the file's, and --set overrides shall apply before the expansion.
TEST(ProblemReaderGmsh, ResolvesFromCurrentDirectoryAndMergesHandGivenParts) {
  const TempFolder dir;
  dir.write("ring.msh", annulus_msh(3, 1));
  dir.write("other.msh", "garbage");
  const fs::path cwd = fs::current_path();
  fs::current_path(dir.path);
  const std::string text =
      with(ring_case, "surface: ring}",
           "surface: ring, arcs: [{edges: outer, center: [0, 0], radius: 2}]}\n"
           "    curves:\n      - {nodes: [2, 1], arc: {center: [0, 0], radius: 1}}\n"
           "    edge_sets:\n      first: [[1, 5]]");
  hpcontact::model::ProblemSpec spec;
  try {
    spec = hio::parse_problem(with(text, "file: ring.msh", "file: other.msh"), "ring.yaml",
                              {"bodies[0].gmsh.file=ring.msh"});
  } catch (...) {
    fs::current_path(cwd);
    throw;
  }
  fs::current_path(cwd);
  const auto& b = spec.bodies.at(0);
  ASSERT_EQ(b.curves.size(), 4u);  // the hand-given one first, then the named outer arcs
  EXPECT_EQ(b.curves[0].where.line, 7);
  EXPECT_EQ(b.curves[1].radius, 2);
  EXPECT_EQ(b.curves[1].where.origin, "from ring.msh");
  ASSERT_EQ(b.edge_sets.size(), 5u);
  EXPECT_EQ(b.edge_sets[0].name, "first");
}

// Errors in bodies[].gmsh shall name the problem file's key, or the .msh file and its line.
TEST(ProblemReaderGmsh, RejectsBadGmshSections) {
  const TempFolder dir;
  dir.write("ring.msh", annulus_msh(2, 1));
  dir.write("bad.msh", with(annulus_msh(2, 1), "4.1 0 8", "2.2 0 8"));
  const std::string label = (dir.path / "ring.yaml").string();
  const auto error = [&](const std::string& text, const std::string& fragment) {
    try {
      hio::parse_problem(text, label);
      ADD_FAILURE() << "no error; expected " << fragment;
    } catch (const hpcontact::Error& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_NE(message.find(fragment), std::string::npos)
          << "'" << fragment << "' not in: " << message;
    }
  };
  error(with(ring_case, "surface: ring", "surface: disc"),
        label + ":5:37: bodies[0].gmsh.surface: no 2D physical group of that name in " +
            (dir.path / "ring.msh").string() + " (defined: ring) (got 'disc')");
  error(with(ring_case, "file: ring.msh", "file: bad.msh"),
        (dir.path / "bad.msh").string() + ":2: MSH version 2.2 is not read");
  error(with(ring_case, "file: ring.msh", "file: none.msh"),
        label + ":5:18: bodies[0].gmsh.file: " + (dir.path / "none.msh").string() +
            ": cannot open mesh file: No such file or directory");
  error(with(ring_case, "file: ring.msh", "file: /dev/zero"),
        label + ":5:18: bodies[0].gmsh.file: /dev/zero: cannot read mesh file: not a regular file");
  error(with(ring_case, "surface: ring}", "surface: ring, size: 3}"),
        label +
            ":5:43: bodies[0].gmsh.size: unknown key (allowed here: file, surface, arcs, "
            "arc_tolerance)");
  error(with(ring_case, "surface: ring}",
             "surface: ring, arcs: [{edges: outer, center: [0, 0], radius: 3}]}"),
        label + ":5:50: bodies[0].gmsh.arcs[0]: node 4 (2, 0) of edge [4, 5] (" +
            (dir.path / "ring.msh").string() +
            ":42) is at distance 2 from the centre, not on the circle of radius 3");
  error(with(ring_case, "    constraints:", "    gmsh: {file: other.msh}\n    constraints:"),
        label + ":6:5: bodies[0].gmsh: duplicate key");
  error(with(ring_case, "    gmsh:", "    nodes: {1: [0, 0]}\n    gmsh:"),
        label + ":5:12: bodies[0].nodes: give either gmsh or nodes and elements, not both");
  error(with(ring_case, "    gmsh: {file: ring.msh, surface: ring}\n", ""),
        label +
            ":3:5: bodies[0]: missing required key 'nodes' (a body needs nodes and elements, or "
            "gmsh)");
  error(with(ring_case, "    constraints:", "    edge_sets: {outer: [[1, 2]]}\n    constraints:"),
        label + ":6:17: bodies[0].edge_sets.outer: the 1D physical group 'outer' of " +
            (dir.path / "ring.msh").string() + " makes an edge set of this name already");
  error(with(ring_case, "{edges: [left], ux: 0}", "{edges: [right], ux: 0}"),
        "bodies[0].constraints[1].edges[0]: no such edge set (defined: inner, outer, bottom, left) "
        "(got 'right')");
}
