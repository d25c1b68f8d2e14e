// Two deformable bodies in contact: the closest-point gap and the consistent tangent of the
// two-body penalty terms against finite differences of the contact forces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "hpcontact/contact/point_gap.hpp"
#include "hpcontact/contact/two_body.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/discretization.hpp"

using namespace hpcontact;

namespace {

// Two p = 4 elements with curved faces pressed into each other, not matching: the lower one's
// top edge bulges up (arc of radius 3), the upper one's bottom edge bulges down (radius 2.5),
// shifted sideways by 0.3.
const char* kTwoBlocks = R"(
case: two-blocks
bodies:
  - name: lower
    material: {E: 1000, nu: 0.3}
    nodes: {1: [0, -1], 2: [1, -1], 3: [1, 0], 4: [0, 0]}
    elements: {1: [1, 2, 3, 4]}
    curves: [{nodes: [3, 4], arc: {center: [0.5, -2.958039891549808], radius: 3.0}}]
    edge_sets: {top: [[3, 4]]}
  - name: upper
    material: {E: 1000, nu: 0.3}
    nodes: {1: [0.3, 0.05], 2: [1.3, 0.05], 3: [1.3, 1.05], 4: [0.3, 1.05]}
    elements: {1: [1, 2, 3, 4]}
    curves: [{nodes: [1, 2], arc: {center: [0.8, 2.499489742783178], radius: 2.5}}]
    edge_sets: {bottom: [[1, 2]]}
discretization: {degree: 4}
)";

/// The two blocks discretised, the upper one's 12 contact points per edge and the lower one's
/// contact boundary.
class TwoBodyContact : public ::testing::Test {
protected:
  const model::ProblemSpec spec = io::parse_problem(kTwoBlocks, "two-blocks.yaml");
  const model::Discretization d = model::discretize(spec);
  const model::Body& lo = d.bodies[0];
  const model::Body& up = d.bodies[1];
  const std::vector<contact::ContactPoint> pts = contact::contact_points(
      up.mesh, up.dofs, up.maps, up.edge_sets.at("bottom"), 12, up.thickness);
  const contact::DeformableBoundary boundary{lo.mesh, lo.dofs, lo.maps, lo.edge_sets.at("top")};
};

}  // namespace

// The analytic tangent of the two-body penalty terms (gap, its covariant linearisation with the
// curvature of the deformed boundary) is the derivative of the forces: compared with central
// differences of the forces over the dofs of both bodies at a state where the boundaries
// overlap (the state is chosen with no point within 1e-4 of the switch g = 0, where the force
// has a kink; asserted).
TEST_F(TwoBodyContact, TangentIsTheDerivativeOfTheForces) {
  const int ns = up.dofs.n_dofs(), nm = lo.dofs.n_dofs();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> r(-1, 1);
  Eigen::VectorXd us(ns), um(nm);
  for (int i = 0; i < ns; ++i) us(i) = 0.01 * r(rng);
  for (int i = 0; i < nm; ++i) um(i) = 0.01 * r(rng);
  us(1) -= 0.08;  // vertex 1 of the upper body pressed deeper (tilts it) ...
  for (int i = 1; i < ns; i += 2) us(i) -= 0.08;  // ... and the whole body pressed down
  const double eps = 1e5;
  auto forces = [&](const Eigen::VectorXd& a, const Eigen::VectorXd& b, std::vector<contact::PointState>* st,
                    std::vector<Eigen::Triplet<double>>* t) {
    boundary.set_displacement(b);
    Eigen::VectorXd fs = Eigen::VectorXd::Zero(ns), fm = Eigen::VectorXd::Zero(nm);
    contact::two_body_contact(pts, a, boundary, eps, 1.0, fs, fm, t, 0, ns, st);
    Eigen::VectorXd f(ns + nm);
    f << fs, fm;
    return f;
  };
  std::vector<contact::PointState> st;
  std::vector<Eigen::Triplet<double>> trip;
  forces(us, um, &st, &trip);
  int active = 0;
  for (const auto& s : st) {
    ASSERT_GT(std::abs(s.gap), 1e-4) << "a point sits on the switch; change the state";
    active += s.gap < 0;
  }
  ASSERT_GE(active, 4);
  ASSERT_LT(active, static_cast<int>(pts.size()));  // some open: the switch is inside the edge
  Eigen::SparseMatrix<double> K(ns + nm, ns + nm);
  K.setFromTriplets(trip.begin(), trip.end());
  const Eigen::MatrixXd Ka(K);
  Eigen::MatrixXd Kf(ns + nm, ns + nm);
  const double h = 1e-7;
  for (int j = 0; j < ns + nm; ++j) {
    Eigen::VectorXd ap = us, am = us, bp = um, bm = um;
    if (j < ns) {
      ap(j) += h;
      am(j) -= h;
    } else {
      bp(j - ns) += h;
      bm(j - ns) -= h;
    }
    Kf.col(j) = -(forces(ap, bp, nullptr, nullptr) - forces(am, bm, nullptr, nullptr)) / (2 * h);
  }
  const double scale = Ka.cwiseAbs().maxCoeff();
  const double diff = (Ka - Kf).cwiseAbs().maxCoeff();
  std::printf("active points %d of %zu; max |K - K_fd| / max |K| = %.3g\n", active, pts.size(),
              diff / scale);
  EXPECT_LT(diff, 1e-6 * scale);
}

// Equal and opposite: the forces on the two bodies have zero resultant (action = reaction).
TEST_F(TwoBodyContact, ForcesBalance) {
  Eigen::VectorXd us = Eigen::VectorXd::Zero(up.dofs.n_dofs()), um = Eigen::VectorXd::Zero(lo.dofs.n_dofs());
  for (int i = 1; i < us.size(); i += 2) us(i) = -0.08;
  boundary.set_displacement(um);
  Eigen::VectorXd fs = Eigen::VectorXd::Zero(us.size()), fm = Eigen::VectorXd::Zero(um.size());
  contact::two_body_contact(pts, us, boundary, 1e5, 1.0, fs, fm, nullptr, 0, 0, nullptr);
  // the vertex modes (0..3) sum to one on the element, so their forces sum to the resultant
  Vec2 rs = Vec2::Zero(), rm = Vec2::Zero();
  for (int v = 0; v < 4; ++v) {
    rs += Vec2(fs(2 * v), fs(2 * v + 1));
    rm += Vec2(fm(2 * v), fm(2 * v + 1));
  }
  EXPECT_GT(rs.y(), 0);
  EXPECT_LT((rs + rm).norm(), 1e-10 * rs.norm());
}

// The mean-normal gap (contact[].normal: mean) of every point at a state where the boundaries
// are tilted (the mean normal up to 0.02 rad and more from the vertical): its gradient dg_row, the derivative d2g
// of its force direction n̄ N, and the turning of its tangent (dtau, ddt) equal central
// differences of g, dg, τ and dt over the dofs of both bodies (relative to their largest
// entries: < 1e-6; measured ~1e-9). The force direction itself is n̄ N on both bodies,
// equal and opposite.
TEST_F(TwoBodyContact, MeanNormalGapDerivativesAgreeWithDifferences) {
  const contact::DeformableBoundary own{up.mesh, up.dofs, up.maps, up.edge_sets.at("bottom")};
  const int ns = up.dofs.n_dofs(), nm = lo.dofs.n_dofs();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> r(-1, 1);
  Eigen::VectorXd u(ns + nm);
  for (int i = 0; i < ns + nm; ++i) u(i) = 0.01 * r(rng);
  for (int i = 1; i < ns; i += 2) u(i) -= 0.06;
  const auto gap_at = [&](const Eigen::VectorXd& x, const contact::ContactPoint& cp, bool second) {
    own.set_displacement(x.head(ns));
    boundary.set_displacement(x.tail(nm));
    return contact::two_body_point_gap(cp, x.head(ns), boundary, 0, ns, second, &own, second);
  };
  int checked = 0;
  double angle = 0;  // the largest angle of n̄ from the vertical: the state is tilted
  for (const auto& cp : pts) {
    const contact::PointGap pg = gap_at(u, cp, true);
    if (!pg.found || pg.beyond_end) continue;
    ASSERT_EQ(pg.dg_row.size(), pg.dg.size());
    const int L = static_cast<int>(pg.dofs.size());
    Eigen::VectorXd dg_fd(L), dtau_err(L);
    Eigen::MatrixXd d2g_fd(L, L), ddt_fd(L, L), dtau_fd(2, L);
    const double h = 1e-6;
    for (int b = 0; b < L; ++b) {
      Eigen::VectorXd up_ = u, um_ = u;
      up_(pg.dofs[b]) += h;
      um_(pg.dofs[b]) -= h;
      const auto p = gap_at(up_, cp, false), m = gap_at(um_, cp, false);
      ASSERT_EQ(p.dofs, pg.dofs);  // the foot stays on its edge
      ASSERT_EQ(m.dofs, pg.dofs);
      dg_fd(b) = (p.g - m.g) / (2 * h);
      d2g_fd.col(b) = (p.dg - m.dg) / (2 * h);
      ddt_fd.col(b) = (p.dt - m.dt) / (2 * h);
      dtau_fd.col(b) = (p.tangent - m.tangent) / (2 * h);
    }
    const auto rel = [](const auto& a, const auto& f) { return (a - f).cwiseAbs().maxCoeff() / f.cwiseAbs().maxCoeff(); };
    EXPECT_LT(rel(pg.dg_row, dg_fd), 1e-6);
    EXPECT_LT(rel(pg.d2g, d2g_fd), 1e-6);
    EXPECT_LT(rel(pg.ddt, ddt_fd), 1e-6);
    EXPECT_LT(rel(pg.dtau, dtau_fd), 1e-6);
    std::printf("point t = %+.3f: dg_row %.2g, d2g %.2g, ddt %.2g, dtau %.2g\n", cp.t, rel(pg.dg_row, dg_fd),
                rel(pg.d2g, d2g_fd), rel(pg.ddt, ddt_fd), rel(pg.dtau, dtau_fd));
    // the force direction: n̄ N_k on the point's modes (and −n̄ N_k(ξ) on the foot's), not ∂g/∂u
    for (size_t k = 0; k < cp.modes.size(); ++k)
      for (int c = 0; c < 2; ++c) EXPECT_DOUBLE_EQ(pg.dg(2 * k + c), cp.N(k) * pg.normal(c));
    angle = std::max(angle, std::acos(std::clamp(-pg.normal.dot(Vec2(0, -1)), -1.0, 1.0)));
    ++checked;
  }
  EXPECT_GE(checked, 6);
  std::printf("largest tilt of the mean normal %.3g rad\n", angle);
  EXPECT_GT(angle, 0.02);
}
