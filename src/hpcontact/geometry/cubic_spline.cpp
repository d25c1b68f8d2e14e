// Natural cubic spline through points (chord-length knots) and closest-point projection onto it.
#include "hpcontact/geometry/cubic_spline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hpcontact/core/error.hpp"

namespace hpcontact::geometry {

namespace {
constexpr int samples_per_segment = 8;
}

CubicSpline::CubicSpline(std::vector<Vec2> points) : points_(std::move(points)) {
  const int n = static_cast<int>(points_.size()) - 1;
  HPC_REQUIRE(n >= 1, InputError, "a curve needs at least two points (got ", points_.size(), ")");
  double size = 0;
  for (const Vec2& p : points_) size = std::max(size, (p - points_.front()).norm());
  knots_.assign(n + 1, 0.0);
  for (int i = 0; i < n; ++i) {
    const double h = (points_[i + 1] - points_[i]).norm();
    HPC_REQUIRE(std::isfinite(h) && h > 1e-12 * size, InputError, "points ", i + 1, " and ", i + 2,
                " of the curve coincide (", points_[i].x(), ", ", points_[i].y(), ")");
    knots_[i + 1] = knots_[i] + h;
  }
  // x''(t_i) = M_i from the continuity of x' at the interior knots, M_0 = M_n = 0 (natural);
  // a tridiagonal system, solved by elimination (diagonally dominant: no pivoting needed).
  moments_.assign(n + 1, Vec2::Zero());
  if (n >= 2) {
    std::vector<double> diag(n + 1, 0.0), upper(n + 1, 0.0);
    std::vector<Vec2> rhs(n + 1, Vec2::Zero());
    for (int i = 1; i < n; ++i) {
      const double h0 = knots_[i] - knots_[i - 1], h1 = knots_[i + 1] - knots_[i];
      diag[i] = 2 * (h0 + h1);
      upper[i] = h1;
      rhs[i] = 6 * ((points_[i + 1] - points_[i]) / h1 - (points_[i] - points_[i - 1]) / h0);
      if (i > 1) {  // eliminate the sub-diagonal entry h0 against row i − 1
        const double m = h0 / diag[i - 1];
        diag[i] -= m * upper[i - 1];
        rhs[i] -= m * rhs[i - 1];
      }
    }
    for (int i = n - 1; i >= 1; --i)
      moments_[i] = (rhs[i] - upper[i] * moments_[i + 1]) / diag[i];
  }
  // Bounding discs: the samples' box centre, and their largest distance from it plus the most
  // the curve can bulge between two samples δ apart (|x''| δ² / 8; |x''| ≤ max |M| on a segment).
  for (int i = 0; i < n; ++i) {
    const double delta = (knots_[i + 1] - knots_[i]) / samples_per_segment;
    Vec2 lo = points_[i], hi = points_[i];
    for (int k = 1; k <= samples_per_segment; ++k) {
      const Vec2 p = point(knots_[i] + k * delta);
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    const Vec2 c = 0.5 * (lo + hi);
    double r = 0;
    for (int k = 0; k <= samples_per_segment; ++k)
      r = std::max(r, (point(knots_[i] + k * delta) - c).norm());
    const double bulge = std::max(moments_[i].norm(), moments_[i + 1].norm()) * delta * delta / 8;
    centres_.push_back(c);
    radii_.push_back(r + bulge + 1e-12 * (knots_[i + 1] - knots_[i]));
  }
}

int CubicSpline::segment(double t) const {
  const auto it = std::upper_bound(knots_.begin(), knots_.end(), t);
  const int i = static_cast<int>(it - knots_.begin()) - 1;
  return std::clamp(i, 0, static_cast<int>(knots_.size()) - 2);
}

Vec2 CubicSpline::point(double t) const {
  if (t < 0) return points_.front() + t * derivative(0);
  if (t > end()) return points_.back() + (t - end()) * derivative(end());
  const int i = segment(t);
  const double h = knots_[i + 1] - knots_[i], a = knots_[i + 1] - t, s = t - knots_[i];
  const Vec2 &m0 = moments_[i], &m1 = moments_[i + 1];
  return (m0 * a * a * a + m1 * s * s * s) / (6 * h) + (points_[i] - m0 * h * h / 6) * (a / h) +
         (points_[i + 1] - m1 * h * h / 6) * (s / h);
}

Vec2 CubicSpline::derivative(double t) const {
  t = std::clamp(t, 0.0, end());  // the straight extensions keep the end tangents
  const int i = segment(t);
  const double h = knots_[i + 1] - knots_[i], a = knots_[i + 1] - t, s = t - knots_[i];
  const Vec2 &m0 = moments_[i], &m1 = moments_[i + 1];
  return (m1 * s * s - m0 * a * a) / (2 * h) +
         ((points_[i + 1] - m1 * h * h / 6) - (points_[i] - m0 * h * h / 6)) / h;
}

Vec2 CubicSpline::second_derivative(double t) const {
  if (t < 0 || t > end()) return Vec2::Zero();
  const int i = segment(t);
  const double h = knots_[i + 1] - knots_[i];
  return (moments_[i] * (knots_[i + 1] - t) + moments_[i + 1] * (t - knots_[i])) / h;
}

double CubicSpline::closest_parameter(const Vec2& x) const {
  // f(t) = (x(t) − x)·x'(t) vanishes at a closest point; f' = |x'|² + (x(t) − x)·x''.
  const auto f = [&](double t) { return (point(t) - x).dot(derivative(t)); };
  const auto distance2 = [&](double t) { return (point(t) - x).squaredNorm(); };
  // Refine a minimum bracketed by [a, b] (f(a) ≤ 0 ≤ f(b) when interior): Newton, falling
  // back to bisection whenever a step leaves the bracket.
  const auto refine = [&](double a, double b) {
    double fa = f(a), fb = f(b);
    if (fa >= 0) return a;
    if (fb <= 0) return b;
    double t = 0.5 * (a + b);
    for (int it = 0; it < 60; ++it) {
      const Vec2 r = point(t) - x, d = derivative(t);
      const double ft = r.dot(d);
      if (ft == 0) return t;
      (ft < 0 ? a : b) = t;
      const double slope = d.squaredNorm() + r.dot(second_derivative(t));
      double next = slope > 0 ? t - ft / slope : 0.5 * (a + b);
      if (!(next > a && next < b)) next = 0.5 * (a + b);
      const bool done = std::abs(next - t) <= 1e-15 * (1 + std::abs(t)) * std::max(1.0, end());
      t = next;
      if (done || b - a <= 1e-15 * std::max(1.0, end())) break;
    }
    return t;
  };

  double best_t = 0, best = std::numeric_limits<double>::infinity();
  const auto consider = [&](double t) {
    if (const double d2 = distance2(t); d2 < best) {
      best = d2;
      best_t = t;
    }
  };
  const int n = static_cast<int>(knots_.size()) - 1;
  double bound = std::numeric_limits<double>::infinity();  // the closest point is no farther
  for (int i = 0; i < n; ++i) bound = std::min(bound, (x - centres_[i]).norm() + radii_[i]);
  for (int i = 0; i < n; ++i) {
    if ((x - centres_[i]).norm() - radii_[i] > bound) continue;
    const double h = (knots_[i + 1] - knots_[i]) / samples_per_segment;
    double d2[samples_per_segment + 1];
    for (int k = 0; k <= samples_per_segment; ++k) d2[k] = distance2(knots_[i] + k * h);
    for (int k = 0; k <= samples_per_segment; ++k) {
      const bool left_ok = k == 0 || d2[k] <= d2[k - 1];
      const bool right_ok = k == samples_per_segment || d2[k] <= d2[k + 1];
      if (!left_ok || !right_ok) continue;
      const double a = knots_[i] + std::max(k - 1, 0) * h;
      const double b = knots_[i] + std::min(k + 1, samples_per_segment) * h;
      consider(refine(a, b));
    }
  }
  // Beyond the ends, on the straight extensions: the foot of the perpendicular.
  const Vec2 d0 = derivative(0), d1 = derivative(end());
  if (const double t = (x - points_.front()).dot(d0) / d0.squaredNorm(); t < 0) consider(t);
  if (const double t = (x - points_.back()).dot(d1) / d1.squaredNorm(); t > 0) consider(end() + t);
  return best_t;
}

}  // namespace hpcontact::geometry
