// The blending map x = sum_i N_i(xi,eta) X_i + sum_i e_i(xi,eta) (seed eq. 2.74).
#include "hpcontact/geometry/blending.hpp"

namespace hpcontact::geometry {

Vec2 BlendingQuad::map(double xi, double eta, Mat2* J) const {
  const auto& X = vertices;
  // Bilinear part (eq. 2.74, first sum) and its derivatives.
  const double a = 0.25 * (1 - xi) * (1 - eta), b = 0.25 * (1 + xi) * (1 - eta),
               c = 0.25 * (1 + xi) * (1 + eta), d = 0.25 * (1 - xi) * (1 + eta);
  Vec2 x = a * X[0] + b * X[1] + c * X[2] + d * X[3];
  Vec2 x_xi = 0.25 * ((1 - eta) * (X[1] - X[0]) + (1 + eta) * (X[2] - X[3]));
  Vec2 x_eta = 0.25 * ((1 - xi) * (X[3] - X[0]) + (1 + xi) * (X[2] - X[1]));

  // Edge terms e_i: the deviation of the curve from its chord, faded linearly to the opposite
  // edge (eq. 2.75). For local edge e with parameter t in [-1, 1] and curve parameter s = (t+1)/2:
  //   deviation D(t) = E(t) - ((1-t)/2 A + (1+t)/2 B),   dD/dt = E'(s)/2 - (B - A)/2.
  auto deviation = [](const CurvePtr& E, const Vec2& A, const Vec2& B, double t, Vec2& dD_dt) {
    const double s = 0.5 * (t + 1);
    dD_dt = 0.5 * E->tangent(s) - 0.5 * (B - A);
    return Vec2(E->point(s) - (0.5 * (1 - t) * A + 0.5 * (1 + t) * B));
  };
  Vec2 dD;
  if (edges[0]) {  // E1: eta = -1, parameter xi, blend (1 - eta)/2
    const Vec2 D = deviation(edges[0], X[0], X[1], xi, dD);
    x += 0.5 * (1 - eta) * D;
    x_xi += 0.5 * (1 - eta) * dD;
    x_eta -= 0.5 * D;
  }
  if (edges[1]) {  // E2: xi = +1, parameter eta, blend (1 + xi)/2
    const Vec2 D = deviation(edges[1], X[1], X[2], eta, dD);
    x += 0.5 * (1 + xi) * D;
    x_xi += 0.5 * D;
    x_eta += 0.5 * (1 + xi) * dD;
  }
  if (edges[2]) {  // E3: eta = +1, parameter xi, blend (1 + eta)/2
    const Vec2 D = deviation(edges[2], X[3], X[2], xi, dD);
    x += 0.5 * (1 + eta) * D;
    x_xi += 0.5 * (1 + eta) * dD;
    x_eta += 0.5 * D;
  }
  if (edges[3]) {  // E4: xi = -1, parameter eta, blend (1 - xi)/2
    const Vec2 D = deviation(edges[3], X[0], X[3], eta, dD);
    x += 0.5 * (1 - xi) * D;
    x_xi -= 0.5 * D;
    x_eta += 0.5 * (1 - xi) * dD;
  }
  if (J) {
    J->col(0) = x_xi;
    J->col(1) = x_eta;
  }
  return x;
}

}  // namespace hpcontact::geometry
