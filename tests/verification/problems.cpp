// Construction of the verification problems.
#include "problems.hpp"

#include <algorithm>
#include <cmath>

#include "hpcontact/fem/edge_load.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::test_problems {

model::BodySpec body(const std::string& name, double E, double nu) {
  model::BodySpec b;
  b.name = name;
  b.material.youngs_modulus = E;
  b.material.poisson_ratio = nu;
  return b;
}

void add_node(model::BodySpec& b, int id, double x, double y) {
  b.node_ids.push_back(id);
  b.nodes.push_back({x, y});
}

void add_element(model::BodySpec& b, int id, int n1, int n2, int n3, int n4) {
  b.element_ids.push_back(id);
  b.elements.push_back({n1, n2, n3, n4});
}

void add_edge_set(model::BodySpec& b, const std::string& name, std::vector<std::array<int, 2>> edges) {
  model::EdgeSetSpec s;
  s.name = name;
  s.edges = std::move(edges);
  b.edge_sets.push_back(s);
}

void start_element_at(model::BodySpec& b, int element_id, int node_id) {
  const auto e = std::find(b.element_ids.begin(), b.element_ids.end(), element_id);
  auto& nodes = b.elements.at(e - b.element_ids.begin());
  const auto first = std::find(nodes.begin(), nodes.end(), node_id);
  std::rotate(nodes.begin(), first, nodes.end());
}

model::ProblemSpec distorted_patch(int p) {
  model::ProblemSpec spec;
  spec.file = "distorted-patch";
  spec.case_name = "distorted-patch";
  auto b = body("patch", 1000.0, 0.25);
  //  7 --- 8 --- 9
  //  |     |     |
  //  4 --- 5 --- 6
  //  |     |     |
  //  1 --- 2 --- 3
  add_node(b, 1, 0, 0);
  add_node(b, 2, 0.9, 0);
  add_node(b, 3, 2, 0);
  add_node(b, 4, 0, 1.1);
  add_node(b, 5, 1.2, 0.75);
  add_node(b, 6, 2, 0.8);
  add_node(b, 7, 0, 2);
  add_node(b, 8, 1.3, 2);
  add_node(b, 9, 2, 2);
  add_element(b, 1, 1, 2, 5, 4);
  add_element(b, 2, 2, 3, 6, 5);
  add_element(b, 3, 4, 5, 8, 7);
  add_element(b, 4, 5, 6, 9, 8);
  add_edge_set(b, "bottom", {{1, 2}, {2, 3}});
  add_edge_set(b, "right", {{3, 6}, {6, 9}});
  add_edge_set(b, "top", {{9, 8}, {8, 7}});
  add_edge_set(b, "left", {{7, 4}, {4, 1}});
  add_edge_set(b, "boundary",
               {{1, 2}, {2, 3}, {3, 6}, {6, 9}, {9, 8}, {8, 7}, {7, 4}, {4, 1}});
  spec.bodies.push_back(b);
  spec.discretization.degree = {p, p};
  return spec;
}

void hold_as_bar(model::BodySpec& b, double tx, double ty) {
  model::ConstraintSpec left;
  left.edge_sets = {"left"};
  left.ux = "0";
  model::ConstraintSpec pin;
  pin.nodes = {1};
  pin.uy = "0";
  b.constraints = {left, pin};
  model::EdgeLoadSpec load;
  load.edge_sets = {"right"};
  load.kind = model::LoadKind::traction;
  load.value = {tx, ty};
  b.edge_loads = {load};
}

model::ProblemSpec quarter_circle_2x2(int p) {
  const double R = 10.0;
  auto on_arc = [&](double alpha_deg) {
    const double a = alpha_deg * M_PI / 180.0;
    return std::array<double, 2>{R * std::sin(a), R - R * std::cos(a)};
  };
  const double alpha_A = std::asin(2.48 / R) * 180.0 / M_PI;
  model::ProblemSpec spec;
  spec.file = "quarter-circle";
  spec.case_name = "quarter-circle-2x2";
  auto b = body("cylinder", 210000.0, 0.3);
  //  centre line y = R:  7 (0,R) --- 8 --- 9 (R,R)
  //  symmetry x = 0:     4 ---------- 5 ---- 6 (arc)
  //                      1 (0,0) ---- 2=A -- 3 (arc)
  const auto A = on_arc(alpha_A), a3 = on_arc(40.0), a6 = on_arc(65.0);
  add_node(b, 1, 0.0, 0.0);
  add_node(b, 2, A[0], A[1]);
  add_node(b, 3, a3[0], a3[1]);
  add_node(b, 4, 0.0, 4.0);
  add_node(b, 5, 3.6, 4.6);
  add_node(b, 6, a6[0], a6[1]);
  add_node(b, 7, 0.0, R);
  add_node(b, 8, 5.0, R);
  add_node(b, 9, R, R);
  add_element(b, 1, 1, 2, 5, 4);
  add_element(b, 2, 2, 3, 6, 5);
  add_element(b, 3, 4, 5, 8, 7);
  add_element(b, 4, 5, 6, 9, 8);
  for (auto [a, c] : std::vector<std::array<int, 2>>{{1, 2}, {2, 3}, {3, 6}, {6, 9}}) {
    model::CurveSpec cs;
    cs.node_a = a;
    cs.node_b = c;
    cs.kind = model::CurveKind::arc;
    cs.center = {0.0, R};
    cs.radius = R;
    b.curves.push_back(cs);
  }
  add_edge_set(b, "symmetry", {{1, 4}, {4, 7}});
  add_edge_set(b, "centre", {{7, 8}, {8, 9}});
  add_edge_set(b, "arc", {{1, 2}, {2, 3}, {3, 6}, {6, 9}});
  model::ConstraintSpec sym;
  sym.edge_sets = {"symmetry"};
  sym.ux = "0";
  model::ConstraintSpec top;
  top.edge_sets = {"centre"};
  top.uy = "-0.01";
  b.constraints = {sym, top};
  spec.bodies.push_back(b);
  spec.discretization.degree = {p, p};
  return spec;
}

model::ProblemSpec quarter_circle_2x2_loaded(int p) {
  auto spec = quarter_circle_2x2(p);
  auto& b = spec.bodies[0];
  start_element_at(b, 4, 9);  // element 4, was (5, 6, 9, 8): (9, 8, 5, 6)
  add_edge_set(b, "zone", {{1, 2}});
  model::EdgeLoadSpec load;
  load.edge_sets = {"zone"};
  load.kind = model::LoadKind::pressure;
  load.value = {500, 0};
  b.edge_loads = {load};
  b.body_force = {300, -200};
  return spec;
}

}  // namespace hpcontact::test_problems

namespace hpcontact::test_problems {

model::ProblemSpec lame_quarter(int n_r, int n_theta) {
  const double a = 10, b = 20;
  model::ProblemSpec spec;
  spec.file = "lame-quarter";
  spec.case_name = "lame-quarter";
  auto bs = body("cylinder", 200000.0, 0.3);
  auto id = [&](int i, int j) { return 1 + j * (n_r + 1) + i; };  // i radial, j angular
  for (int j = 0; j <= n_theta; ++j)
    for (int i = 0; i <= n_r; ++i) {
      const double r = a + (b - a) * i / n_r, t = 0.5 * M_PI * j / n_theta;
      add_node(bs, id(i, j), r * std::cos(t), r * std::sin(t));
    }
  int e = 1;
  for (int j = 0; j < n_theta; ++j)
    for (int i = 0; i < n_r; ++i) add_element(bs, e++, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  std::vector<std::array<int, 2>> inner, bottom, left;
  for (int j = 0; j <= n_theta; ++j)
    for (int i = 0; i <= n_r; ++i) {
      if (j < n_theta) {
        model::CurveSpec c;
        c.node_a = id(i, j);
        c.node_b = id(i, j + 1);
        c.radius = a + (b - a) * i / n_r;
        bs.curves.push_back(c);
        if (i == 0) inner.push_back({id(0, j), id(0, j + 1)});
      }
    }
  for (int i = 0; i < n_r; ++i) {
    bottom.push_back({id(i, 0), id(i + 1, 0)});
    left.push_back({id(i, n_theta), id(i + 1, n_theta)});
  }
  add_edge_set(bs, "inner", inner);
  add_edge_set(bs, "bottom", bottom);
  add_edge_set(bs, "left", left);
  model::ConstraintSpec c1, c2;
  c1.edge_sets = {"bottom"};
  c1.uy = "0";
  c2.edge_sets = {"left"};
  c2.ux = "0";
  bs.constraints = {c1, c2};
  model::EdgeLoadSpec load;
  load.edge_sets = {"inner"};
  load.value = {100.0, 0.0};
  bs.edge_loads = {load};
  spec.bodies.push_back(bs);
  spec.exact.type = "lame";
  spec.exact.inner_radius = a;
  spec.exact.outer_radius = b;
  spec.exact.inner_pressure = 100;
  return spec;
}

}  // namespace hpcontact::test_problems

namespace hpcontact::test_problems {

Vec2 edge_displacement(const model::Body& body, int q, int le, double t, const Eigen::VectorXd& u) {
  const auto& es = body.dofs.element(q);
  Eigen::VectorXd N(es.n_modes());
  const auto r = fem::edge_reference_point(le, t);
  es.evaluate(r[0], r[1], N.data(), nullptr, nullptr);
  Vec2 v = Vec2::Zero();
  for (int a = 0; a < es.n_modes(); ++a) {
    const int dof = body.dof_offset + 2 * es.modes[a];
    v += N(a) * Vec2(u(dof), u(dof + 1));
  }
  return v;
}

double tangent_mismatch(const model::ProblemSpec& spec, const model::Discretization& d,
                        const model::NonlinearSolution& sol, double* asymmetry) {
  const Eigen::MatrixXd Ka = model::contact_tangent(spec, d, sol, false);
  const Eigen::MatrixXd Kd = model::residual_jacobian_by_differences(spec, d, sol);
  const double scale = Ka.cwiseAbs().maxCoeff();
  if (asymmetry) *asymmetry = (Ka - Ka.transpose()).cwiseAbs().maxCoeff() / scale;
  return (Ka - Kd).cwiseAbs().maxCoeff() / scale;
}

}  // namespace hpcontact::test_problems
