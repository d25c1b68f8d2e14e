// One hexahedron's stiffness and body force by whichever kernel is cheaper for its degrees.
#pragma once

#include <Eigen/Dense>
#include <array>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/material/linear_elastic.hpp"
#include "hpcontact/mesh/hex_map.hpp"

namespace hpcontact::fem {

/// How an element stiffness is formed: the six derivative-pair products over all modes and
/// points (hex_elasticity.hpp, O(n² n_points) = O(p⁹) for the tensor space), sum factorisation
/// (hex_factored_stiffness.hpp, O(p⁷) whatever the space), or the cheaper of the two
/// (hex_stiffness_kernel).
enum class HexStiffnessKernel { automatic, blocks, factored };

/// Floating-point operations of the two kernels' dense products for this element on a grid of
/// n_points (hex_gauss_points), the model hex_stiffness_kernel compares.
struct HexKernelFlops {
  double blocks = 0, factored = 0;
};
HexKernelFlops hex_kernel_flops(const basis::HierarchicHex& element,
                                const std::array<int, 3>& n_points);

/// The kernel `automatic` stands for: factored where its operation count is below
/// kFactoredFlopRatio of the blocks' (its products are smaller and its set-up, the gather of
/// the element's modes, costs more per operation), else blocks.
HexStiffnessKernel hex_stiffness_kernel(const basis::HierarchicHex& element,
                                        const std::array<int, 3>& n_points);

/// Measured on one distorted trilinear hex (bench/bench_hex_element.cpp, BENCHMARKS.md): the
/// factored kernel is faster from p = 3 in the tensor space (flop ratio 0.42; at p = 2, ratio
/// 0.78, it is slower), and in the trunk space it is not (p = 8: ratio 0.90, 1.2 times slower).
inline constexpr double kFactoredFlopRatio = 0.7;

/// An element's stiffness (3n × 3n) and load for a constant body force (3n), component-blocked
/// (hex_elasticity.hpp), on the Gauss grid of hex_gauss_points. Throws MeshError where det J <= 0.
struct HexElementMatrices {
  Eigen::MatrixXd K;
  Eigen::VectorXd f;
};
HexElementMatrices hex_element_matrices(const basis::HierarchicHex& element,
                                        const mesh::HexMap& map,
                                        const material::LinearElastic& material,
                                        const mesh::Vec3& body_force,
                                        HexStiffnessKernel kernel = HexStiffnessKernel::automatic);

}  // namespace hpcontact::fem
