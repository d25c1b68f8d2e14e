// Warnings about a solved state: the axis of an axisymmetric body, coarse contact edges.
#include "hpcontact/driver/solution_warnings.hpp"

#include <algorithm>
#include <iomanip>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

#include "hpcontact/mesh/element_shape.hpp"
#include "hpcontact/model/axis.hpp"

namespace hpcontact::driver {

namespace {

std::string body_place(const model::ProblemSpec& spec, const model::Discretization& d, size_t b) {
  return spec.file + ": bodies[" + std::to_string(b) + "] (" + d.bodies[b].name + ")";
}

/// The contact edges (indices into pair.edges) that carry the zone: those with an active
/// multiplier node (exact), or with a point that has a pressure (penalty).
std::set<int> edges_in_contact(const model::ContactPair& pair, const model::ContactResult& c) {
  std::set<int> edges;
  if (pair.constraints) {
    const auto& per_edge = pair.constraints->nodes.edge_nodes;
    for (size_t k = 0; k < per_edge.size(); ++k)
      for (int j : per_edge[k])
        if (c.nodes[j].active) edges.insert(static_cast<int>(k));
  } else {
    for (size_t i = 0; i < c.states.size(); ++i)
      if (c.states[i].pressure > 0) edges.insert(pair.points[i].edge);
  }
  return edges;
}

/// A zone within one or two contact edges, shorter than kZoneToEdgeLimit of them.
std::optional<std::string> coarse_zone(const model::ProblemSpec& spec, const model::Discretization& d,
                                       size_t k, const model::ContactPair& pair,
                                       const model::ContactResult& c) {
  const auto edges = edges_in_contact(pair, c);
  if (edges.empty() || edges.size() > 2) return std::nullopt;
  const auto& body = d.bodies[pair.body];
  double shortest = std::numeric_limits<double>::infinity();
  int element = -1;
  for (int e : edges) {
    const auto& edge = body.mesh.edge(pair.edges[e]);
    const double L = mesh::edge_length(body.maps[edge.quads[0]], edge.local_edge[0], 8);
    if (L < shortest) {
      shortest = L;
      element = body.mesh.quad_id(edge.quads[0]);
    }
  }
  if (!(c.contact_length < kZoneToEdgeLimit * shortest)) return std::nullopt;
  std::ostringstream os;
  os << std::setprecision(4) << spec.contact[k].where.str() << ": the contact zone (" << c.contact_length
     << " long) lies on " << edges.size() << " contact edge(s) of body '" << body.name
     << "', the shortest " << shortest << " long (element " << element << "): its pressure, peak "
     << "and ends are that element's polynomial's; refine the mesh towards the zone, or adapt "
        "(adapt: {method: hp})";
  return os.str();
}

/// A singular point: where, that its peak is no converged value, and the fitted strength.
std::string singular_point(const model::ProblemSpec& spec, size_t k, const model::SingularPoint& p) {
  std::ostringstream os;
  os << std::setprecision(5) << spec.contact[k].where.str() << ": the pressure is unbounded at ("
     << p.X.x() << ", " << p.X.y() << "), " << p.where << ", where the contact zone is closed: its peak "
     << p.peak << " is the discretisation's, not a converged value (pressure_max " << "is the largest "
     << "beyond " << p.pressure_max_beyond << " from it); ";
  if (p.fit)
    os << "p ≈ K d^-λ with K = " << p.fit->strength << ", λ = " << p.fit->exponent << " (fitted over d = "
       << p.fit->from << " … " << p.fit->to << ", " << p.fit->points << " points; as a square-root "
       << "singularity K½ = " << p.fit->square_root_strength << ")";
  else
    os << "too few pressures beyond the elements touching it to fit its strength: refine the mesh "
          "towards it";
  return os.str();
}

}  // namespace

std::vector<std::string> solution_warnings(const model::ProblemSpec& spec,
                                           const model::Discretization& d, const Eigen::VectorXd& u,
                                           const std::vector<model::ContactPair>& pairs,
                                           const std::vector<model::ContactResult>& contact) {
  std::vector<std::string> out;
  for (size_t b = 0; b < d.bodies.size(); ++b) {
    const auto& body = d.bodies[b];
    if (!body.axisymmetric() || body.finite_strain()) continue;
    if (const auto where = model::crosses_axis(body, u))
      out.push_back(body_place(spec, d, b) + ": the deformed section crosses the axis r = 0 (" +
                    *where + "): displacements of the order of the radius are beyond linear " +
                    "elasticity (material.model: neo-hooke follows them)");
  }
  for (size_t k = 0; k < pairs.size() && k < contact.size(); ++k) {
    if (const auto w = coarse_zone(spec, d, k, pairs[k], contact[k])) out.push_back(*w);
    for (const auto& p : contact[k].singular_points) out.push_back(singular_point(spec, k, p));
  }
  return out;
}

}  // namespace hpcontact::driver
