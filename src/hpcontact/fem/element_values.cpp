// Evaluation of shape functions through the element map at quadrature points.
#include "hpcontact/fem/element_values.hpp"

#include <cmath>

#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/core/error.hpp"

namespace hpcontact::fem {

ElementValues element_values(const ElementSpace& space, const mesh::ElementMap& map, int n_gauss,
                             const mesh::Mesh& mesh, int q) {
  const auto& rule = basis::gauss_legendre(n_gauss);
  const int n = space.n_modes(), nq = n_gauss * n_gauss;
  ElementValues ev;
  ev.N.resize(n, nq);
  ev.dN_dx.resize(n, nq);
  ev.dN_dy.resize(n, nq);
  ev.JxW.resize(nq);
  ev.x.resize(nq);
  std::vector<double> dxi(n), deta(n);
  Mat2 J;
  for (int i = 0, k = 0; i < n_gauss; ++i) {
    for (int j = 0; j < n_gauss; ++j, ++k) {
      const double xi = rule.points[i], eta = rule.points[j];
      ev.x[k] = map.map(xi, eta, &J);
      const double det = J.determinant();
      HPC_REQUIRE(det > 0 && std::isfinite(det), MeshError, mesh.context(), ": element ",
                  mesh.quad_id(q), " has a non-positive Jacobian determinant ", det,
                  " at (xi, eta) = (", xi, ", ", eta, "): it is inverted or its curved edges cross");
      ev.JxW(k) = rule.weights[i] * rule.weights[j] * det;
      space.evaluate(xi, eta, ev.N.col(k).data(), dxi.data(), deta.data());
      // grad_phys = J^{-T} grad_ref
      const Mat2 Jinv_T = J.inverse().transpose();
      for (int a = 0; a < n; ++a) {
        ev.dN_dx(a, k) = Jinv_T(0, 0) * dxi[a] + Jinv_T(0, 1) * deta[a];
        ev.dN_dy(a, k) = Jinv_T(1, 0) * dxi[a] + Jinv_T(1, 1) * deta[a];
      }
    }
  }
  return ev;
}

PointValues point_values(const ElementSpace& space, const mesh::ElementMap& map, double xi,
                         double eta) {
  const int n = space.n_modes();
  PointValues pv;
  pv.N.resize(n);
  pv.dN_dx.resize(n);
  pv.dN_dy.resize(n);
  std::vector<double> dxi(n), deta(n);
  Mat2 J;
  pv.x = map.map(xi, eta, &J);
  pv.det_J = J.determinant();
  space.evaluate(xi, eta, pv.N.data(), dxi.data(), deta.data());
  const Mat2 Jinv_T = J.inverse().transpose();
  for (int a = 0; a < n; ++a) {
    pv.dN_dx(a) = Jinv_T(0, 0) * dxi[a] + Jinv_T(0, 1) * deta[a];
    pv.dN_dy(a) = Jinv_T(1, 0) * dxi[a] + Jinv_T(1, 1) * deta[a];
  }
  return pv;
}

}  // namespace hpcontact::fem
