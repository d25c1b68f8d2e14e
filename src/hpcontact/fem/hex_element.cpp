// The choice between the hexahedron's two stiffness kernels, by their operation counts.
#include "hpcontact/fem/hex_element.hpp"

#include "hpcontact/fem/hex_elasticity.hpp"
#include "hpcontact/fem/hex_factored_stiffness.hpp"
#include "hpcontact/fem/hex_values.hpp"

namespace hpcontact::fem {

HexKernelFlops hex_kernel_flops(const basis::HierarchicHex& element,
                                const std::array<int, 3>& n_points) {
  const double n = element.n_modes();
  const double n0 = n_points[0], n1 = n_points[1], nq = n0 * n1 * n_points[2];
  const double m0 = element.p[0] + 1, m1 = element.p[1] + 1, m2 = element.p[2] + 1;
  HexKernelFlops f;
  // Six products n × nq × n; the values and physical gradients, ~30 per mode and point.
  f.blocks = 12 * n * n * nq + 30 * n * nq;
  // Nine (r, s) sums over ζ (six pairs ij each), 54 sums over η, the four kinds' sum over ξ for
  // all (m0 m1 m2)² tensor products and six pairs; the gather, ~9 per entry of K.
  f.factored = 108 * m2 * m2 * nq + 108 * m1 * m1 * m2 * m2 * n0 * n1 +
               48 * m0 * m0 * m1 * m1 * m2 * m2 * n0 + 9 * n * n;
  return f;
}

HexStiffnessKernel hex_stiffness_kernel(const basis::HierarchicHex& element,
                                        const std::array<int, 3>& n_points) {
  const HexKernelFlops f = hex_kernel_flops(element, n_points);
  return f.factored < kFactoredFlopRatio * f.blocks ? HexStiffnessKernel::factored
                                                    : HexStiffnessKernel::blocks;
}

HexElementMatrices hex_element_matrices(const basis::HierarchicHex& element,
                                        const mesh::HexMap& map,
                                        const material::LinearElastic& material,
                                        const mesh::Vec3& body_force, HexStiffnessKernel kernel) {
  const std::array<int, 3> n_points = hex_gauss_points(element, map);
  if (kernel == HexStiffnessKernel::automatic) kernel = hex_stiffness_kernel(element, n_points);
  HexElementMatrices e;
  if (kernel == HexStiffnessKernel::factored) {
    const HexGridGeometry geometry = hex_grid_geometry(map, n_points);
    e.K = hex_stiffness_factored(element, geometry, material);
    e.f = hex_body_force_factored(element, geometry, body_force);
  } else {
    const HexValues values = hex_values(element, map, n_points);
    e.K = hex_stiffness(values, material);
    e.f = hex_body_force(values, body_force);
  }
  return e;
}

}  // namespace hpcontact::fem
