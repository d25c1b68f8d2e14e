// The structured cylinder sector: a polar lattice of nodes, one blending hexahedron per cell.
#include "hpcontact/mesh/cylinder_sector.hpp"

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/core/error.hpp"

namespace hpcontact::mesh {

HexMesh cylinder_sector_mesh(const CylinderSector& sector, std::array<int, 3> n) {
  constexpr double pi = std::numbers::pi;
  const double a = sector.inner_radius, b = sector.outer_radius;
  const double angle0 = sector.angle0, angle1 = sector.angle1;
  HPC_REQUIRE(a > 0 && b > a, InputError,
              "cylinder sector: radii must satisfy 0 < inner_radius < outer_radius (got ", a, ", ",
              b, ")");
  HPC_REQUIRE(angle1 > angle0 && angle1 - angle0 < 2 * pi, InputError,
              "cylinder sector: angles must satisfy angle0 < angle1 < angle0 + 2π (got ", angle0,
              ", ", angle1, ")");
  HPC_REQUIRE(sector.length > 0, InputError, "cylinder sector: length must be > 0 (got ",
              sector.length, ")");
  const char* direction[3] = {"radius", "angle", "length"};
  for (int d = 0; d < 3; ++d)
    HPC_REQUIRE(n[d] >= 1, InputError, "cylinder sector: the number of elements along the ",
                direction[d], " must be >= 1 (got ", n[d], ")");
  HPC_REQUIRE((angle1 - angle0) / n[1] < pi, InputError,
              "cylinder sector: each element's angle (angle1 - angle0)/n_angle must be < π (got ",
              (angle1 - angle0) / n[1], " with ", n[1], " elements)");

  HexMesh m;
  m.context = "cylinder sector";
  std::vector<double> radius(n[0] + 1), angle(n[1] + 1), height(n[2] + 1);
  auto step = [](int i, int n_steps) { return static_cast<double>(i) / n_steps; };
  for (int i = 0; i <= n[0]; ++i) radius[i] = std::lerp(a, b, step(i, n[0]));
  for (int j = 0; j <= n[1]; ++j) angle[j] = std::lerp(angle0, angle1, step(j, n[1]));
  for (int k = 0; k <= n[2]; ++k) height[k] = std::lerp(0.0, sector.length, step(k, n[2]));
  for (int k = 0; k <= n[2]; ++k)
    for (int j = 0; j <= n[1]; ++j)
      for (int i = 0; i <= n[0]; ++i)
        m.nodes.push_back(
            Vec3(radius[i] * std::cos(angle[j]), radius[i] * std::sin(angle[j]), height[k]));

  // One surface per lattice plane, shared by the elements on either side of it, so that
  // neighbours have the same image of their common face.
  std::vector<geometry::SurfacePtr> cylinder, meridian, level;
  for (double r : radius)
    cylinder.push_back(std::make_shared<geometry::Cylinder>(Vec3::Zero(), Vec3::UnitZ(), r));
  for (double t : angle)
    meridian.push_back(
        std::make_shared<geometry::Plane>(Vec3::Zero(), Vec3(-std::sin(t), std::cos(t), 0)));
  for (double z : height)
    level.push_back(std::make_shared<geometry::Plane>(Vec3(0, 0, z), Vec3::UnitZ()));

  add_structured_hexes(m, n, {"inner", "outer", "theta0", "theta1", "z0", "z1"},
                       [&](int i, int j, int k, const std::array<Vec3, 8>& x) {
                         const std::array<geometry::SurfacePtr, 6> faces{
                             cylinder[i], cylinder[i + 1], meridian[j],
                             meridian[j + 1], level[k], level[k + 1]};
                         return HexMap::blending(geometry::blending_hex(x, faces, "cylinder sector"));
                       });
  return m;
}

}  // namespace hpcontact::mesh
