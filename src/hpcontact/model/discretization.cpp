// Discretisation of a problem: geometry, spaces, prescribed values (with projection onto edge
// modes) and the external load vector.
#include "hpcontact/model/discretization.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <tuple>

#include "hpcontact/basis/legendre.hpp"
#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/contact/contact_boundary.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/fem/edge_load.hpp"
#include "hpcontact/fem/elasticity.hpp"
#include "hpcontact/fem/mixed_finite_strain.hpp"
#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/mesh/element_shape.hpp"
#include "hpcontact/model/axis.hpp"
#include "hpcontact/model/edge_interpolant.hpp"
#include "hpcontact/model/expression.hpp"
#include "hpcontact/model/rigid_motion.hpp"

namespace hpcontact::model {

namespace {

std::string body_context(const ProblemSpec& spec, int b) {
  return spec.file + ": bodies[" + std::to_string(b) + "] (" + spec.bodies[b].name + ")";
}

geometry::CurvePtr make_curve(const CurveSpec& c, const Vec2& a, const Vec2& b) {
  const std::string where = c.where.str();
  if (c.kind == CurveKind::arc)
    return geometry::arc_through(a, b, Vec2(c.center[0], c.center[1]), c.radius, c.ccw, where);
  auto fx = std::make_shared<Expression>(c.x_expr, std::vector<std::string>{"s"}, where + ".x");
  auto fy = std::make_shared<Expression>(c.y_expr, std::vector<std::string>{"s"}, where + ".y");
  auto curve = std::make_shared<geometry::FunctionCurve>(
      [fx, fy](double s) { return Vec2((*fx)(s), (*fy)(s)); }, nullptr,
      "parametric(" + c.x_expr + ", " + c.y_expr + ")");
  // Its ends must be its nodes (as an arc's nodes must be on its circle): the node is moved
  // onto the end only by the round-off of the node's digits.
  const double tol = 1e-6 * (b - a).norm();
  for (const auto& [s, node, id] : {std::tuple{0.0, a, c.node_a}, std::tuple{1.0, b, c.node_b}}) {
    const Vec2 end = curve->point(s);
    HPC_REQUIRE((end - node).norm() <= tol, InputError, where, ": the curve's end at s = ", s,
                " is (", end.x(), ", ", end.y(), "), ", (end - node).norm(), " away from its node ",
                id, " at (", node.x(), ", ", node.y(),
                "): a curve must end at its nodes (to 1e-6 of the distance between them)");
  }
  return curve;
}

/// The law of an input model name (the schema admits only these).
material::Law law_of(const MaterialSpec& m) {
  for (auto law : {material::Law::saint_venant_kirchhoff, material::Law::neo_hooke,
                   material::Law::neo_hooke_split, material::Law::mooney_rivlin, material::Law::yeoh})
    if (m.model == material::law_name(law)) return law;
  return material::Law::linear;
}

Body make_body(const ProblemSpec& spec, int b) {
  const BodySpec& bs = spec.bodies[b];
  const std::string ctx = body_context(spec, b);
  std::vector<Vec2> xy;
  for (const auto& p : bs.nodes) xy.emplace_back(p[0], p[1]);
  std::unordered_map<int, int> index;
  for (size_t i = 0; i < bs.node_ids.size(); ++i) index[bs.node_ids[i]] = static_cast<int>(i);
  auto node = [&](int id, const SourceRef& where) {
    auto it = index.find(id);
    HPC_REQUIRE(it != index.end(), InputError, where.str(), ": node ", id, " does not exist");
    return it->second;
  };
  std::vector<std::array<int, 4>> quads;
  for (const auto& e : bs.elements) {
    std::array<int, 4> q;
    for (int k = 0; k < 4; ++k) q[k] = node(e[k], bs.where);
    quads.push_back(q);
  }
  std::vector<mesh::EdgeCurve> curves;
  for (const auto& c : bs.curves) {
    const int a = node(c.node_a, c.where), bb = node(c.node_b, c.where);
    curves.push_back({a, bb, make_curve(c, xy[a], xy[bb])});
    // Nodes given to a few digits lie slightly off their circle (arc_through accepts 1e-6·r):
    // they are moved onto the exact curve so that the geometry is exact.
    xy[a] = curves.back().curve->point(0.0);
    xy[bb] = curves.back().curve->point(1.0);
  }
  if (bs.material.plane == PlaneMode::axisymmetric) snap_to_axis(xy);
  mesh::Mesh mesh(xy, bs.node_ids, quads, bs.element_ids, curves, ctx);

  const DiscretizationSpec& ds = spec.discretization;
  fem::SpaceOptions opt;
  opt.lagrange = ds.method == Method::h;
  opt.lagrange_type = ds.element == LagrangeElement::q4   ? basis::LagrangeType::q4
                      : ds.element == LagrangeElement::q8 ? basis::LagrangeType::q8
                                                          : basis::LagrangeType::q9;
  opt.space = ds.space == ShapeSpace::trunk ? basis::Space::trunk : basis::Space::tensor_product;
  for (int q = 0; q < mesh.n_quads(); ++q) {
    std::array<int, 2> p = bs.degree ? *bs.degree : ds.degree;
    if (auto it = bs.element_degrees.find(mesh.quad_id(q)); it != bs.element_degrees.end())
      p = it->second;
    opt.degrees.push_back(p);
  }
  fem::DofMap dofs(mesh, opt);
  for (int v = 0; v < mesh.n_nodes(); ++v)
    HPC_REQUIRE(dofs.vertex_mode(v) >= 0, InputError, bs.where.str(), ".nodes: node ",
                mesh.node_id(v), " is a corner of no element (remove it or use it in an element)");

  const material::Law law = law_of(bs.material);
  const auto plane = bs.material.plane == PlaneMode::plane_stress  ? material::Plane::stress
                     : bs.material.plane == PlaneMode::axisymmetric ? material::Plane::axisymmetric
                                                                    : material::Plane::strain;
  material::RubberConstants rubber;
  material::LinearElastic mat;
  mat.youngs_modulus = bs.material.youngs_modulus;
  mat.poisson_ratio = bs.material.poisson_ratio;
  mat.plane = plane;
  if (material::is_rubber(law)) {
    const double K = bs.material.incompressible ? std::numeric_limits<double>::infinity() : bs.material.K;
    rubber = {bs.material.C10, bs.material.C01, bs.material.C20, bs.material.C30, K};
    mat = rubber.small_strain(plane);
  }
  mat.validate(bs.material.where.str());

  Body body{bs.name, std::move(mesh), std::move(dofs), {}, {}, mat, bs.material.thickness, 0, {},
            law, rubber, {}, {}, {}, {}, false, 0, {}};
  body.mixed = bs.material.formulation == "mixed";
  body.inverse_bulk = 1 / rubber.K;  // 0 when incompressible
  if (!bs.regions.empty()) body.element_region.assign(body.mesh.n_quads(), -1);
  for (const auto& region : bs.regions) {
    material::LinearElastic rm = mat;
    rm.youngs_modulus = region.material.youngs_modulus;
    rm.poisson_ratio = region.material.poisson_ratio;
    rm.validate(region.material.where.str());
    for (int id : region.elements)
      body.element_region[body.mesh.quad_index(id)] = static_cast<int>(body.region_materials.size());
    body.region_materials.push_back(rm);
  }
  HPC_REQUIRE(law == material::Law::linear || law == material::Law::saint_venant_kirchhoff ||
                  mat.plane != material::Plane::stress,
              InputError, bs.material.where.str(), ".plane: ", bs.material.model,
              " is implemented in plane strain and axisymmetry only (use plane: strain, or "
              "saint-venant-kirchhoff in plane stress)");
  if (body.axisymmetric()) {
    for (int v = 0; v < body.mesh.n_nodes(); ++v)
      HPC_REQUIRE(body.mesh.node(v).x() >= 0, InputError, bs.where.str(), ".nodes: node ",
                  body.mesh.node_id(v), " lies at x = r = ", body.mesh.node(v).x(),
                  " < 0; an axisymmetric body is the meridian section r >= 0 (axis x = 0)");
  }
  for (int q = 0; q < body.mesh.n_quads(); ++q) {
    body.maps.push_back(opt.lagrange ? mesh::ElementMap::isoparametric(body.mesh, q, opt.lagrange_type)
                                     : mesh::ElementMap::blending(body.mesh, q));
    body.n_gauss.push_back(body.dofs.element(q).max_degree() + ds.quadrature_extra);
    HPC_REQUIRE(!body.mixed || fem::pressure_degree(body.dofs.element(q)) >= 1, InputError, bs.material.where.str(),
                ".formulation: mixed needs degree 2 or more, on its edges too (element ", body.mesh.quad_id(q),
                " has 1: its pressure would be one constant, Q1-P0, which locks or oscillates)");
    mesh::check_jacobian(body.maps[q], body.mesh, q, body.n_gauss[q]);
  }
  for (const auto& set : bs.edge_sets) {
    std::vector<int> edges;
    for (const auto& pair : set.edges) {
      const int e = body.mesh.find_edge(node(pair[0], set.where), node(pair[1], set.where));
      HPC_REQUIRE(e >= 0, InputError, set.where.str(), ": nodes ", pair[0], " and ", pair[1],
                  " are not joined by an element edge");
      edges.push_back(e);
    }
    body.edge_sets[set.name] = edges;
  }
  return body;
}

const std::vector<int>& edge_set(const Body& body, const std::string& name, const SourceRef& where) {
  auto it = body.edge_sets.find(name);
  HPC_REQUIRE(it != body.edge_sets.end(), InputError, where.str(), ": no edge set named '", name,
              "' in body '", body.name, "'");
  return it->second;
}

/// Prescribes component `comp` = g(x, y) on an edge: vertex values, and the edge modes by the L2
/// projection of g minus its linear interpolant onto phi_2..phi_p along the edge. Returns the
/// dofs it prescribed.
std::vector<int> prescribe_edge(const Body& body, int e, int comp, const Expression& g, Discretization& d) {
  std::vector<int> dofs;
  auto set = [&](int mode, double v) {
    const int dof = body.dof_offset + 2 * mode + comp;
    d.free_index[dof] = -1;
    d.prescribed(dof) = v;
    dofs.push_back(dof);
  };
  const auto& edge = body.mesh.edge(e);
  const Vec2 x0 = body.mesh.node(edge.v0), x1 = body.mesh.node(edge.v1);
  set(body.dofs.vertex_mode(edge.v0), g(x0.x(), x0.y()));
  set(body.dofs.vertex_mode(edge.v1), g(x1.x(), x1.y()));
  const int p = body.dofs.edge_degree(e);
  if (p < 2) return dofs;
  if (g.is_constant() && !body.dofs.lagrange()) {
    for (int k = 2; k <= p; ++k) set(body.dofs.edge_mode(e, k), 0.0);
    return dofs;
  }
  const auto a = edge_mode_values(body, e, [&](const Vec2& x) { return g(x.x(), x.y()); });
  for (int k = 2; k <= p; ++k) set(body.dofs.edge_mode(e, k), a[k - 2]);
  return dofs;
}

/// The radial dofs of an axisymmetric body's axis: the vertex modes of its nodes on the axis and
/// the edge modes of its edges along it, as (dof, node or edge) for messages; none otherwise.
std::vector<std::pair<int, std::string>> axis_radial_dofs(const Body& body) {
  std::vector<std::pair<int, std::string>> dofs;
  if (!body.axisymmetric()) return dofs;
  for (int v : axis_nodes(body.mesh))
    dofs.emplace_back(body.dof_offset + 2 * body.dofs.vertex_mode(v),
                      "node " + std::to_string(body.mesh.node_id(v)));
  for (int e = 0; e < body.mesh.n_edges(); ++e) {
    if (!edge_on_axis(body.mesh, e) || body.dofs.lagrange()) continue;
    const auto& edge = body.mesh.edge(e);
    for (int k = 2; k <= body.dofs.edge_degree(e); ++k)
      dofs.emplace_back(body.dof_offset + 2 * body.dofs.edge_mode(e, k),
                        "edge " + std::to_string(body.mesh.node_id(edge.v0)) + "-" +
                            std::to_string(body.mesh.node_id(edge.v1)));
  }
  return dofs;
}

/// Prescribes a body's constraints; returns per constraint entry the dofs it holds (a dof that
/// two entries prescribe is held by the first listed: its reaction is that entry's; the value
/// prescribed is the last's).
std::vector<std::vector<int>> apply_constraints(const BodySpec& bs, const Body& body, Discretization& d) {
  const auto axis = axis_radial_dofs(body);
  std::vector<std::vector<int>> held(bs.constraints.size());
  std::vector<char> taken(body.dofs.n_dofs(), 0);
  auto hold = [&](size_t entry, int dof) {
    if (taken[dof - body.dof_offset]) return;
    taken[dof - body.dof_offset] = 1;
    held[entry].push_back(dof);
  };
  for (size_t i = 0; i < bs.constraints.size(); ++i) {
    const auto& c = bs.constraints[i];
    const std::string where = c.where.str();
    for (int comp = 0; comp < 2; ++comp) {
      const auto& text = comp == 0 ? c.ux : c.uy;
      if (!text) continue;
      const Expression g(*text, {"x", "y"}, where + (comp == 0 ? ".ux" : ".uy"));
      for (const auto& name : c.edge_sets)
        for (int e : edge_set(body, name, c.where))
          for (int dof : prescribe_edge(body, e, comp, g, d)) hold(i, dof);
      for (int id : c.nodes) {
        const int v = body.mesh.node_index(id);
        HPC_REQUIRE(v >= 0, InputError, where, ".nodes: node ", id, " does not exist");
        const int dof = body.dof_offset + 2 * body.dofs.vertex_mode(v) + comp;
        d.free_index[dof] = -1;
        d.prescribed(dof) = g(body.mesh.node(v).x(), body.mesh.node(v).y());
        hold(i, dof);
      }
      // The axis cannot move radially: it would open a hole, or pass through itself.
      if (comp == 0)
        for (const auto& [dof, what] : axis)
          HPC_REQUIRE(d.free_index[dof] != -1 || d.prescribed(dof) == 0, InputError, where,
                      ".ux: prescribes u_r = ", d.prescribed(dof), " at ", what, " of body '",
                      body.name, "' on the axis r = 0 of an axisymmetric body, where only u_r = 0 "
                      "is a solid of revolution (a point of the axis moved radially would open a "
                      "hole or pass through itself)");
    }
  }
  return held;
}

/// A warning for an axisymmetric body whose nodes on the axis are free to move radially: the
/// hoop strain u_r / r is unbounded there unless u_r = 0, so the discrete solution's u_r there
/// is a discretisation error (it goes to 0 with refinement, slowly).
std::optional<std::string> axis_left_free(const ProblemSpec& spec, int b, const Body& body,
                                          const Discretization& d) {
  std::vector<int> free;
  for (int v : axis_nodes(body.mesh))
    if (d.free_index[body.dof_offset + 2 * body.dofs.vertex_mode(v)] != -1)
      free.push_back(body.mesh.node_id(v));
  if (free.empty() || !body.axisymmetric()) return std::nullopt;
  std::ostringstream os;
  os << body_context(spec, b) << ": " << free.size() << " node(s) on the axis r = 0 (";
  for (size_t i = 0; i < free.size() && i < 8; ++i) os << (i ? ", " : "") << free[i];
  if (free.size() > 8) os << ", ...";
  os << ") may move radially: u_r = 0 there is what a solid of revolution needs (the hoop strain "
        "u_r / r is unbounded otherwise); add a constraint {edges: [the axis' edges], ux: 0}";
  return os.str();
}

double load_shape(LoadShape shape, double t) {
  switch (shape) {
    case LoadShape::constant: return 1.0;
    case LoadShape::linear: return 1.0 - t;
    case LoadShape::bspline1: return (1 - t) * (1 - t);
    // The right half of the uniform quadratic B-spline, from its peak to zero (eq. 4.9, scaled).
    case LoadShape::bspline2: return t <= 1.0 / 3 ? 1 - 3 * t * t : 1.5 * (1 - t) * (1 - t);
    case LoadShape::hermite: return 1 - 3 * t * t + 2 * t * t * t;
    case LoadShape::expression: return 1.0;
  }
  return 1.0;
}

/// Integrates a distributed load over the loaded part of its edges. The integration on an edge
/// is split where the load's interval starts or ends, so a load ending inside an element edge is
/// integrated exactly (to quadrature accuracy) on both sides.
/// A follower load's edges in the order of their chain (its start at the end edge the sets list
/// first), each with its break points; with penetration they must be one open chain.
template <class Pieces>
FollowerLoad follower_load(const EdgeLoadSpec& ls, const Body& body, int body_index, const Pieces& pieces) {
  FollowerLoad L;
  L.body = body_index;
  L.where = ls.where.str();
  L.dead = !body.finite_strain();
  if (ls.penetration) L.penetration = Penetration{ls.penetration->contact, ls.penetration->from_end};
  std::vector<int> edges;
  for (const auto& name : ls.edge_sets)
    for (int e : edge_set(body, name, ls.where)) edges.push_back(e);
  auto chain = contact::chain_edges(body.mesh, edges);
  const bool one_open_chain =
      !chain.empty() && !chain.back().closes &&
      std::all_of(chain.begin() + 1, chain.end(), [](const contact::ChainEdge& c) { return c.continues; });
  HPC_REQUIRE(!ls.penetration || one_open_chain, InputError, ls.where.str(),
              ".penetration: the loaded edges must form one open chain (a path with two ends), so "
              "that the pressure runs from one end up to the contact (got ",
              chain.empty() ? std::string("no edges")
                            : chain.back().closes ? std::string("a closed loop") : std::string("several chains"),
              ")");
  const auto listed = [&](int e) { return std::find(edges.begin(), edges.end(), e) - edges.begin(); };
  if (chain.size() > 1 && listed(chain.back().edge) < listed(chain.front().edge)) {
    std::reverse(chain.begin(), chain.end());
    for (auto& c : chain) {
      std::swap(c.start, c.end);
      c.against = !c.against;
    }
  }
  for (const auto& c : chain) {
    const auto& edge = body.mesh.edge(c.edge);
    FollowerEdge fe;
    fe.q = edge.quads[0];
    fe.le = edge.local_edge[0];
    fe.mesh_edge = c.edge;
    fe.against = c.against;
    fe.breaks = pieces(fe.q, fe.le);
    L.edges.push_back(std::move(fe));
  }
  return L;
}

void apply_edge_load(const EdgeLoadSpec& ls, const Body& body, int body_index, Discretization& d) {
  const std::string where = ls.where.str();
  const int axis = ls.along == 'y' ? 1 : 0;
  std::shared_ptr<Expression> expr;
  if (ls.shape == LoadShape::expression)
    expr = std::make_shared<Expression>(ls.expression, std::vector<std::string>{"x", "y"},
                                        where + ".expression");
  // The loaded edges, each as (element, local edge).
  std::vector<std::pair<int, int>> sides;
  for (const auto& name : ls.edge_sets) {
    for (int e : edge_set(body, name, ls.where)) {
      const auto& edge = body.mesh.edge(e);
      HPC_REQUIRE(edge.on_boundary(), InputError, where, ": edge ", body.mesh.node_id(edge.v0), "-",
                  body.mesh.node_id(edge.v1), " of set '", name, "' is not on the boundary");
      sides.emplace_back(edge.quads[0], edge.local_edge[0]);
    }
  }
  // The interval [a, b] of the coordinate along which the profile parameter t runs.
  double a, b;
  if (ls.interval) {
    a = (*ls.interval)[0];
    b = (*ls.interval)[1];
  } else {
    a = std::numeric_limits<double>::infinity();
    b = -a;
    for (auto [q, le] : sides)
      for (int i = 0; i <= 32; ++i) {
        const double c = fem::edge_geometry(body.maps[q], le, -1 + i / 16.0, nullptr, nullptr)(axis);
        a = std::min(a, c);
        b = std::max(b, c);
      }
  }
  const bool shaped = ls.shape != LoadShape::constant && ls.shape != LoadShape::expression;
  HPC_REQUIRE(!shaped || std::abs(b - a) > 0, InputError, where,
              ": the loaded edges have no extent along ", ls.along,
              "; give 'along' the other coordinate or an 'interval'");
  // by value: a follower load keeps it
  auto profile = [a, b, axis, expr, interval = ls.interval, shape = ls.shape](const Vec2& x) -> double {
    const double c = x(axis);
    const double lo = std::min(a, b), hi = std::max(a, b);
    if (interval && (c < lo - 1e-12 * (1 + std::abs(lo)) || c > hi + 1e-12 * (1 + std::abs(hi))))
      return 0.0;
    const double t = b != a ? std::clamp((c - a) / (b - a), 0.0, 1.0) : 0.0;
    return expr ? (*expr)(x.x(), x.y()) : load_shape(shape, t);
  };
  // Break points of each edge: where the coordinate crosses a or b, and the joint t = 1/3 of
  // the two-sided B-spline (its second derivative jumps there).
  std::vector<double> targets;
  if (ls.interval) targets = {a, b};
  if (ls.shape == LoadShape::bspline2) targets.push_back(a + (b - a) / 3);
  auto pieces = [&](int q, int le) {
    std::vector<double> ts{-1.0, 1.0};
    for (double target : targets) {
      auto f = [&](double t) {
        return fem::edge_geometry(body.maps[q], le, t, nullptr, nullptr)(axis) - target;
      };
      const int ns = 64;
      for (int i = 0; i < ns; ++i) {
        double t0 = -1 + 2.0 * i / ns, t1 = -1 + 2.0 * (i + 1) / ns, f0 = f(t0), f1 = f(t1);
        if (f0 == 0 && i > 0) ts.push_back(t0);  // a break point on a scan point
        if (f0 == 0 || f0 * f1 >= 0) continue;
        for (int it = 0; it < 60; ++it) {
          const double tm = 0.5 * (t0 + t1), fm = f(tm);
          (f0 * fm <= 0 ? t1 : t0) = tm;
          if (f0 * fm > 0) f0 = fm;
        }
        ts.push_back(0.5 * (t0 + t1));
      }
    }
    std::sort(ts.begin(), ts.end());
    return ts;
  };
  double scale = 1.0;
  const double magnitude =
      ls.kind == LoadKind::pressure ? std::abs(ls.value[0]) : Vec2(ls.value[0], ls.value[1]).norm();
  if (ls.resultant) {
    // ∫ |load| ds over the loaded part, per unit value (per unit thickness; axisymmetric: over
    // the whole surface of revolution, 2π r ds, the total force).
    double integral = 0;
    for (auto [q, le] : sides) {
      const auto ts = pieces(q, le);
      const auto& rule = basis::gauss_legendre(body.n_gauss[q] + 8);
      for (size_t k = 0; k + 1 < ts.size(); ++k)
        for (int i = 0; i < rule.size(); ++i) {
          const double t = 0.5 * (ts[k] + ts[k + 1]) + 0.5 * (ts[k + 1] - ts[k]) * rule.points[i];
          double ds;
          const Vec2 x = fem::edge_geometry(body.maps[q], le, t, nullptr, &ds);
          const double around = body.axisymmetric() ? body.out_of_plane().at(x) : 1.0;
          integral += 0.5 * (ts[k + 1] - ts[k]) * rule.weights[i] * ds * around * std::abs(profile(x));
        }
    }
    HPC_REQUIRE(integral * magnitude > 0, InputError, where,
                ": the load is zero everywhere, so it cannot be scaled to the resultant");
    scale = *ls.resultant / (integral * magnitude);
  }
  if (ls.follower && (body.finite_strain() || ls.penetration)) {
    d.follower_loads.push_back(follower_load(ls, body, body_index, pieces));
    d.follower_loads.back().pressure = [profile, scale, p = ls.value[0]](const Vec2& X) {
      return scale * profile(X) * p;
    };
    return;
  }
  const Vec2 value(ls.value[0], ls.value[1]);
  fem::TractionFn traction = [&](const Vec2& x, const Vec2& n) -> Vec2 {
    const double f = scale * profile(x);
    return ls.kind == LoadKind::pressure ? Vec2(-f * ls.value[0] * n) : Vec2(f * value);
  };
  for (auto [q, le] : sides) {
    const auto ts = pieces(q, le);
    for (size_t k = 0; k + 1 < ts.size(); ++k) {
      if (ts[k + 1] - ts[k] < 1e-14) continue;
      const Eigen::VectorXd fe = fem::edge_load(body.dofs.element(q), body.maps[q], le, ts[k],
                                                ts[k + 1], body.n_gauss[q] + 8, body.out_of_plane(),
                                                traction);
      for (int i = 0; i < fe.size(); ++i) d.load(body.global_dof(q, i)) += fe(i);
    }
  }
}

/// The pressure dofs of the mixed bodies, after all displacement dofs: per element
/// n_pressure_modes(p − 1), body after body.
void number_pressures(Discretization& d) {
  for (Body& body : d.bodies) {
    if (!body.mixed) continue;
    body.pressure_first.push_back(d.n_dofs);
    for (int q = 0; q < body.mesh.n_quads(); ++q) {
      d.n_dofs += fem::n_pressure_modes(fem::pressure_degree(body.dofs.element(q)));
      body.pressure_first.push_back(d.n_dofs);
    }
  }
}

/// The rigid-body motions each body's constraints leave free.
void find_free_rigid_motions(Discretization& d) {
  for (size_t b = 0; b < d.bodies.size(); ++b) {
    Body& body = d.bodies[b];
    const auto held = prescribed_vertices(d, static_cast<int>(b));
    if (body.axisymmetric()) {
      // A solid of revolution moves rigidly only along its axis (u_r = const strains the hoop).
      const bool axial = std::any_of(held.begin(), held.end(), [](const PointConstraint& c) { return c.component == 1; });
      body.free_rigid_motions = axial ? std::vector<std::string>{}
                                      : std::vector<std::string>{"translation along the axis (uy)"};
      continue;
    }
    body.free_rigid_motions = free_rigid_motions(held, body.mesh.size());
  }
}

/// The mesh edges of a body that some contact pair names, as its own edges or as its obstacle's.
std::vector<int> contact_edges_of(const ProblemSpec& spec, const Body& body) {
  std::vector<int> edges;
  auto add = [&](const std::vector<std::string>& names) {
    for (const auto& name : names)
      if (const auto it = body.edge_sets.find(name); it != body.edge_sets.end())
        edges.insert(edges.end(), it->second.begin(), it->second.end());
  };
  for (const auto& cs : spec.contact) {
    if (cs.body == body.name) add(cs.edge_sets);
    if (cs.obstacle.kind == ObstacleKind::body && cs.obstacle.body == body.name) add(cs.obstacle.edge_sets);
  }
  return edges;
}

/// An incompressible body must have some boundary where neither displacement component is
/// prescribed, or a contact pair: held all round, J = 1 leaves its mean pressure undetermined
/// (the tangent is singular).
void require_free_boundary(const ProblemSpec& spec, const Discretization& d) {
  for (size_t b = 0; b < d.bodies.size(); ++b) {
    const Body& body = d.bodies[b];
    if (!body.mixed || body.inverse_bulk != 0 || !contact_edges_of(spec, body).empty()) continue;
    bool free = false;
    for (int e = 0; e < body.mesh.n_edges() && !free; ++e) {
      const auto& edge = body.mesh.edge(e);
      if (!edge.on_boundary()) continue;
      std::vector<int> modes = {body.dofs.vertex_mode(edge.v0), body.dofs.vertex_mode(edge.v1)};
      for (int k = 2; k <= body.dofs.edge_degree(e); ++k) modes.push_back(body.dofs.edge_mode(e, k));
      for (int m : modes)
        for (int c = 0; c < 2; ++c) free = free || d.free_index[body.dof_offset + 2 * m + c] >= 0;
    }
    HPC_REQUIRE(free, InputError, spec.bodies[b].material.where.str(),
                ".incompressible: body '", body.name, "' has every boundary displacement prescribed and "
                "no contact: J = 1 then leaves its mean pressure undetermined (leave part of its "
                "boundary free or loaded, or give a finite K)");
  }
}

}  // namespace

Discretization discretize(const ProblemSpec& spec) {
  HPC_REQUIRE(!spec.bodies.empty(), InputError, spec.file, ": no bodies");
  Discretization d;
  d.method = spec.discretization.method == Method::h ? "h" : "p";
  for (size_t b = 0; b < spec.bodies.size(); ++b) {
    d.bodies.push_back(make_body(spec, static_cast<int>(b)));
    d.bodies.back().dof_offset = d.n_dofs;
    d.n_dofs += d.bodies.back().dofs.n_dofs();
  }
  number_pressures(d);
  d.free_index.assign(d.n_dofs, 0);
  d.prescribed = Eigen::VectorXd::Zero(d.n_dofs);
  d.load = Eigen::VectorXd::Zero(d.n_dofs);
  for (size_t b = 0; b < spec.bodies.size(); ++b) {
    const BodySpec& bs = spec.bodies[b];
    const Body& body = d.bodies[b];
    d.bodies[b].constraint_dofs = apply_constraints(bs, body, d);
    if (const auto w = axis_left_free(spec, static_cast<int>(b), body, d)) d.warnings.push_back(*w);
    for (const auto& ls : bs.edge_loads) apply_edge_load(ls, body, static_cast<int>(b), d);
    for (const auto& nf : bs.nodal_forces) {
      const int v = body.mesh.node_index(nf.node);
      HPC_REQUIRE(v >= 0, InputError, nf.where.str(), ": node ", nf.node, " does not exist");
      HPC_REQUIRE(!body.axisymmetric() || (body.mesh.node(v).x() == 0 && nf.force[0] == 0), InputError,
                  nf.where.str(), ": a nodal force on an axisymmetric body is a force on the "
                  "axis, along it: node ", nf.node, " at r = ", body.mesh.node(v).x(), " with fx = ",
                  nf.force[0], " would be a ring load (give it as an edge load instead)");
      for (int comp = 0; comp < 2; ++comp)
        d.load(body.dof_offset + 2 * body.dofs.vertex_mode(v) + comp) += nf.force[comp];
    }
    const Vec2 bf(bs.body_force[0], bs.body_force[1]);
    if (bf.norm() > 0) {
      for (int q = 0; q < body.mesh.n_quads(); ++q) {
        const auto ev = fem::element_values(body.dofs.element(q), body.maps[q], body.n_gauss[q],
                                            body.mesh, q);
        const Eigen::VectorXd fe = fem::body_force(ev, bf, body.out_of_plane());
        for (int i = 0; i < fe.size(); ++i) d.load(body.global_dof(q, i)) += fe(i);
      }
    }
  }
  find_free_rigid_motions(d);
  require_free_boundary(spec, d);
  for (size_t b = 0; b < d.bodies.size(); ++b) {
    const Body& body = d.bodies[b];
    const auto shapes = mesh::shape_warnings(body.mesh, body.maps, contact_edges_of(spec, body),
                                             body_context(spec, static_cast<int>(b)));
    d.warnings.insert(d.warnings.end(), shapes.begin(), shapes.end());
  }
  // Free numbering: external modes of all bodies first, then internal modes.
  for (int pass = 0; pass < 2; ++pass) {
    for (const Body& body : d.bodies) {
      for (int m = 0; m < body.dofs.n_modes(); ++m) {
        const bool internal = m >= body.dofs.n_external_modes();
        if (internal != (pass == 1)) continue;
        for (int comp = 0; comp < 2; ++comp) {
          const int dof = body.dof_offset + 2 * m + comp;
          if (d.free_index[dof] >= 0) d.free_index[dof] = d.n_free++;
        }
      }
    }
    if (pass == 0) d.n_free_external = d.n_free;
  }
  for (const Body& body : d.bodies)
    if (body.mixed)
      for (int dof = body.pressure_first.front(); dof < body.pressure_first.back(); ++dof)
        d.free_index[dof] = d.n_free++;
  return d;
}

}  // namespace hpcontact::model
