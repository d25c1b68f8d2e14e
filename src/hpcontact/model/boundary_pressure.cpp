// The pressures at any point of a pair's contact boundary, located by its coordinate along the
// obstacle: the traction the method carries and what the stresses say there.
#include "hpcontact/model/boundary_pressure.hpp"

#include <algorithm>
#include <cmath>

#include "hpcontact/core/roots.hpp"
#include "hpcontact/fem/edge_load.hpp"
#include "hpcontact/model/boundary_point.hpp"
#include "hpcontact/model/boundary_stress.hpp"

namespace hpcontact::model {

std::vector<double> BoundaryPressureProbe::edge_ends() const {
  std::vector<double> ends;
  for (const auto& c : coord_) {
    ends.push_back(c.front());
    ends.push_back(c.back());
  }
  return ends;
}

BoundaryPressureProbe::BoundaryPressureProbe(const Discretization& d, const ContactPair& pair,
                                             const Eigen::VectorXd& u,
                                             const Eigen::VectorXd* multipliers)
    : d_(d), pair_(pair), u_(u), multipliers_(multipliers),
      common_tangent_(contact::line_frame(pair.reference_point, pair.tangent)),
      coord_(pair.edges.size()) {
  if (pair.other >= 0) {  // the other body's deformed boundary is the obstacle: at this state
    const Body &a = d.bodies[pair.body], &b = d.bodies[pair.other];
    pair.boundary->set_displacement(u.segment(a.dof_offset, a.dofs.n_dofs()));
    pair.other_boundary->set_displacement(u.segment(b.dof_offset, b.dofs.n_dofs()));
  }
  range_.resize(pair.edges.size());
  for (size_t k = 0; k < pair.edges.size(); ++k) {
    for (int i = 0; i <= kSamples; ++i)
      coord_[k][i] = coordinate(static_cast<int>(k), -1 + 2.0 * i / kSamples);
    const auto [lo, hi] = std::minmax_element(coord_[k].begin(), coord_[k].end());
    range_[k] = {*lo, *hi};
  }
}

double BoundaryPressureProbe::traction(int k, double t, Vec2* x, Vec2* X) const {
  const Body& body = d_.bodies[pair_.body];
  const auto& edge = body.mesh.edge(pair_.edges[k]);
  const bool exact = pair_.constraints && multipliers_;
  if (exact && !x && !X) return pair_.constraints->nodes.interpolate(k, t, *multipliers_);
  const double g = gap_at(body, *pair_.obstacle, edge.quads[0], edge.local_edge[0], t, u_, x, X);
  if (exact) return pair_.constraints->nodes.interpolate(k, t, *multipliers_);
  return g < 0 ? -pair_.penalty * g : 0.0;
}

bool BoundaryPressureProbe::has_tangential_traction() const {
  return pair_.constraints && multipliers_ && pair_.constraints->has_friction();
}

double BoundaryPressureProbe::tangential_traction(int k, double t) const {
  if (!has_tangential_traction()) return 0;
  const int n = pair_.constraints->size();
  return pair_.constraints->nodes.interpolate(k, t, multipliers_->segment(n, n));
}

double BoundaryPressureProbe::coordinate(int k, double t) const {
  const Body& body = d_.bodies[pair_.body];
  const auto& edge = body.mesh.edge(pair_.edges[k]);
  const Vec2 X = fem::edge_geometry(body.maps[edge.quads[0]], edge.local_edge[0], t, nullptr, nullptr);
  return pair_.coordinate(X);
}

std::optional<BoundaryPressure> BoundaryPressureProbe::operator()(double s) const {
  const Body& body = d_.bodies[pair_.body];
  const double tol = 1e-12 * (1 + std::abs(s));  // s on a node: round-off must not hide it
  for (size_t k = 0; k < coord_.size(); ++k) {
    if (s < range_[k].first - tol || s > range_[k].second + tol) continue;
    for (int i = 0; i < kSamples; ++i) {
      double fa = coord_[k][i] - s, fb = coord_[k][i + 1] - s;
      if (std::abs(fa) <= tol) fa = 0;
      if (std::abs(fb) <= tol) fb = 0;
      if (fa * fb > 0) continue;
      const double t = pegasus_root([&](double r) { return coordinate(static_cast<int>(k), r) - s; },
                                    -1 + 2.0 * i / kSamples, -1 + 2.0 * (i + 1) / kSamples, fa, fb, tol);
      const auto& edge = body.mesh.edge(pair_.edges[k]);
      const int q = edge.quads[0], le = edge.local_edge[0];
      BoundaryPressure bp;
      bp.traction = traction(static_cast<int>(k), t);
      const SideValues sv = side_values(body, pair_, *pair_.obstacle, *common_tangent_, q, le, t, u_);
      bp.X = sv.X;
      bp.pressure = bp.traction * sv.length_ratio;
      bp.pressure_from_stress = sv.pressure_from_stress;
      bp.minus_sigma_nn = sv.minus_sigma_nn;
      return bp;
    }
  }
  return std::nullopt;
}

}  // namespace hpcontact::model
