// The structured box: a lattice of nodes, equally spaced or at given planes, one trilinear
// hexahedron per cell.
#include "hpcontact/mesh/hex_box.hpp"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/core/error.hpp"

namespace hpcontact::mesh {

HexMesh hex_box_mesh(const Vec3& lower, const Vec3& upper, std::array<int, 3> n) {
  const char* axis = "xyz";
  std::array<std::vector<double>, 3> planes;
  for (int d = 0; d < 3; ++d) {
    HPC_REQUIRE(lower(d) < upper(d), InputError, "hexahedral box: ", axis[d], "0 < ", axis[d],
                "1 required (got ", lower(d), ", ", upper(d), ")");
    HPC_REQUIRE(n[d] >= 1, InputError, "hexahedral box: the number of elements along ", axis[d],
                " must be >= 1 (got ", n[d], ")");
    for (int i = 0; i <= n[d]; ++i)
      planes[d].push_back(std::lerp(lower(d), upper(d), static_cast<double>(i) / n[d]));
  }
  return hex_box_mesh(planes);
}

HexMesh hex_box_mesh(const std::array<std::vector<double>, 3>& planes) {
  const char* axis = "xyz";
  std::array<int, 3> n;
  for (int d = 0; d < 3; ++d) {
    const std::vector<double>& x = planes[d];
    HPC_REQUIRE(x.size() >= 2, InputError, "hexahedral box: the planes along ", axis[d],
                " must be two or more (got ", x.size(), ")");
    for (size_t i = 1; i < x.size(); ++i)
      HPC_REQUIRE(x[i - 1] < x[i], InputError, "hexahedral box: the planes along ", axis[d],
                  " must increase strictly (got ", x[i - 1], " before ", x[i], " at ", i, ")");
    n[d] = static_cast<int>(x.size()) - 1;
  }
  HexMesh m;
  m.context = "hexahedral box";
  for (int k = 0; k <= n[2]; ++k)
    for (int j = 0; j <= n[1]; ++j)
      for (int i = 0; i <= n[0]; ++i)
        m.nodes.push_back(Vec3(planes[0][i], planes[1][j], planes[2][k]));
  add_structured_hexes(m, n, {"x0", "x1", "y0", "y1", "z0", "z1"},
                       [](int, int, int, const std::array<Vec3, 8>& x) { return HexMap::trilinear(x); });
  return m;
}

}  // namespace hpcontact::mesh
