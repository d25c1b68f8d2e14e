// Finding the element and reference coordinates of a point of the undeformed bodies.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "hpcontact/model/discretization.hpp"

namespace hpcontact::post {

/// A point of the undeformed configuration in element `element` of body `body`, at reference
/// coordinates (xi, eta) in [-1, 1]².
struct PointLocation {
  int body = -1;
  int element = -1;
  double xi = 0, eta = 0;
};

/// Inverts the element maps of a discretisation: which element holds an undeformed point, and
/// where in its reference square. Each element is boxed once, when constructed (its boundary
/// sampled, the box widened by 5 % of its diagonal); a query runs Newton's method on
/// x(xi, eta) = X, kept inside [-1, 1]², in every element whose box holds X. Holds a reference
/// to the discretisation, which must outlive it.
class PointLocator {
public:
  explicit PointLocator(const model::Discretization& d);

  /// The first element, bodies and elements in order, that holds X: a point of its reference
  /// square maps onto X to 1e-10 of the element's size (so points on an edge or on the body's
  /// boundary, up to round-off, are found). `body` >= 0 searches that body only. nullopt if no
  /// element holds X.
  std::optional<PointLocation> locate(const Vec2& X, int body = -1) const;

private:
  struct Box {
    int body, element;
    Eigen::AlignedBox2d box;
    double size;  ///< diagonal of the element's own (unwidened) box
  };
  const model::Discretization& d_;
  std::vector<Box> boxes_;
};

}  // namespace hpcontact::post
