// Aspect and Jacobian ratios of elements, from their maps at Gauss points.
#include "hpcontact/mesh/element_shape.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>

#include <Eigen/SVD>

#include "hpcontact/basis/quadrature.hpp"

namespace hpcontact::mesh {

ElementShape element_shape(const ElementMap& map, int n_points) {
  const auto& rule = basis::gauss_legendre(n_points);
  ElementShape shape;
  double det_min = std::numeric_limits<double>::infinity(), det_max = 0;
  for (int i = 0; i < rule.size(); ++i)
    for (int j = 0; j < rule.size(); ++j) {
      Mat2 J;
      map.map(rule.points[i], rule.points[j], &J);
      const Eigen::Vector2d sigma = Eigen::JacobiSVD<Mat2>(J).singularValues();
      if (sigma(1) > 0) shape.aspect_ratio = std::max(shape.aspect_ratio, sigma(0) / sigma(1));
      const double det = J.determinant();
      det_min = std::min(det_min, det);
      det_max = std::max(det_max, det);
      shape.area += rule.weights[i] * rule.weights[j] * det;
    }
  if (det_min > 0) shape.jacobian_ratio = det_max / det_min;
  return shape;
}

double edge_length(const ElementMap& map, int le, int n_points) {
  const auto& rule = basis::gauss_legendre(n_points);
  double length = 0;
  for (int i = 0; i < rule.size(); ++i) {
    const double t = rule.points[i];
    // E1: η = −1, E2: ξ = 1, E3: η = 1, E4: ξ = −1 (kEdgeVertices); E1, E3 run along ξ
    const double xi = le == 1 ? 1 : le == 3 ? -1 : t, eta = le == 0 ? -1 : le == 2 ? 1 : t;
    Mat2 J;
    map.map(xi, eta, &J);
    length += rule.weights[i] * (le % 2 == 0 ? J.col(0) : J.col(1)).norm();
  }
  return length;
}

namespace {

/// The element with the largest value of one measure beyond its limit, and how many are.
struct Worst {
  double limit;
  int count = 0, element = -1;
  double value = 0;
  void add(int q, double v) {
    if (!(v > limit)) return;
    ++count;
    if (v > value) {
      value = v;
      element = q;
    }
  }
};

}  // namespace

std::vector<std::string> shape_warnings(const Mesh& mesh, const std::vector<ElementMap>& maps,
                                        const std::vector<int>& contact_edges,
                                        const std::string& context) {
  const std::set<int> contact(contact_edges.begin(), contact_edges.end());
  Worst aspect{kAspectRatioLimit}, jacobian{kJacobianRatioLimit}, along{kContactStretchLimit};
  for (int q = 0; q < mesh.n_quads(); ++q) {
    const ElementShape s = element_shape(maps[q], 4);
    aspect.add(q, s.aspect_ratio);
    jacobian.add(q, s.jacobian_ratio);
    for (int le = 0; le < 4; ++le)
      if (contact.count(mesh.quad_edge(q, le))) {
        const double L = edge_length(maps[q], le, 8);
        along.add(q, L * L / s.area);
      }
  }
  std::vector<std::string> out;
  auto say = [&](const Worst& w, const char* what, const char* why) {
    if (w.count == 0) return;
    std::ostringstream os;
    os << std::setprecision(3) << context << ": " << w.count << " element(s) " << what << " above "
       << w.limit << "; the worst, element " << mesh.quad_id(w.element) << ", has " << w.value
       << ": " << why;
    out.push_back(os.str());
  };
  say(along, "on a contact edge with the edge's length over the element's depth",
      "the pressure along the contact edge is resolved as coarsely as the edge is long, whatever "
      "the depth (needle elements along a contact surface); split them along the edge");
  say(aspect, "with an aspect ratio", "a needle resolves the field along its long side as "
      "coarsely as across its short one; split it along its length");
  say(jacobian, "with a Jacobian ratio", "a distorted element maps its polynomials to functions of "
      "lower order; straighten it, or give it more elements");
  return out;
}

}  // namespace hpcontact::mesh
