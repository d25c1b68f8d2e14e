// One-dimensional Gauss–Legendre and Gauss–Lobatto rules on the reference interval [-1, 1].
#pragma once

#include <vector>

namespace hpcontact::basis {

/// Points (ascending) and weights of a rule on [-1, 1]; the weights sum to 2.
struct QuadratureRule1D {
  std::vector<double> points;
  std::vector<double> weights;
  int size() const { return static_cast<int>(points.size()); }
};

/// Gauss–Legendre rule with n_points >= 1 points: exact for polynomials of degree 2n-1.
/// Nodes and weights accurate to 1e-14 for any n up to at least 200. Results are cached.
const QuadratureRule1D& gauss_legendre(int n_points);

/// Gauss–Lobatto rule with n_points >= 2 points (the end points included): exact to degree 2n-3.
const QuadratureRule1D& gauss_lobatto(int n_points);

}  // namespace hpcontact::basis
