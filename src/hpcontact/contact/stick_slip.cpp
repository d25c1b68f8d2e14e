// Stick and slip along a contact boundary: neighbouring points and the transitions between them.
#include "hpcontact/contact/stick_slip.hpp"

#include "hpcontact/core/error.hpp"

namespace hpcontact::contact {

namespace {

int common_vertices(const mesh::Edge& a, const mesh::Edge& b) {
  return (a.v0 == b.v0 || a.v0 == b.v1) + (a.v1 == b.v0 || a.v1 == b.v1);
}

bool neighbours(const mesh::Mesh& mesh, int edge_a, int edge_b) {
  return edge_a == edge_b || common_vertices(mesh.edge(edge_a), mesh.edge(edge_b)) > 0;
}

bool frictional(const PointState& s) { return s.stick_slip != StickSlip::open; }

}  // namespace

BoundaryOrder boundary_order(const mesh::Mesh& mesh, const std::vector<int>& point_edges) {
  BoundaryOrder order;
  const size_t n = point_edges.size();
  order.follows.assign(n, 0);
  bool one_chain = n > 1;
  int n_edges = n > 0 ? 1 : 0;
  for (size_t i = 1; i < n; ++i) {
    order.follows[i] = neighbours(mesh, point_edges[i - 1], point_edges[i]);
    one_chain = one_chain && order.follows[i];
    n_edges += point_edges[i] != point_edges[i - 1];
  }
  if (one_chain && point_edges.front() != point_edges.back()) {
    const int shared = common_vertices(mesh.edge(point_edges.front()), mesh.edge(point_edges.back()));
    order.closed = n_edges == 2 ? shared == 2 : shared > 0;
  }
  return order;
}

std::vector<Vec2> stick_slip_transitions(const std::vector<PointState>& states,
                                         const std::vector<Vec2>& X, const BoundaryOrder& order) {
  HPC_ASSERT(states.size() == X.size() && states.size() == order.follows.size(), "stick_slip_transitions: ",
             states.size(), " states, ", X.size(), " positions, ", order.follows.size(), " follows");
  std::vector<Vec2> transitions;
  auto changes = [&](size_t a, size_t b) {
    return frictional(states[a]) && frictional(states[b]) && states[a].stick_slip != states[b].stick_slip;
  };
  for (size_t i = 1; i < states.size(); ++i)
    if (order.follows[i] && changes(i - 1, i)) transitions.push_back(0.5 * (X[i - 1] + X[i]));
  if (order.closed && states.size() > 2 && changes(states.size() - 1, 0))
    transitions.push_back(0.5 * (X.back() + X.front()));
  return transitions;
}

}  // namespace hpcontact::contact
