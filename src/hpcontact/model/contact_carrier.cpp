// Choosing the body of a two-body pair that carries the multipliers, by a rule symmetric in the
// two bodies (contact[].carrier: auto).
#include "hpcontact/model/contact_carrier.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "hpcontact/contact/contact_boundary.hpp"
#include "hpcontact/contact/deformable_boundary.hpp"
#include "hpcontact/contact/multiplier_nodes.hpp"
#include "hpcontact/core/error.hpp"

namespace hpcontact::model {

namespace {

/// What the rule compares of one side of a pair.
struct Side {
  std::string name;
  int index = -1;        ///< the body's place under `bodies`
  double facing = 0;     ///< the share of its contact length with a foot on the other's boundary
  double density = 0;    ///< its multiplier nodes per unit length over that part
  double modulus = 0;    ///< E' at its first contact edge
};

/// The body's contact edges of `sets` in chain order.
std::vector<contact::ChainEdge> chained(const Body& body, const std::vector<std::string>& sets,
                                        const std::string& key) {
  std::vector<int> edges;
  for (const auto& name : sets) {
    const auto it = body.edge_sets.find(name);
    HPC_REQUIRE(it != body.edge_sets.end(), InputError, key, ": no edge set '", name, "' in body '",
                body.name, "'");
    edges.insert(edges.end(), it->second.begin(), it->second.end());
  }
  return contact::chain_edges(body.mesh, edges);
}

int body_index(const Discretization& d, const std::string& name, const std::string& key) {
  for (size_t b = 0; b < d.bodies.size(); ++b)
    if (d.bodies[b].name == name) return static_cast<int>(b);
  throw InputError(key + ": no body named '" + name + "'");
}

/// One side measured against the other's undeformed boundary (both as the input meshes them).
Side side(const Discretization& d, int b, const std::vector<contact::ChainEdge>& chain, int o,
          const std::vector<contact::ChainEdge>& other_chain) {
  const Body &body = d.bodies[b], &other = d.bodies[o];
  std::vector<int> edges, other_edges;
  for (const auto& ce : chain) edges.push_back(ce.edge);
  for (const auto& ce : other_chain) other_edges.push_back(ce.edge);
  const contact::DeformableBoundary partner(other.mesh, other.dofs, other.maps, other_edges);
  partner.set_displacement(Eigen::VectorXd::Zero(other.dofs.n_dofs()));
  contact::BoundaryPoint foot;
  const fem::OutOfPlane length;  // plain lengths: a share of the boundary, not of its area
  double total = 0, faced = 0;
  for (const auto& cp : contact::contact_points(body.mesh, body.dofs, body.maps, edges, 20, length)) {
    total += cp.weight;
    if (partner.project(cp.X, foot)) faced += cp.weight;
  }
  int faced_nodes = 0;
  for (const auto& node : contact::multiplier_nodes(body.mesh, body.dofs, body.maps, chain, length).nodes)
    if (partner.project(node.X, foot)) ++faced_nodes;
  Side s;
  s.name = body.name;
  s.index = b;
  s.facing = total > 0 ? faced / total : 0;
  s.density = faced > 0 ? faced_nodes / faced : 0;
  s.modulus = body.material_of(body.mesh.edge(chain.front().edge).quads[0]).plane_modulus();
  return s;
}

/// Whether a exceeds b by more than `tolerance` relative to the larger.
bool exceeds(double a, double b, double tolerance) {
  return a > b + tolerance * std::max(std::abs(a), std::abs(b));
}

std::string percent(double share) {
  std::ostringstream os;
  os.precision(3);
  os << 100 * share << " %";
  return os.str();
}

}  // namespace

CarrierChoice chosen_carrier(const ContactPairSpec& pair, const Discretization& d) {
  const std::string key = pair.where.str();
  HPC_ASSERT(pair.obstacle.kind == ObstacleKind::body, "a carrier is chosen between two bodies");
  const int b = body_index(d, pair.body, key + ".body"), o = body_index(d, pair.obstacle.body, key + ".obstacle.body");
  const auto chain = chained(d.bodies[b], pair.edge_sets, key + ".edges");
  const auto other_chain = chained(d.bodies[o], pair.obstacle.edge_sets, key + ".obstacle.edges");
  const Side own = side(d, b, chain, o, other_chain), other = side(d, o, other_chain, b, chain);
  // the first criterion that tells the two apart picks the carrier
  std::ostringstream why;
  bool obstacle_carries = false;
  if (std::abs(own.facing - other.facing) > 1e-3) {
    obstacle_carries = other.facing > own.facing;
    const Side &c = obstacle_carries ? other : own, &n = obstacle_carries ? own : other;
    why << "body '" << c.name << "' carries: its contact edges lie within body '" << n.name << "''s ("
        << percent(c.facing) << " of its contact length faces the other's boundary, " << percent(n.facing)
        << " of the other's faces it)";
  } else if (exceeds(own.density, other.density, 0.01) || exceeds(other.density, own.density, 0.01)) {
    obstacle_carries = other.density > own.density;
    const Side &c = obstacle_carries ? other : own, &n = obstacle_carries ? own : other;
    why << "body '" << c.name << "' carries: the finer contact mesh (" << c.density
        << " multiplier nodes per unit length where the bodies face each other, against " << n.density << ")";
  } else if (exceeds(own.modulus, other.modulus, 1e-9) || exceeds(other.modulus, own.modulus, 1e-9)) {
    obstacle_carries = other.modulus < own.modulus;
    const Side &c = obstacle_carries ? other : own, &n = obstacle_carries ? own : other;
    why << "body '" << c.name << "' carries: the softer (E' " << c.modulus << " against " << n.modulus << ")";
  } else {
    obstacle_carries = other.index < own.index;
    why << "body '" << (obstacle_carries ? other : own).name
        << "' carries: the two sides alike (shares facing each other, node densities, moduli), the "
           "body named first under bodies";
  }
  return {obstacle_carries, why.str()};
}

ProblemSpec with_chosen_carriers(const ProblemSpec& spec, const Discretization& d) {
  ProblemSpec out = spec;
  for (auto& pair : out.contact) {
    if (!pair.auto_carrier) continue;
    const CarrierChoice choice = chosen_carrier(pair, d);
    pair.auto_carrier = false;
    pair.carrier_choice = "auto: " + choice.reason;
    if (!choice.swap) continue;
    std::swap(pair.body, pair.obstacle.body);
    std::swap(pair.edge_sets, pair.obstacle.edge_sets);
    if (pair.normal_direction)  // the force on the pair's body: on the other body it is opposite
      for (double& v : *pair.normal_direction) v = -v;
  }
  return out;
}

ProblemSpec with_chosen_carriers(const ProblemSpec& spec) {
  const bool any = std::any_of(spec.contact.begin(), spec.contact.end(),
                               [](const ContactPairSpec& pair) { return pair.auto_carrier; });
  return any ? with_chosen_carriers(spec, discretize(spec)) : spec;
}

}  // namespace hpcontact::model
