// Unit tests of the 3D Gmsh import: hexahedra (8, 20, 27 nodes) and boundary quads read from MSH
// 4.1, the body made of them (nodes, maps, face sets of physical surfaces), a quarter plate with
// a hole meshed by gmsh, and one-line refusals naming the file, line and cause.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "edit_text.hpp"
#include "gmsh_box.hpp"
#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/io/gmsh_hex_import.hpp"
#include "hpcontact/io/gmsh_import.hpp"
#include "hpcontact/io/gmsh_reader.hpp"

namespace hio = hpcontact::io;
namespace mesh = hpcontact::mesh;
namespace fs = std::filesystem;
using hpcontact::InputError;
using hpcontact::MeshError;
using hpcontact::test::Box;
using hpcontact::test::box_msh;
using hpcontact::test::line_starting;
using hpcontact::test::with;
using mesh::Vec3;

namespace {

mesh::HexMesh import(const std::string& text, const hio::HexImportOptions& options = {}) {
  return hio::import_gmsh_hex_body(hio::parse_gmsh_volume(text, "box.msh"), options);
}

/// The message of the error of type E that reading and importing `text` throws, checked to be
/// one line holding every fragment.
template <class E = InputError>
std::string error(const std::string& text, const std::vector<std::string>& fragments,
                  const hio::HexImportOptions& options = {}) {
  try {
    import(text, options);
  } catch (const E& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    for (const std::string& f : fragments)
      EXPECT_NE(message.find(f), std::string::npos) << "'" << f << "' not in: " << message;
    return message;
  }
  ADD_FAILURE() << "no error; expected " << (fragments.empty() ? "" : fragments[0]);
  return "";
}

/// sum over the elements of the integral of det J (Gauss, 4 points per axis: exact for the
/// triquadratic map's det J, of degree 5 along each axis).
double volume(const mesh::HexMesh& m, std::vector<double>* per_element = nullptr) {
  const auto& rule = hpcontact::basis::gauss_legendre(4);
  double total = 0;
  for (const mesh::HexMap& map : m.maps) {
    double v = 0;
    for (std::size_t i = 0; i < rule.points.size(); ++i)
      for (std::size_t j = 0; j < rule.points.size(); ++j)
        for (std::size_t k = 0; k < rule.points.size(); ++k) {
          mesh::Mat3 J;
          map.map(rule.points[i], rule.points[j], rule.points[k], &J);
          v += rule.weights[i] * rule.weights[j] * rule.weights[k] * J.determinant();
        }
    if (per_element) per_element->push_back(v);
    total += v;
  }
  return total;
}

/// The points of a face's map at reference positions in {-1, 0, 1}^2 of the face (9 points).
std::vector<Vec3> face_points(const mesh::HexMesh& m, const mesh::ElementFace& face) {
  const auto [h, f] = face;
  std::vector<Vec3> points;
  for (int a = -1; a <= 1; ++a)
    for (int b = -1; b <= 1; ++b) {
      double r[3];
      r[hpcontact::basis::kHexFaceNormalAxis[f]] = f % 2 == 0 ? -1 : 1;
      r[hpcontact::basis::kHexFaceAxes[f][0]] = a;
      r[hpcontact::basis::kHexFaceAxes[f][1]] = b;
      points.push_back(m.maps[static_cast<std::size_t>(h)].map(r[0], r[1], r[2]));
    }
  return points;
}

/// The nodes of a 27-node hexahedron's map on one of its local faces (9 nodes).
std::vector<Vec3> face_nodes(const mesh::HexMesh& m, const mesh::ElementFace& face) {
  const auto [h, f] = face;
  const mesh::HexMap& map = m.maps[static_cast<std::size_t>(h)];
  std::vector<Vec3> nodes;
  const int axis = hpcontact::basis::kHexFaceNormalAxis[f], side = f % 2 == 0 ? -1 : 1;
  for (std::size_t n = 0; n < map.nodes().size(); ++n)
    if (mesh::kHex27Nodes[n][axis] == side) nodes.push_back(map.nodes()[n]);
  return nodes;
}

/// A bump that vanishes on the box's faces: moves interior nodes only.
Vec3 bumped(const Vec3& x) {
  const double b = (1 - x[0] * x[0]) * (1 - x[1] * x[1]) * (1 - x[2] * x[2]);
  return x + 0.15 * b * Vec3(1, 0.5, -0.7);
}

std::string run_gmsh(const std::string& arguments) {
  const int status = std::system(("gmsh " + arguments + " > /dev/null 2>&1").c_str());
  EXPECT_EQ(status, 0) << "gmsh " << arguments
                       << " (gmsh is a dependency: scripts/install-deps.sh)";
  return arguments;
}

const std::string kPlateFolder = std::string(HPC_SOURCE_DIR) + "/examples/plate-hole-3d";
constexpr double kHoleRadius = 2;  // examples/plate-hole-3d/plate.geo: a = 0.2 W, W = 10

}  // namespace

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

// The body shall be the hexahedra with their vertices numbered from 0 by Gmsh tag, one map per
// element, and a face set of each physical surface holding its boundary faces; the elements'
// volumes shall add up to the box's, 8, to round-off for every node order, also with the
// interior nodes moved.
TEST(GmshHexImport, MakesTheBodyOfABox) {
  for (int order : {1, 2})
    for (bool serendipity : {false, true})
      for (bool bump : {false, true}) {
        if (order == 1 && serendipity) continue;
        SCOPED_TRACE(std::to_string(order) + (serendipity ? " serendipity" : "") +
                     (bump ? " bumped" : ""));
        Box box;
        box.order = order;
        box.serendipity = serendipity;
        if (bump) box.shape = bumped;
        const mesh::HexMesh m = import(box_msh(box));
        EXPECT_EQ(m.context, "box.msh");
        ASSERT_EQ(m.nodes.size(), 27u);  // the vertices only
        EXPECT_EQ(m.topology.n_hexes(), 8);
        EXPECT_EQ(m.topology.n_nodes(), 27);
        EXPECT_EQ(m.topology.n_faces(), 36);
        EXPECT_EQ(m.topology.boundary_faces().size(), 24u);
        // Vertex tags ascend with the index: the first element's V0 is grid node (0, 0, 0).
        EXPECT_EQ(m.topology.hex(0)[0], 0);
        EXPECT_EQ(m.nodes[0], Vec3(-1, -1, -1));
        ASSERT_EQ(m.maps.size(), 8u);
        EXPECT_EQ(m.maps[0].kind(),
                  order == 1 ? mesh::HexMapKind::trilinear : mesh::HexMapKind::triquadratic);
        ASSERT_EQ(m.face_sets.size(), 6u);
        const char* names[] = {"x0", "x1", "y0", "y1", "z0", "z1"};
        for (int f = 0; f < 6; ++f) {
          const auto& set = m.face_sets.at(names[f]);
          ASSERT_EQ(set.size(), 4u) << names[f];
          for (const mesh::ElementFace& face : set) {
            EXPECT_TRUE(
                m.topology.face(m.topology.hex_face(face.first, face.second)).on_boundary());
            for (const Vec3& x : face_points(m, face))
              EXPECT_NEAR(x[f / 2], f % 2 == 0 ? -1 : 1, 1e-15) << names[f];
          }
        }
        std::vector<double> element_volumes;
        EXPECT_NEAR(volume(m, &element_volumes), 8, 1e-13);
        double spread = 0;
        for (double v : element_volumes) spread = std::max(spread, std::abs(v - 1));
        if (bump) EXPECT_GT(spread, 1e-2);  // the interior nodes did move
        else EXPECT_LT(spread, 1e-14);
      }
}

// A 20-node hexahedron shall be completed to the 27-node one by its serendipity map: for a map of
// total degree 2 (which the serendipity space holds) both give the same map.
TEST(GmshHexImport, CompletesTwentyNodeHexahedraBySerendipity) {
  const auto quadratic = [](const Vec3& x) {
    return Vec3(x[0] + 0.1 * x[1] * x[1] - 0.05 * x[0] * x[2], x[1] + 0.08 * x[0] * x[2],
                x[2] - 0.1 * x[0] * x[0] + 0.07 * x[1]);
  };
  Box box;
  box.order = 2;
  box.shape = quadratic;
  const mesh::HexMesh full = import(box_msh(box));
  box.serendipity = true;
  const mesh::HexMesh serendipity = import(box_msh(box));
  std::mt19937 random(3);
  std::uniform_real_distribution<double> r(-1, 1);
  double worst = 0;
  for (std::size_t h = 0; h < full.maps.size(); ++h)
    for (int trial = 0; trial < 20; ++trial) {
      const double xi = r(random), eta = r(random), zeta = r(random);
      worst = std::max(worst, (full.maps[h].map(xi, eta, zeta) -
                               serendipity.maps[h].map(xi, eta, zeta)).norm());
    }
  EXPECT_LT(worst, 1e-14);
  // x² y² is not in the serendipity space: the completion differs from the 27-node map.
  box.shape = [](const Vec3& x) {
    return Vec3(x[0] + 0.1 * x[0] * x[0] * x[1] * x[1], x[1], x[2]);
  };
  const mesh::HexMesh cubic20 = import(box_msh(box));
  box.serendipity = false;
  const mesh::HexMesh cubic27 = import(box_msh(box));
  EXPECT_GT((cubic20.maps[0].map(0, 0, 0) - cubic27.maps[0].map(0, 0, 0)).norm(), 1e-3);
}

// `volumes` shall choose the body's elements: only their vertices become nodes, the face sets
// keep the faces on its boundary (an interface to another volume too) and leave out the faces of
// the other volumes; a surface between two chosen volumes is refused as an interior face.
TEST(GmshHexImport, ChoosesVolumes) {
  Box box;
  box.order = 2;
  box.split = true;
  const std::string text = box_msh(box);
  const mesh::HexMesh left = import(text, {{"left"}});
  EXPECT_EQ(left.topology.n_hexes(), 4);
  EXPECT_EQ(left.nodes.size(), 18u);
  EXPECT_NEAR(volume(left), 4, 1e-13);
  std::vector<std::string> names;
  for (const auto& [name, faces] : left.face_sets) names.push_back(name);
  EXPECT_EQ(names, (std::vector<std::string>{"mid", "x0", "y0", "y1", "z0", "z1"}));
  EXPECT_EQ(left.face_sets.at("mid").size(), 4u);
  EXPECT_EQ(left.face_sets.at("y0").size(), 2u);
  for (const mesh::ElementFace& face : left.face_sets.at("mid"))
    for (const Vec3& x : face_points(left, face)) EXPECT_NEAR(x[0], 0, 1e-15);
  const mesh::HexMesh right = import(text, {{"right"}});
  EXPECT_EQ(right.face_sets.count("x0"), 0u);
  EXPECT_EQ(right.face_sets.at("x1").size(), 4u);
  EXPECT_EQ(right.face_sets.at("mid").size(), 4u);

  const std::string interior = "face set 'mid' has a face that is not on the boundary: quad ";
  const int mid_line = line_starting(text, "25 ");  // the first quad of "mid"
  error(text, {"box.msh:" + std::to_string(mid_line) + ": " + interior + "25 lies between "
               "hexahedra 29 and 33"},
        {{"left", "right"}});
  error(text, {"box.msh:" + std::to_string(mid_line) + ": " + interior + "25"});
  try {
    import(text, {{"left", "top"}});
    ADD_FAILURE() << "no error";
  } catch (const hio::GmshOptionError& e) {
    EXPECT_EQ(e.key, "volumes[1]");
    EXPECT_EQ(e.what_text,
              "no 3D physical group of that name in box.msh (defined: left, right) (got 'top')");
  }
}

// A quarter plate with a cylindrical hole meshed by gmsh (transfinite, recombined, extruded;
// -3 -order 2) shall be read with its seven face sets on their planes, the hole's 27-node
// hexahedra with their face nodes on the cylinder to round-off, its volume that of the plate
// less the hole to the accuracy of quadratic arcs (1e-6).(1e-6).
TEST(GmshHexImport, ReadsTheQuarterPlateWithAHole) {
  const mesh::HexMesh m =
      hio::import_gmsh_hex_body(hio::read_gmsh_volume(kPlateFolder + "/plate.msh"), {{"plate"}});
  EXPECT_EQ(m.topology.n_hexes(), 66);
  std::vector<std::string> names;
  for (const auto& [name, faces] : m.face_sets) names.push_back(name);
  EXPECT_EQ(names, (std::vector<std::string>{"end", "hole", "side", "x0", "y0", "z0", "z1"}));
  EXPECT_EQ(m.face_sets.at("hole").size(), 12u);  // 6 along the quarter arc, 2 through t
  // Every boundary face is in exactly one set.
  std::size_t n_set_faces = 0;
  for (const auto& [name, faces] : m.face_sets) n_set_faces += faces.size();
  EXPECT_EQ(n_set_faces, m.topology.boundary_faces().size());
  double worst = 0;
  for (const mesh::ElementFace& face : m.face_sets.at("hole")) {
    const std::vector<Vec3> nodes = face_nodes(m, face);
    ASSERT_EQ(nodes.size(), 9u);
    for (const Vec3& x : nodes)
      worst = std::max(worst, std::abs(std::hypot(x[0], x[1]) - kHoleRadius));
  }
  EXPECT_LT(worst, 1e-14 * kHoleRadius);
  const auto on_plane = [&](const std::string& set, int axis, double at) {
    for (const mesh::ElementFace& face : m.face_sets.at(set))
      for (const Vec3& x : face_points(m, face)) EXPECT_NEAR(x[axis], at, 1e-13) << set;
  };
  on_plane("x0", 0, 0);
  on_plane("y0", 1, 0);
  on_plane("z0", 2, 0);
  on_plane("z1", 2, 2);
  on_plane("end", 0, 20);
  on_plane("side", 1, 10);
  const double exact = (20 * 10 - std::numbers::pi * kHoleRadius * kHoleRadius / 4) * 2;
  EXPECT_NEAR(volume(m) / exact, 1, 1e-6);  // measured 1.6e-7
}

// The example's .geo shall give through gmsh (now) meshes of 27-, 20- and 8-node hexahedra that
// import, the mesh nodes of the hole on the cylinder.
TEST(GmshHexImport, ImportsWhatGmshMakesOfTheExample) {
  const fs::path dir =
      fs::temp_directory_path() /
      ("hpc-gmsh-hex-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  fs::create_directories(dir);
  struct Case {
    std::string options;
    int type;
  };
  for (const Case& c :
       {Case{"-order 2", 12}, Case{"-order 2 -string 'Mesh.SecondOrderIncomplete = 1;'", 17},
        Case{"-order 1", 5}}) {
    SCOPED_TRACE(c.options);
    const std::string out = (dir / "plate.msh").string();
    run_gmsh("-3 " + c.options + " -format msh41 " + kPlateFolder + "/plate.geo -o " + out);
    const hio::GmshVolumeMesh g = hio::read_gmsh_volume(out);
    ASSERT_FALSE(g.hexes.empty());
    EXPECT_EQ(g.hexes[0].type, c.type);
    const mesh::HexMesh m = hio::import_gmsh_hex_body(g);
    EXPECT_EQ(m.face_sets.at("hole").size(), 12u);
    for (const hio::GmshQuad& q : g.quads)
      if (q.groups == std::vector<std::string>{"hole"})
        for (const std::array<int, 4>& tags : {q.corners, q.midside})
          for (int tag : tags)
            if (tag != 0)
              EXPECT_NEAR(std::hypot(g.nodes.at(tag)[0], g.nodes.at(tag)[1]), kHoleRadius, 1e-13);
  }
  fs::remove_all(dir);
}

// Volume elements other than hexahedra of order 1 or 2 in the body shall be refused with their
// counts by type and the line of the first; those of a volume not chosen are left out.
TEST(GmshHexImport, RefusesOtherVolumeElements) {
  Box box;
  const std::vector<int> nodes{1, 2, 4, 10, 11, 13, 5, 14, 3, 6};
  const auto block = [&](int entity, int type, int n_nodes, int count) {
    return Box::Block{
        3, entity, type,
        std::vector<std::vector<int>>(static_cast<std::size_t>(count),
                                      std::vector<int>(nodes.begin(), nodes.begin() + n_nodes))};
  };
  box.blocks = {block(1, 4, 4, 120), block(1, 6, 6, 8)};
  std::string text = box_msh(box);
  const std::string advice =
      "; hpcontact meshes 3D bodies with hexahedra only: use Recombine and a transfinite or "
      "subdivided mesh";
  const std::string at = "box.msh:" + std::to_string(line_starting(text, "1001 ")) + ": ";
  error(text, {at + "the mesh has 120 tetrahedra (gmsh type 4) and 8 prisms (gmsh type 6) (the "
               "first, element 1001, on this line)" + advice});
  error(text, {at + "volume 'box' has 120 tetrahedra (gmsh type 4) and 8 prisms"}, {{"box"}});
  box.blocks = {block(1, 7, 5, 3), block(1, 11, 10, 1), block(1, 4, 4, 2)};
  error(box_msh(box), {"the mesh has 2 tetrahedra (gmsh type 4), 3 pyramids (gmsh type 7) and 1 "
                       "10-node tetrahedron (gmsh type 11)"});
  // In a volume of their own, not chosen: left out.
  box.entities = {{3, 2, 8, "bolt"}};
  box.blocks = {block(2, 4, 4, 5)};
  EXPECT_EQ(import(box_msh(box), {{"box"}}).topology.n_hexes(), 8);
  error(box_msh(box), {"the mesh has 5 tetrahedra (gmsh type 4)"});
  // Hexahedra of order 3.
  box.entities = {};
  std::vector<int> nodes64;
  for (int k = 0; k < 64; ++k) nodes64.push_back(1 + k % 27);
  box.blocks = {{3, 1, 92, {nodes64}}};
  error(box_msh(box), {"the mesh has 1 64-node hexahedron (gmsh type 92) (the first, element 1001, "
                       "on this line); hpcontact reads hexahedra of order 1 and 2 (gmsh types 5, "
                       "12, 17; gmsh -order 1 or 2)"});
}

// A file of 2D elements only, or one holding a 2D mesh beside the volumes, shall be refused.
TEST(GmshHexImport, RefusesTwoDimensionalMeshes) {
  try {
    hio::import_gmsh_hex_body(hio::read_gmsh_volume(std::string(HPC_SOURCE_DIR) +
                                                    "/examples/gmsh/hertz.msh"));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/examples/gmsh/hertz.msh: no volume elements (31 "
                                         "quadrilaterals, 0 other 2D elements): a 3D body needs a "
                                         "volume meshed with hexahedra (gmsh -3)"),
              std::string::npos)
        << e.what();
  }
  // A surface of its own: two quads (nodes 1 3 9 7 span the bottom face) and a triangle.
  Box box;
  box.entities = {{2, 8, 10, "sheet"}};
  box.blocks = {{2, 8, 3, {{1, 3, 9, 7}, {19, 21, 27, 25}}}, {2, 8, 2, {{1, 3, 9}}}};
  std::string text = box_msh(box);
  error(text, {"box.msh:" + std::to_string(line_starting(text, "1001 ")) +
               ": surface entity 8 (physical surface 'sheet') is a 2D mesh beside the volumes: "
               "none of its 3 elements is a face of a volume element; a 3D body's file holds "
               "volumes and their boundary faces: mesh a 2D body in a file of its own"});
  box.blocks = {{2, 8, 2, {{1, 3, 9}}}};
  error(box_msh(box), {": surface entity 8 (physical surface 'sheet') is a 2D mesh beside"});
}

// A quad of a physical surface shall be a boundary face of the body: one that is a face of no
// element, or an interior face, is refused naming the face set, the quad and its line.
TEST(GmshHexImport, RefusesFacesOffTheBoundary) {
  Box box;
  box.blocks = {{2, 1, 3, {{1, 3, 9, 7}}}};  // in the entity of x0
  std::string text = box_msh(box);
  error(text, {"box.msh:" + std::to_string(line_starting(text, "1001 ")) +
               ": face set 'x0' has quad 1001, which is not a face of any volume element"});
  box.blocks = {{2, 1, 3, {{2, 5, 14, 11}}}};  // the face x = 0 between the first two elements
  text = box_msh(box);
  error(text, {"box.msh:" + std::to_string(line_starting(text, "1001 ")) +
               ": face set 'x0' has a face that is not on the boundary: quad 1001 lies between "
               "hexahedra 25 and 26"});
}

// An inverted or flat hexahedron, or one with a vertex twice, shall be refused naming the file,
// the line and the Gmsh element.
TEST(GmshHexImport, RefusesInvertedAndDegenerateHexahedra) {
  const std::string text = box_msh({});
  const std::string line = "box.msh:" + std::to_string(line_starting(text, "25 ")) + ": ";
  // The bottom and top faces swapped: a mirror image.
  error<MeshError>(with(text, "25 1 2 5 4 10 11 14 13", "25 10 11 14 13 1 2 5 4"),
                   {line + "element 25 has a negative Jacobian determinant", "(xi, eta, zeta)",
                    "it is inverted or degenerate"});
  Box flat;
  flat.shape = [](const Vec3& x) { return Vec3(x[0], x[1], x[2] == 0 ? -1 : x[2]); };
  error<MeshError>(box_msh(flat), {line + "element 25 has a ", "Jacobian determinant",
                                   "it is inverted or degenerate"});
  error(with(text, "25 1 2 5 4 10 11 14 13", "25 1 2 5 4 10 11 14 1"),
        {line + "element 25 has corner node 1 twice"});
  error(with(text, "25 1 2 5 4 10 11 14 13", "25 1 2 5 4 10 11 14 130"),
        {line + "element 25 refers to node 130, which $Nodes does not define"});
  // What the topology refuses: an element given twice.
  Box twice;
  twice.blocks = {{3, 1, 5, {{1, 2, 5, 4, 10, 11, 14, 13}}}};
  error<MeshError>(box_msh(twice), {"box.msh: elements 0 and 8 have the same nodes"});
}

// Hostile input shall end in an InputError or a body, never in a crash or another exception:
// every truncation of a valid file (an InputError unless only the last line end is cut), and a
// few thousand random byte changes (any error of the library).
TEST(GmshVolumeReader, SurvivesTruncatedAndMutatedFiles) {
  Box box;
  box.order = 2;
  box.split = true;
  const std::string text = box_msh(box);
  const auto parse = [](const std::string& t) { import(t, {{"left"}}); };
  for (std::size_t n = 0; n < text.size(); ++n) {
    try {
      parse(text.substr(0, n));
      EXPECT_EQ(n, text.size() - 1) << "a truncation read";
    } catch (const InputError&) {
    } catch (...) {
      ADD_FAILURE() << "another exception at " << n;
    }
  }
  std::mt19937 random(11);
  const std::string alphabet = "0123456789 -.e\n$\"x";
  for (int trial = 0; trial < 2000; ++trial) {
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
    try {
      parse(t);
    } catch (const hpcontact::Error&) {
    } catch (...) {
      ADD_FAILURE() << "another exception for:\n" << t;
    }
  }
}
