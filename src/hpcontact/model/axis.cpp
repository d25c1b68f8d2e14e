// An axisymmetric body's section against its axis: round-off put on it, edges and nodes on it,
// a deformed section that crosses it.
#include "hpcontact/model/axis.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "hpcontact/model/discretization.hpp"

namespace hpcontact::model {

namespace {

double extent(const std::vector<Vec2>& xy) {
  if (xy.empty()) return 0;
  Vec2 lo = xy.front(), hi = xy.front();
  for (const auto& p : xy) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

}  // namespace

void snap_to_axis(std::vector<Vec2>& xy) {
  const double tol = kAxisTolerance * extent(xy);
  for (auto& p : xy)
    if (std::abs(p.x()) <= tol) p.x() = 0;
}

bool edge_on_axis(const mesh::Mesh& mesh, int e) {
  const auto& edge = mesh.edge(e);
  if (mesh.node(edge.v0).x() != 0 || mesh.node(edge.v1).x() != 0) return false;
  return std::abs(mesh.edge_point(e, 0.0).x()) <= kAxisTolerance * mesh.size();
}

std::vector<int> axis_nodes(const mesh::Mesh& mesh) {
  std::vector<int> nodes;
  for (int v = 0; v < mesh.n_nodes(); ++v)
    if (mesh.node(v).x() == 0) nodes.push_back(v);
  return nodes;
}

std::optional<std::string> crosses_axis(const Body& body, const Eigen::VectorXd& u) {
  int worst = -1;
  double r_min = -kAxisTolerance * body.mesh.size();
  for (int v = 0; v < body.mesh.n_nodes(); ++v) {
    if (body.mesh.node(v).x() == 0) continue;  // on the axis: u_r = 0 or axis_left_free's warning
    const double r = body.mesh.node(v).x() + u(body.dof_offset + 2 * body.dofs.vertex_mode(v));
    if (r < r_min) {
      r_min = r;
      worst = v;
    }
  }
  if (worst < 0) return std::nullopt;
  std::ostringstream os;
  os << "node " << body.mesh.node_id(worst) << " at r = " << body.mesh.node(worst).x()
     << " is displaced to r + u_r = " << r_min;
  return os.str();
}

}  // namespace hpcontact::model
