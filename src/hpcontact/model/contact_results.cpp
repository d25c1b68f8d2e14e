// The results of a contact pair at a state, step by step: the rows at its points (Gauss points or
// multiplier nodes, model/contact_result_rows), the points' order along each boundary, the zone
// ends and extent (model/contact_zone_ends), the singular points and the largest pressure away
// from them; and the pair's constraint state and resultant.
#include "hpcontact/model/contact_results.hpp"

#include <stdexcept>
#include <vector>

#include "hpcontact/model/contact_forces.hpp"
#include "hpcontact/model/contact_result_rows.hpp"
#include "hpcontact/model/contact_zone_ends.hpp"

namespace hpcontact::model {

ConstraintState pair_constraint_state(const Discretization& d, const ContactPair& pair,
                                      const Eigen::VectorXd& u, const Eigen::VectorXd& multipliers,
                                      Eigen::VectorXd* residual) {
  const int m = pair.constraints->size();
  const Eigen::VectorXd lambda = multipliers.head(m);
  Eigen::VectorXd lambda_t;
  FrictionInputs fi;
  if (pair.constraints->has_friction() && multipliers.size() == 2 * m) {
    lambda_t = multipliers.tail(m);
    fi.lambda_t = &lambda_t;
  }
  return evaluate_constraints(d, pair, u, lambda, residual, nullptr, false, fi);
}

Vec2 contact_resultant(const Discretization& d, const ContactPair& pair, const Eigen::VectorXd& u,
                       const Eigen::VectorXd* multipliers) {
  if (pair.constraints) {
    if (!multipliers) throw std::invalid_argument("contact_resultant: an exact pair needs its multipliers");
    return pair_constraint_state(d, pair, u, *multipliers).resultant;
  }
  return pair_forces(d, pair, u, nullptr).resultant(pair);
}

namespace {

/// The mesh edge of each state's point of a pair's own side: its multiplier node's first edge
/// (exact enforcement) or its contact point's.
std::vector<int> state_edges(const ContactPair& pair) {
  std::vector<int> edges;
  if (pair.constraints)
    for (const auto& node : pair.constraints->nodes.nodes) edges.push_back(pair.constraints->edges[node.edge]);
  else
    for (const auto& cp : pair.points) edges.push_back(pair.edges[cp.edge]);
  return edges;
}

/// The mesh edge of each of the other body's contact points.
std::vector<int> other_point_edges(const ContactPair& pair) {
  std::vector<int> edges;
  for (const auto& cp : pair.other_points) edges.push_back(pair.other_edges[cp.edge]);
  return edges;
}

}  // namespace

ContactResult evaluate_contact(const Discretization& d, const ContactPair& pair,
                               const Eigen::VectorXd& u, const Eigen::VectorXd* multipliers,
                               const Eigen::VectorXd* step_slips, const Eigen::VectorXd* total_slips) {
  ContactResult res;
  if (pair.constraints) {
    if (!multipliers) throw std::invalid_argument("evaluate_contact: an exact pair's results need its multipliers");
    add_multiplier_node_rows(res, d, pair, u, *multipliers, step_slips, total_slips);
  } else {
    add_gauss_point_rows(res, d, pair, u);
  }
  res.order = contact::boundary_order(d.bodies[pair.body].mesh, state_edges(pair));
  if (pair.other >= 0) res.other_order = contact::boundary_order(d.bodies[pair.other].mesh, other_point_edges(pair));
  ZoneEnds own = own_zone_ends(d, pair, u, multipliers, res);
  res.gamma_star = std::move(own.X);
  res.gamma_star_deformed = std::move(own.x);
  res.outer_ends = std::move(own.outer);
  if (pair.other >= 0) res.other_zone_ends = other_zone_ends(d, pair, u, res);
  if (const auto extent = zone_extent(pair, res)) {
    res.zone = extent->zone;
    res.contact_length = extent->zone.second - extent->zone.first;
    res.half_width = extent->half_width;
    res.zone_deformed = extent->zone_deformed;
  }
  res.singular_points = singular_points(d, pair, u, res);
  res.pressure_max = pressure_max_away(res, res.singular_points);
  return res;
}

}  // namespace hpcontact::model
