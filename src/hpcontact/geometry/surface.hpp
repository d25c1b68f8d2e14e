// Exact surfaces that give hexahedron faces and edges their shape, each as a map onto itself.
#pragma once

#include <memory>
#include <string>

#include <Eigen/Dense>

namespace hpcontact::geometry {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// A smooth surface S given by an explicit map P from the space around it onto it, with P(x) = x
/// for x on S (a retraction; no closest-point iteration), and a curve on S between two of its
/// points (edge()). The blending map of a hexahedron (blending_hex.hpp) places a face on S as
/// P(T(s, t)), T the transfinite interpolant of the face's edges, and an edge as edge(A, B, t):
/// since P fixes S's points, a face so mapped passes through its edges exactly when they lie on S.
class Surface {
 public:
  virtual ~Surface() = default;
  /// P(y) and, if dP is not null, its derivative dP/dy (3 × 3; dP_ij = ∂P_i/∂y_j). Defined off
  /// a set of measure zero (a sphere's centre, a cylinder's axis), where it throws InputError.
  virtual Vec3 onto(const Vec3& y, Mat3* dP = nullptr) const = 0;
  /// The curve E(t), t in [−1, 1], on S from A = E(−1) to B = E(1) (both on S), and if dE is not
  /// null dE/dt. The default is the image of the chord, P((1 − t)/2 A + (1 + t)/2 B); the sphere
  /// and the cylinder override it with curves uniform in angle, so that a circular edge has the
  /// parametrisation of the 2D code's CircularArc (geometry/curve.hpp) and a hexahedron extruded
  /// from a plane blending quadrilateral (geometry/blending.hpp) has that map in every section.
  virtual Vec3 edge(const Vec3& A, const Vec3& B, double t, Vec3* dE = nullptr) const;
  /// True for a plane: a chord between two of its points lies on it.
  virtual bool flat() const { return false; }
  /// Short description for messages, e.g. "sphere(centre=(0,0,0), R=2)".
  virtual std::string describe() const = 0;
};

using SurfacePtr = std::shared_ptr<const Surface>;

/// Sphere |x − c| = R, by central projection from its centre: P(y) = c + R (y − c)/|y − c|,
///   dP/dy = R/|y − c| (I − n nᵀ),  n = (y − c)/|y − c|.
/// It maps a chord to a great-circle arc and keeps every plane through c. edge(): the great-circle
/// arc from A to B uniform in angle (slerp of the directions n_A, n_B at angle ω between them,
/// s = (t + 1)/2):  E = c + R [sin((1 − s) ω) n_A + sin(s ω) n_B] / sin ω  (the shorter arc; the
/// chord when A = B; InputError for antipodal points, whose great circle is not unique).
class Sphere final : public Surface {
 public:
  Sphere(Vec3 centre, double radius);
  Vec3 onto(const Vec3& y, Mat3* dP = nullptr) const override;
  Vec3 edge(const Vec3& A, const Vec3& B, double t, Vec3* dE = nullptr) const override;
  std::string describe() const override;
  const Vec3& centre() const { return c_; }
  double radius() const { return r_; }

 private:
  Vec3 c_;
  double r_;
};

/// Circular cylinder of radius R about the line c + s a (|a| = 1), by projection from the axis
/// along its normal plane: with y − c = (a·(y − c)) a + w, P(y) = c + (a·(y − c)) a + R w/|w|,
///   dP/dy = a aᵀ + R/|w| (I − n nᵀ)(I − a aᵀ),  n = w/|w|.
/// It keeps every plane that contains the axis or is normal to it. edge(): the helix uniform in
/// angle and in height, E = c + ((1 − s) h_A + s h_B) a + R slerp(n_A, n_B; s) (h the axial
/// coordinate, n the radial direction, s = (t + 1)/2, the shorter way round): a circle arc of the
/// normal plane uniform in angle when h_A = h_B, a straight generator when n_A = n_B.
class Cylinder final : public Surface {
 public:
  /// `axis` need not be a unit vector (it is normalised); throws InputError if it is zero.
  Cylinder(Vec3 point_on_axis, Vec3 axis, double radius);
  Vec3 onto(const Vec3& y, Mat3* dP = nullptr) const override;
  Vec3 edge(const Vec3& A, const Vec3& B, double t, Vec3* dE = nullptr) const override;
  std::string describe() const override;

 private:
  Vec3 c_, a_;
  double r_;
};

/// Plane (x − c)·n = 0, by orthogonal projection: P(y) = y − ((y − c)·n) n, dP/dy = I − n nᵀ.
class Plane final : public Surface {
 public:
  /// `normal` need not be a unit vector; throws InputError if it is zero.
  Plane(Vec3 point, Vec3 normal);
  Vec3 onto(const Vec3& y, Mat3* dP = nullptr) const override;
  bool flat() const override { return true; }
  std::string describe() const override;
  const Vec3& normal() const { return n_; }

 private:
  Vec3 c_, n_;
};

}  // namespace hpcontact::geometry
