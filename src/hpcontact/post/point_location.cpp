// Point location by bounding boxes and Newton's method on the element map.
#include "hpcontact/post/point_location.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace hpcontact::post {

namespace {

/// Newton's method for x(xi, eta) = X from a start point, each iterate clamped into [-1, 1]²
/// (the map need not be defined outside it), run until the step stalls at round-off (so the
/// point found is as accurate as the map); X is found if the residual is then below `tol`.
std::optional<Vec2> invert(const mesh::ElementMap& map, const Vec2& X, Vec2 xi, double tol) {
  for (int it = 0; it < 50; ++it) {
    Mat2 J;
    const Vec2 r = X - map.map(xi.x(), xi.y(), &J);
    if (r.isZero(0)) break;
    const double det = J.determinant();
    // A singular map (a 180° corner) at the iterate: step a hair towards the centre instead.
    const Vec2 step = std::abs(det) > 1e-14 * J.squaredNorm() ? Vec2(J.inverse() * r)
                                                               : Vec2(-1e-6 * xi);
    if (!step.allFinite()) return std::nullopt;
    const Vec2 next = (xi + step).cwiseMax(-1.0).cwiseMin(1.0);
    const bool stalled = (next - xi).lpNorm<Eigen::Infinity>() < 1e-15;
    xi = next;
    if (stalled) break;  // converged, or stuck on the square's boundary with X outside
  }
  if ((X - map.map(xi.x(), xi.y())).norm() > tol) return std::nullopt;
  return xi;
}

}  // namespace

PointLocator::PointLocator(const model::Discretization& d) : d_(d) {
  constexpr int kSamples = 16;  // per edge of the reference square
  for (int b = 0; b < static_cast<int>(d.bodies.size()); ++b) {
    const auto& body = d.bodies[b];
    for (int q = 0; q < body.mesh.n_quads(); ++q) {
      Eigen::AlignedBox2d box;
      for (int i = 0; i <= kSamples; ++i) {
        const double s = -1 + 2.0 * i / kSamples;
        for (const Vec2& ref : {Vec2(s, -1), Vec2(1, s), Vec2(-s, 1), Vec2(-1, -s)})
          box.extend(body.maps[q].map(ref.x(), ref.y()));
      }
      const double size = box.diagonal().norm();
      const Vec2 pad = Vec2::Constant(0.05 * size);
      box.extend(Vec2(box.min() - pad));
      box.extend(Vec2(box.max() + pad));
      boxes_.push_back({b, q, box, size});
    }
  }
}

std::optional<PointLocation> PointLocator::locate(const Vec2& X, int body) const {
  // Newton from the centre first; from the four quarter centres where that fails (strongly
  // curved elements, a start on the wrong side of a singular corner).
  static const std::array<Vec2, 5> starts = {Vec2(0, 0), Vec2(-0.5, -0.5), Vec2(0.5, -0.5),
                                             Vec2(0.5, 0.5), Vec2(-0.5, 0.5)};
  for (const auto& e : boxes_) {
    if (body >= 0 && e.body != body) continue;
    if (!e.box.contains(X)) continue;
    const auto& map = d_.bodies[e.body].maps[e.element];
    for (const Vec2& start : starts)
      if (const auto xi = invert(map, X, start, 1e-10 * e.size))
        return PointLocation{e.body, e.element, xi->x(), xi->y()};
  }
  return std::nullopt;
}

}  // namespace hpcontact::post
