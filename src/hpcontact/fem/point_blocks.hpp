// An element's quadrature points in blocks for its large matrix products (Bᵀ D B over all points):
// at high degree one element's products are seconds of work, and a stop request (core/stop.hpp)
// is honoured between blocks.
#pragma once

#include <algorithm>

#include "hpcontact/core/stop.hpp"

namespace hpcontact::fem {

/// Calls block(first, count) for consecutive blocks [first, first + count) of the points
/// [0, n_points), each of about 2^28 floating-point operations at `flops_per_point` (all the points
/// in one block for elements below degree ~10), with a stop point ("assembling") before each.
template <class Block>
void for_point_blocks(int n_points, double flops_per_point, const Block& block) {
  constexpr double kBlockFlops = 1 << 28;  // ~0.1 s on one core
  const int size = std::max(8, static_cast<int>(std::min<double>(
                                   n_points, kBlockFlops / std::max(1.0, flops_per_point))));
  for (int first = 0; first < n_points; first += size) {
    stop_point("assembling");
    block(first, std::min(size, n_points - first));
  }
}

}  // namespace hpcontact::fem
