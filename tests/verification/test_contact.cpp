// Penalty contact against a rigid obstacle: the Hertz examples, condensation, the analytic tangent.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "hpcontact/contact/penalty.hpp"
#include "hpcontact/driver/run.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/post/fields.hpp"

using namespace hpcontact;

namespace {
std::string example(const std::string& name) {
  return std::string(HPC_SOURCE_DIR) + "/examples/hertz/" + name;
}
}  // namespace

// The Hertz examples run as they are: 220, 544 and 1860 free unknowns, Newton converges, and
// force control finds the displacement whose contact resultant is F/2 = 35000 N (within 0.1 %;
// the secant iteration's own tolerance is 1e-9), and the gap closed at every active node.
TEST(HertzExamples, DofsAndResultant) {
  for (auto [name, dofs] : {std::pair{"p5.yaml", 220}, std::pair{"p8.yaml", 544},
                            std::pair{"p15.yaml", 1860}}) {
    const auto spec = io::read_problem(example(name));
    const auto s = driver::run_problem(spec, {}).summary;
    EXPECT_TRUE(s.converged);
    EXPECT_EQ(s.dofs, dofs) << name;
    const auto& c = s.extra.at("contact");
    EXPECT_NEAR(c.at("resultant")[1].get<double>(), 35000.0, 35.0) << name;
    EXPECT_NEAR(c.at("resultant")[0].get<double>(), 0.0, 1e-6) << name;
    // exact contact, collocated at the multiplier nodes: no penetration beyond round-off there
    EXPECT_GE(c.at("max_penetration").get<double>(), 0.0) << name;
    EXPECT_LT(c.at("max_penetration").get<double>(), 1e-12) << name;
    EXPECT_FALSE(c.at("gamma_star").empty());
  }
}

// Statically condensing the internal modes before Newton gives the same contact solution as
// Newton on all free unknowns (displacements within 1e-8 relative).
TEST(ContactSolve, CondensedEqualsFull) {
  for (const char* name : {"p5.yaml", "p8.yaml"}) {
    auto full = io::read_problem(example(name), {"discretization.condense=false"});
    auto cond = io::read_problem(example(name), {"discretization.condense=true"});
    const auto a = driver::run_problem(full, {});
    const auto b = driver::run_problem(cond, {});
    EXPECT_LT((a.u - b.u).norm(), 1e-8 * a.u.norm()) << name;
  }
}

namespace {

/// Max |K_analytic - K_fd| / max |K_analytic| for the penalty force of one contact pair at the
/// state u, by central differences of f_c with step h on the dofs of the contact boundary.
double tangent_mismatch(const model::Discretization& d, model::ContactPair pair,
                        const Eigen::VectorXd& u_global, double h) {
  const auto& body = d.bodies[pair.body];
  const int n = body.dofs.n_dofs();
  const Eigen::VectorXd u = u_global.segment(body.dof_offset, n);
  // Points within 1e-5 of the contact switch (g = 0) would change state under the differences:
  // the force is not differentiable there, so they are left out of the comparison.
  {
    std::vector<contact::PointState> states;
    Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
    contact::penalty_contact(pair.points, *pair.obstacle, pair.penalty, u, f, nullptr, 0, &states);
    std::vector<contact::ContactPoint> kept;
    for (size_t i = 0; i < states.size(); ++i)
      if (std::abs(states[i].gap) > 1e-5) kept.push_back(pair.points[i]);
    pair.points = kept;
  }
  std::vector<Eigen::Triplet<double>> t;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  contact::penalty_contact(pair.points, *pair.obstacle, pair.penalty, u, f, &t, 0, nullptr);
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(t.begin(), t.end());
  const Eigen::MatrixXd Ka = Eigen::MatrixXd(K);
  std::vector<int> dofs;
  for (const auto& cp : pair.points)
    for (int m : cp.modes) dofs.push_back(2 * m), dofs.push_back(2 * m + 1);
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  double diff = 0;
  for (int j : dofs) {
    Eigen::VectorXd up = u, um = u, fp = Eigen::VectorXd::Zero(n), fm = Eigen::VectorXd::Zero(n);
    up(j) += h;
    um(j) -= h;
    contact::penalty_contact(pair.points, *pair.obstacle, pair.penalty, up, fp, nullptr, 0, nullptr);
    contact::penalty_contact(pair.points, *pair.obstacle, pair.penalty, um, fm, nullptr, 0, nullptr);
    // K is the derivative of -f_c.
    const Eigen::VectorXd col = -(fp - fm) / (2 * h);
    for (int i : dofs) diff = std::max(diff, std::abs(col(i) - Ka(i, j)));
  }
  return diff / Ka.cwiseAbs().maxCoeff();
}

}  // namespace

// The analytic contact tangent equals the central finite-difference tangent of the contact force
// on a converged Hertz state (relative difference < 1e-8, the accuracy of the differences), for the plane and for a rigid circle,
// whose curvature term (g dn/dx) the analytic tangent includes.
TEST(ContactTangent, AnalyticEqualsFiniteDifference) {
  const auto spec = io::read_problem(example("p5.yaml"), {"contact[0].enforcement=penalty"});
  const auto result = driver::run_problem(spec, {});
  const auto& d = result.discretization;
  auto pairs = model::make_contact_pairs(spec, d);
  ASSERT_EQ(pairs.size(), 1u);
  // Step 1e-6: the round-off of the gap (~1e-14 at coordinates ~50) stays far below it.
  const double plane = tangent_mismatch(d, pairs[0], result.u, 1e-6);
  RecordProperty("mismatch_plane", std::to_string(plane));
  EXPECT_LT(plane, 1e-8);

  auto circle_spec = spec;
  circle_spec.contact[0].obstacle.kind = model::ObstacleKind::circle;
  circle_spec.contact[0].obstacle.center = {0.0, -50.0};
  circle_spec.contact[0].obstacle.radius = 50.0;
  auto circle_pairs = model::make_contact_pairs(circle_spec, d);
  const double circle = tangent_mismatch(d, circle_pairs[0], result.u, 1e-6);
  RecordProperty("mismatch_circle", std::to_string(circle));
  EXPECT_LT(circle, 1e-8);

  // A general rigid curve (a spline through points of y = -0.0005 x² + 0.00002 x³, whose
  // curvature changes along the contact zone): the foot of the closest point moves with x.
  auto curve_spec = spec;
  curve_spec.contact[0].obstacle.kind = model::ObstacleKind::curve;
  for (int i = 0; i <= 40; ++i) {
    const double x = -5.0 + 0.5 * i;
    curve_spec.contact[0].obstacle.points.push_back({x, -0.0005 * x * x + 0.00002 * x * x * x});
  }
  auto curve_pairs = model::make_contact_pairs(curve_spec, d);
  const double curve = tangent_mismatch(d, curve_pairs[0], result.u, 1e-6);
  RecordProperty("mismatch_curve", std::to_string(curve));
  EXPECT_LT(curve, 1e-8);

  // A profile whose concave corner 0.1 above the cylinder's bottom (a V of slopes ±0.06, about as
  // deep as the undeformed body may start inside an obstacle) is rounded by a fillet of radius 10:
  // penetrating points on the arc, whose normal turns with them (dn/dx = −(I − e eᵀ)/|x − c|).
  // (A sharp corner's fan beyond it is too narrow here to hold a point: its dn/dx is checked in
  // tests/unit/contact/test_rigid_profile.cpp.)
  {
    const double fillet = 10;
    auto profile_spec = spec;
    auto& o = profile_spec.contact[0].obstacle;
    o.kind = model::ObstacleKind::profile;
    o.points = {{-10.0, 0.1 + 0.06 * 10.3}, {0.3, 0.1}, {10.0, 0.1 + 0.06 * 9.7}};
    o.fillets = {fillet};
    auto profile_pairs = model::make_contact_pairs(profile_spec, d);
    // Penetrating points whose foot is on the arc: what this case checks.
    const auto& profile = dynamic_cast<const contact::RigidProfile&>(*profile_pairs[0].obstacle).profile();
    const Eigen::VectorXd u = result.u.segment(d.bodies[0].dof_offset, d.bodies[0].dofs.n_dofs());
    int turning = 0;
    for (const auto& cp : profile_pairs[0].points) {
      Vec2 x = cp.X;
      for (size_t k = 0; k < cp.modes.size(); ++k)
        x += cp.N(k) * Vec2(u(2 * cp.modes[k]), u(2 * cp.modes[k] + 1));
      const auto foot = profile.closest(x);
      if (profile.pieces()[foot.piece].arc && profile_pairs[0].obstacle->gap(x, nullptr, nullptr) < -1e-5) ++turning;
    }
    EXPECT_GE(turning, 3);
    const double mismatch = tangent_mismatch(d, profile_pairs[0], result.u, 1e-6);
    std::printf("profile's fillet: %d penetrating points on it, tangent mismatch %.3g\n", turning, mismatch);
    RecordProperty("mismatch_profile_arc", std::to_string(mismatch));
    EXPECT_LT(mismatch, 1e-8);
  }
}

// A rigid curve through points of the plane y = 0 (a straight spline) is that plane: the Hertz
// p8 solution is the same to round-off; through points of a circle of radius 50 below the
// cylinder it approaches the exact circle as the points get denser: the difference in
// displacement falls at least 6 times per halving of the point spacing (measured: 8.2 and 9.3
// from 8 to 16 to 32 intervals over 100°; the spline's position error alone falls like h^4).
TEST(ContactSolve, RigidCurveObstacleEqualsPlaneAndCircle) {
  using model::ObstacleKind;
  const auto plane = io::read_problem(example("p8.yaml"));
  auto line = plane;
  line.contact[0].obstacle.kind = ObstacleKind::curve;
  line.contact[0].obstacle.points = {{-3.0, 0.0}, {1.0, 0.0}, {4.0, 0.0}, {12.0, 0.0}};
  const auto a = driver::run_problem(plane, {});
  const auto b = driver::run_problem(line, {});
  ASSERT_TRUE(b.summary.converged);
  EXPECT_LT((a.u - b.u).norm(), 1e-10 * a.u.norm());

  auto disc = plane;
  disc.contact[0].obstacle.kind = ObstacleKind::circle;
  disc.contact[0].obstacle.center = {0.0, -50.0};
  disc.contact[0].obstacle.radius = 50.0;
  const auto exact = driver::run_problem(disc, {});
  ASSERT_TRUE(exact.summary.converged);
  double previous = 0;
  for (int n : {8, 16, 32}) {
    auto sampled = plane;
    sampled.contact[0].obstacle.kind = ObstacleKind::curve;
    // Clockwise over 100° about the top of the disc: the cylinder stays on the left.
    for (int i = 0; i <= n; ++i) {
      const double angle = (140.0 - 100.0 * i / n) * 3.14159265358979323846 / 180.0;
      sampled.contact[0].obstacle.points.push_back(
          {50.0 * std::cos(angle), -50.0 + 50.0 * std::sin(angle)});
    }
    const auto r = driver::run_problem(sampled, {});
    ASSERT_TRUE(r.summary.converged) << n;
    const double difference = (r.u - exact.u).norm() / exact.u.norm();
    std::printf("circle through %d + 1 points: |u - u_circle| / |u_circle| = %.3g\n", n, difference);
    if (previous > 0) EXPECT_LT(difference, previous / 6) << n;
    previous = difference;
  }
  EXPECT_LT(previous, 5e-6);
}

namespace {

/// max |K_analytic − K_difference| / max |K| on the converged state of `spec` (the residuals of
/// both the same), and the two tangents' sizes.
struct TangentComparison {
  double relative = 0;
  Eigen::Index rows = 0;
};
TangentComparison compare_tangents(const model::ProblemSpec& spec, const model::Discretization& d) {
  const auto sol = model::solve_contact(spec, d);
  EXPECT_TRUE(sol.converged) << sol.message;
  Eigen::VectorXd r_an, r_fd;
  const auto Ka = model::contact_tangent(spec, d, sol, false, &r_an);
  const auto Kf = model::contact_tangent(spec, d, sol, true, &r_fd);
  EXPECT_EQ((r_an - r_fd).norm(), 0.0);
  const double scale = Eigen::MatrixXd(Ka).cwiseAbs().maxCoeff();
  return {Eigen::MatrixXd(Ka - Kf).cwiseAbs().maxCoeff() / scale, Ka.rows()};
}

}  // namespace

// The seed's finite-difference tangent (central differences of the whole residual, normals of
// the undisturbed state, eq. 3.36) and the analytic tangent agree on a converged Hertz state:
// against a rigid plane the contact force is piecewise linear in u, so the differences are exact
// except at points changing state within the step and round-off of order 1e-16·|R|/h: max
// |difference| below 2e-8 of max |K| (measured 1.5e-9 and 1.2e-9).
TEST(ContactTangent, SeedFiniteDifferenceTangentEqualsAnalytic) {
  for (const char* name : {"p5.yaml", "p8.yaml"}) {
    const auto spec = io::read_problem(example(name), {"contact[0].enforcement=penalty"});
    const auto d = model::discretize(spec);
    const auto c = compare_tangents(spec, d);
    std::printf("%s: max |K_analytic - K_fd| / max |K| = %.3g\n", name, c.relative);
    EXPECT_LT(c.relative, 2e-8) << name;
  }
}

// With exact contact the seed's difference tangent is the whole saddle-point system's: its
// displacement block symmetrised, the multipliers' rows and columns (and the bordered force's)
// as differenced. On a converged Hertz state it equals the analytic one to 5e-8 of max |K|
// (measured 1.3e-8 and 2.1e-8, the differences' round-off: the multiplier rows are linear in the
// unknowns, the gap to a plane linear in u). Averaging the whole system with its transpose mixed
// an inactive multiplier's row (the multiplier) with its column (the constraint): Newton then
// cycled between two residuals, no node ever active.
TEST(ContactTangent, SeedFiniteDifferenceTangentEqualsAnalyticWithMultipliers) {
  for (const char* name : {"p5.yaml", "p8.yaml"}) {
    const auto spec = io::read_problem(example(name));
    ASSERT_EQ(spec.contact[0].enforcement, model::Enforcement::augmented_lagrangian);
    const auto d = model::discretize(spec);
    const auto c = compare_tangents(spec, d);
    ASSERT_GT(c.rows, d.n_free_external) << "the multipliers are unknowns of the system";
    std::printf("%s, exact contact: max |K_analytic - K_fd| / max |K| = %.3g\n", name, c.relative);
    EXPECT_LT(c.relative, 5e-8) << name;
  }
}

// Newton with the seed's finite-difference tangent reaches the same solution as with the
// analytic one (the residual is the same; only the path differs): displacements within 1e-8,
// with the penalty and with exact contact (multipliers), under force control (p8.yaml).
TEST(ContactTangent, FiniteDifferenceTangentGivesTheSameSolution) {
  for (const char* name : {"p5.yaml", "p8.yaml"})
    for (const std::string enforcement : {"penalty", "augmented-lagrangian"}) {
      const std::string set = "contact[0].enforcement=" + enforcement;
      const auto an = io::read_problem(example(name), {set});
      const auto fd = io::read_problem(example(name), {set, "solver.tangent=finite-difference"});
      const auto a = driver::run_problem(an, {});
      const auto b = driver::run_problem(fd, {});
      ASSERT_TRUE(b.summary.converged) << name << ", " << enforcement;
      EXPECT_LT((a.u - b.u).norm(), 1e-8 * a.u.norm()) << name << ", " << enforcement;
    }
}

// Clapeyron's theorem: the strain energy of a converged Hertz solution (p = 8 and 15, force
// control) shall equal half the work of the forces on the body, U = ½ (P v + Σ_j W_j λ_j u_y,j):
// the centre line's reaction −P (vertical equilibrium with the contact resultant P) on its
// displacement −v, and the plane's pressure λ_j at multiplier node j (weight W_j; exact contact
// collocated at the nodes) on that node's displacement u_y,j; the symmetry line's reaction does
// no work (ux = 0 there). Forces and
// displacements only, not the stresses the energy integrates: to 1e-12 relative (measured
// 2e-14; the same quadratures on both sides). This checks the energies the convergence study
// extrapolates its U_ref from (tests/cli/test_convergence_study.py).
TEST(ContactSolve, StrainEnergyIsHalfTheWorkOfTheForces) {
  for (const char* name : {"p8.yaml", "p15.yaml"}) {
    const auto spec = io::read_problem(example(name));
    const auto d = model::discretize(spec);
    const auto sol = model::solve_contact(spec, d);
    ASSERT_TRUE(sol.converged) << sol.message;
    const auto& body = d.bodies[0];
    const auto& pair = sol.pairs.front();
    const auto r = model::evaluate_contact(d, pair, sol.u, sol.multipliers_of(0));
    // The forces on the body: exact contact (collocation on the plane) W_j λ_j at its nodes,
    // the penalty w_i p_i at its Gauss points.
    ASSERT_TRUE(pair.constraints);
    double P = 0, contact_work = 0;
    for (size_t i = 0; i < r.states.size(); ++i) {
      const double w = pair.constraints->weight(static_cast<int>(i)), p = r.states[i].pressure;
      P += w * p;
      contact_work += w * p * (r.states[i].x.y() - r.X[i].y());
    }
    const int centre = body.dof_offset + 2 * body.dofs.vertex_mode(body.mesh.node_index(7)) + 1;
    const double v = -sol.u(centre);
    const double U = post::strain_energy(d, sol.u), clapeyron = 0.5 * (P * v + contact_work);
    std::printf("%s: U = %.10g, ½ (P v + Σ w p u_y) = %.10g, relative difference %.2g\n", name, U,
                clapeyron, std::abs(U / clapeyron - 1));
    EXPECT_NEAR(P, 35000, 1e-6 * 35000) << name;
    EXPECT_NEAR(U, clapeyron, 1e-12 * U) << name;
  }
}
