// The cubed-sphere octant: three radial stacks of blending hexahedra.
#include "hpcontact/mesh/shell_octant.hpp"

#include <cmath>
#include <array>
#include <memory>
#include <utility>
#include <vector>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/core/error.hpp"

namespace hpcontact::mesh {

HexMesh shell_octant_mesh(double inner_radius, double outer_radius, int n_layers) {
  HPC_REQUIRE(inner_radius > 0 && outer_radius > inner_radius, InputError,
              "shell octant: radii must satisfy 0 < a < b (got a = ", inner_radius, ", b = ",
              outer_radius, ")");
  HPC_REQUIRE(n_layers >= 1, InputError, "shell octant: n_layers must be >= 1 (got ", n_layers,
              ")");
  // Unit directions: the axis points X, Y, Z, the arcs' mid-points XY, YZ, XZ, the centre C.
  const double h = 1 / std::sqrt(2.0), c = 1 / std::sqrt(3.0);
  const std::array<Vec3, 7> direction{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(h, h, 0),
                                      Vec3(0, h, h), Vec3(h, 0, h), Vec3(c, c, c)};
  enum { X, Y, Z, XY, YZ, XZ, C };
  // Each patch counter-clockwise seen from outside, so that zeta (outwards) completes a
  // right-handed frame: (V1 − V0) × (V3 − V0) points away from the centre.
  const int patch[3][4] = {{X, XY, C, XZ}, {Y, YZ, C, XY}, {Z, XZ, C, YZ}};

  const int n_levels = n_layers + 1;
  std::vector<Vec3> nodes;
  std::vector<double> radius(n_levels);
  for (int k = 0; k < n_levels; ++k)
    radius[k] = inner_radius + (outer_radius - inner_radius) * k / n_layers;
  for (const Vec3& d : direction)
    for (int k = 0; k < n_levels; ++k) nodes.push_back(radius[k] * d);
  auto node = [&](int dir, int k) { return dir * n_levels + k; };

  std::vector<std::shared_ptr<const geometry::Surface>> sphere;
  for (double r : radius) sphere.push_back(std::make_shared<geometry::Sphere>(Vec3::Zero(), r));
  std::array<geometry::SurfacePtr, 3> plane;
  for (int i = 0; i < 3; ++i)
    plane[i] = std::make_shared<geometry::Plane>(Vec3::Zero(), Vec3::Unit(i));

  HexMesh m;
  m.context = "shell octant";
  m.nodes = std::move(nodes);
  std::vector<std::array<int, 8>> hexes;
  std::vector<ElementFace>& inner = m.face_sets["inner"];
  std::vector<ElementFace>& outer = m.face_sets["outer"];
  std::array<std::vector<ElementFace>*, 3> symmetry{&m.face_sets["x0"], &m.face_sets["y0"],
                                                    &m.face_sets["z0"]};
  for (const auto& q : patch)
    for (int k = 0; k < n_layers; ++k) {
      const int element = static_cast<int>(hexes.size());
      std::array<int, 8> v;
      for (int i = 0; i < 4; ++i) {
        v[i] = node(q[i], k);
        v[i + 4] = node(q[i], k + 1);
      }
      hexes.push_back(v);
      std::array<Vec3, 8> x;
      for (int i = 0; i < 8; ++i) x[i] = m.nodes[v[i]];
      std::array<geometry::SurfacePtr, 6> faces{};
      faces[4] = sphere[k];
      faces[5] = sphere[k + 1];
      if (k == 0) inner.push_back({element, 4});
      if (k == n_layers - 1) outer.push_back({element, 5});
      // A lateral face lies on the plane x_i = 0 when its four corners do.
      for (int f = 0; f < 4; ++f)
        for (int i = 0; i < 3; ++i) {
          bool on = true;
          for (int corner : basis::kHexFaceVertices[f]) on = on && x[corner](i) == 0;
          if (!on) continue;
          faces[f] = plane[i];
          symmetry[i]->push_back({element, f});
        }
      m.maps.push_back(HexMap::blending(geometry::blending_hex(x, faces, "shell octant")));
    }
  m.topology = HexTopology(std::move(hexes), static_cast<int>(m.nodes.size()), m.context);
  check_hex_mesh(m);
  return m;
}

}  // namespace hpcontact::mesh
