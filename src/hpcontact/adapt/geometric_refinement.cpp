// Conforming geometric refinement towards a node: each element at the node becomes a corner
// square and two quadrilaterals (seed Fig. 4.12 with the square's size `factor`).
#include "hpcontact/adapt/geometric_refinement.hpp"

#include <algorithm>

#include "hpcontact/core/error.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::adapt {

namespace {

/// Reference corners V1..V4 of the square [-1, 1]² (basis/quad_modes.hpp).
constexpr double kCorner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

bool same_edge(const std::array<int, 2>& e, int u, int v) {
  return (e[0] == u && e[1] == v) || (e[0] == v && e[1] == u);
}

}  // namespace

model::ProblemSpec refine_towards_node(const model::ProblemSpec& spec, int body, int centre,
                                       double factor) {
  HPC_ASSERT(factor > 0 && factor < 1, "factor ", factor);
  const model::Discretization d = model::discretize(spec);
  const model::Body& db = d.bodies[body];
  const mesh::Mesh& m = db.mesh;
  const int c_index = m.node_index(centre);
  HPC_REQUIRE(c_index >= 0, AdaptError, "hp: node ", centre, " does not exist in body '", db.name, "'");

  model::ProblemSpec out = spec;
  model::BodySpec& nb = out.bodies[body];
  int next_node = *std::max_element(nb.node_ids.begin(), nb.node_ids.end()) + 1;
  int next_element = *std::max_element(nb.element_ids.begin(), nb.element_ids.end()) + 1;
  auto add_node = [&](const Vec2& x) {
    nb.node_ids.push_back(next_node);
    nb.nodes.push_back({x.x(), x.y()});
    return next_node++;
  };

  // The new node on the edge from the centre to node v, at `factor` of the way (on its curve).
  std::map<int, int> split_node;  // v -> new node
  auto edge_node = [&](int v) {
    if (auto it = split_node.find(v); it != split_node.end()) return it->second;
    const int e = m.find_edge(c_index, m.node_index(v));
    HPC_ASSERT(e >= 0, "edge ", centre, "-", v);
    const double t = m.edge(e).v0 == c_index ? -1 + 2 * factor : 1 - 2 * factor;
    const int id = add_node(m.edge_point(e, t));
    split_node[v] = id;
    // An exact curve is split into two of the same circle.
    for (size_t k = 0; k < nb.curves.size(); ++k) {
      model::CurveSpec& cs = nb.curves[k];
      if (!same_edge({cs.node_a, cs.node_b}, centre, v)) continue;
      HPC_REQUIRE(cs.kind == model::CurveKind::arc, AdaptError, "hp: the edge from node ", centre,
                  " to node ", v, " is a parametric curve (", cs.where.str(),
                  "); hp splits circles and straight edges only");
      model::CurveSpec second = cs;
      const int far = cs.node_a == centre ? cs.node_b : cs.node_a;
      const bool from_centre = cs.node_a == centre;
      cs.node_a = from_centre ? centre : id;
      cs.node_b = from_centre ? id : centre;
      second.node_a = from_centre ? id : far;
      second.node_b = from_centre ? far : id;
      nb.curves.push_back(second);
      break;
    }
    // Edge sets keep covering the same boundary.
    for (auto& set : nb.edge_sets) {
      std::vector<std::array<int, 2>> edges;
      for (const auto& ed : set.edges) {
        if (!same_edge(ed, centre, v)) {
          edges.push_back(ed);
          continue;
        }
        edges.push_back({ed[0], id});  // the two halves, in the listed direction
        edges.push_back({id, ed[1]});
      }
      set.edges = std::move(edges);
    }
    return id;
  };

  std::vector<int> ids;
  std::vector<std::array<int, 4>> elements;
  bool any = false;
  for (int q = 0; q < m.n_quads(); ++q) {
    const int id = m.quad_id(q);
    const auto& nodes = spec.bodies[body].elements[q];
    const auto at = std::find(nodes.begin(), nodes.end(), centre);
    if (at == nodes.end()) {
      ids.push_back(id);
      elements.push_back(nodes);
      continue;
    }
    any = true;
    const int c = static_cast<int>(at - nodes.begin());
    const int A = nodes[(c + 1) % 4], C = nodes[(c + 2) % 4], B = nodes[(c + 3) % 4];
    const int a = edge_node(A), b = edge_node(B);
    // The inner corner of the square, on the element's blending map.
    const double xi = kCorner[c][0] + factor * (kCorner[(c + 1) % 4][0] - kCorner[c][0]) +
                      factor * (kCorner[(c + 3) % 4][0] - kCorner[c][0]);
    const double eta = kCorner[c][1] + factor * (kCorner[(c + 1) % 4][1] - kCorner[c][1]) +
                       factor * (kCorner[(c + 3) % 4][1] - kCorner[c][1]);
    const int mid = add_node(db.maps[q].map(xi, eta));
    for (const auto& quad : {std::array{centre, a, mid, b}, std::array{a, A, C, mid},
                             std::array{b, mid, C, B}}) {
      ids.push_back(next_element++);
      elements.push_back(quad);
    }
    nb.element_degrees.erase(id);
  }
  HPC_REQUIRE(any, AdaptError, "hp: node ", centre, " of body '", db.name,
              "' is not a corner of any element");
  nb.element_ids = std::move(ids);
  nb.elements = std::move(elements);
  try {
    (void)model::discretize(out);
  } catch (const MeshError& e) {
    throw AdaptError(detail::concat("hp: refining towards node ", centre, " with factor ", factor,
                                    " gives an invalid mesh: ", e.what()));
  }
  return out;
}

std::map<int, int> element_layers(const model::BodySpec& body, const std::vector<int>& centres) {
  std::map<int, std::vector<int>> elements_of_node;  // node id -> element indices
  for (size_t q = 0; q < body.elements.size(); ++q)
    for (int n : body.elements[q]) elements_of_node[n].push_back(static_cast<int>(q));
  std::vector<int> layer(body.elements.size(), -1), front;
  for (int c : centres)
    for (int q : elements_of_node[c])
      if (layer[q] < 0) layer[q] = 0, front.push_back(q);
  for (int depth = 1; !front.empty(); ++depth) {
    std::vector<int> next;
    for (int q : front)
      for (int n : body.elements[q])
        for (int r : elements_of_node[n])
          if (layer[r] < 0) layer[r] = depth, next.push_back(r);
    front = std::move(next);
  }
  std::map<int, int> by_id;
  for (size_t q = 0; q < layer.size(); ++q) by_id[body.element_ids[q]] = layer[q];
  return by_id;
}

}  // namespace hpcontact::adapt
