// The follower loads' forces at a converged state, from the contact it finds there.
#include "hpcontact/model/follower_forces.hpp"

#include <algorithm>

#include "hpcontact/model/contact_forces.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::model {

void add_point_marks(const ContactPair& pair, const PairForces& f, std::vector<ContactMark>& marks) {
  for (size_t i = 0; i < f.states.size(); ++i)
    marks.push_back({pair.body, pair.edges[pair.points[i].edge], pair.points[i].t, pair.points[i].X,
                     f.states[i].pressure});
  for (size_t i = 0; i < f.other_states.size(); ++i)
    marks.push_back({pair.other, pair.other_edges[pair.other_points[i].edge], pair.other_points[i].t,
                     pair.other_points[i].X, f.other_states[i].pressure});
}

ContactMark node_mark(const ContactPair& pair, int j, double pressure) {
  const PairConstraints& c = *pair.constraints;
  const auto& node = c.nodes.nodes[j];
  return {pair.body, c.edges[node.edge], node.t, node.X, pressure};
}

std::vector<ContactMark> contact_marks(const Discretization& d, const ContactPair& pair,
                                       const Eigen::VectorXd& u, const Eigen::VectorXd& multipliers) {
  std::vector<ContactMark> marks;
  if (pair.constraints) {
    for (int j = 0; j < pair.constraints->size(); ++j)
      marks.push_back(node_mark(pair, j, j < multipliers.size() ? std::max(0.0, multipliers(j)) : 0.0));
    return marks;
  }
  add_point_marks(pair, pair_forces(d, pair, u, nullptr), marks);
  return marks;
}

Eigen::VectorXd follower_forces(const Discretization& d, const std::vector<ContactPair>& pairs,
                                const Eigen::VectorXd& u, const std::vector<Eigen::VectorXd>& multipliers,
                                double loads_factor, std::vector<WetRange>* ranges) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(d.n_dofs);
  if (ranges) ranges->clear();
  for (const FollowerLoad& L : d.follower_loads) {
    std::vector<ContactMark> marks;
    if (L.penetration && L.penetration->pair < static_cast<int>(pairs.size())) {
      const int k = L.penetration->pair;
      marks = contact_marks(d, pairs[k], u, k < static_cast<int>(multipliers.size()) ? multipliers[k] : Eigen::VectorXd());
    }
    const WetRange range = wetted_range(L, marks, loads_factor);
    if (ranges) ranges->push_back(range);
    add_follower_force(d, L, u, range, loads_factor, f, nullptr);
  }
  return f;
}

}  // namespace hpcontact::model
