// Contact points: only the modes of the edge's two vertices and the edge itself are non-zero on
// it, so each point keeps p + 1 modes instead of the element's (p + 1)².
#include "hpcontact/contact/contact_boundary.hpp"

#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/fem/edge_load.hpp"

namespace hpcontact::contact {

std::vector<ContactPoint> contact_points(const mesh::Mesh& mesh, const fem::DofMap& dofs,
                                         const std::vector<mesh::ElementMap>& maps,
                                         const std::vector<int>& edges, int n_points,
                                         double thickness) {
  const auto& rule = basis::gauss_legendre(n_points);
  std::vector<ContactPoint> points;
  for (int e : edges) {
    const auto& edge = mesh.edge(e);
    HPC_REQUIRE(edge.on_boundary(), InputError, mesh.context(), ": contact edge ",
                mesh.node_id(edge.v0), "-", mesh.node_id(edge.v1), " is not on the boundary");
    const int q = edge.quads[0], le = edge.local_edge[0];
    const auto& es = dofs.element(q);
    const int n = es.n_modes();
    Eigen::VectorXd N(n);
    // Which local modes live on this edge: evaluate at an interior point of the edge.
    std::vector<int> local;
    {
      const auto r = fem::edge_reference_point(le, 0.123456789);
      es.evaluate(r[0], r[1], N.data(), nullptr, nullptr);
      for (int a = 0; a < n; ++a)
        if (N(a) != 0.0) local.push_back(a);
    }
    for (int i = 0; i < rule.size(); ++i) {
      ContactPoint cp;
      cp.element = q;
      cp.local_edge = le;
      cp.t = rule.points[i];
      double ds_dt;
      cp.X = fem::edge_geometry(maps[q], le, cp.t, &cp.normal, &ds_dt);
      cp.weight = rule.weights[i] * ds_dt * thickness;
      const auto r = fem::edge_reference_point(le, cp.t);
      es.evaluate(r[0], r[1], N.data(), nullptr, nullptr);
      cp.N.resize(local.size());
      for (size_t k = 0; k < local.size(); ++k) {
        cp.modes.push_back(es.modes[local[k]]);
        cp.N(k) = N(local[k]);
      }
      points.push_back(std::move(cp));
    }
  }
  return points;
}

}  // namespace hpcontact::contact
