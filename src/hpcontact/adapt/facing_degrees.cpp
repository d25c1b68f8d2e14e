// Equal degrees on the facing contact edges of two bodies (facing_degrees.hpp).
#include "hpcontact/adapt/facing_degrees.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "hpcontact/geometry/vec2.hpp"

namespace hpcontact::adapt {

namespace {

/// A contact edge of a body as a straight segment between its vertices, and its element.
struct ContactEdge {
  Vec2 a, b;
  int element = -1;  ///< index into BodySpec::elements
};

int body_index(const model::ProblemSpec& spec, const std::string& name) {
  for (size_t b = 0; b < spec.bodies.size(); ++b)
    if (spec.bodies[b].name == name) return static_cast<int>(b);
  return -1;
}

std::vector<ContactEdge> contact_edges(const model::BodySpec& body, const std::vector<std::string>& sets) {
  std::map<int, Vec2> at;
  for (size_t i = 0; i < body.node_ids.size(); ++i) at[body.node_ids[i]] = Vec2(body.nodes[i][0], body.nodes[i][1]);
  std::vector<ContactEdge> out;
  for (const auto& set : body.edge_sets) {
    if (std::find(sets.begin(), sets.end(), set.name) == sets.end()) continue;
    for (const auto& [n0, n1] : set.edges) {
      for (size_t e = 0; e < body.elements.size(); ++e) {
        const auto& q = body.elements[e];
        const bool has0 = std::find(q.begin(), q.end(), n0) != q.end();
        const bool has1 = std::find(q.begin(), q.end(), n1) != q.end();
        if (has0 && has1 && at.count(n0) && at.count(n1)) {
          out.push_back({at[n0], at[n1], static_cast<int>(e)});
          break;
        }
      }
    }
  }
  return out;
}

/// Whether the two edges face each other: the part of `f` whose projection falls on `e`
/// covers more than half of the shorter edge, and f's midpoint lies within half the shorter
/// length of e's line.
bool facing(const ContactEdge& e, const ContactEdge& f) {
  const Vec2 d = e.b - e.a;
  const double le = d.norm(), lf = (f.b - f.a).norm();
  if (le <= 0 || lf <= 0) return false;
  const Vec2 t = d / le;
  const double s0 = t.dot(f.a - e.a), s1 = t.dot(f.b - e.a);
  const double overlap = std::min(le, std::max(s0, s1)) - std::max(0.0, std::min(s0, s1));
  const double shorter = std::min(le, lf);
  const Vec2 mid = 0.5 * (f.a + f.b) - e.a;
  const double off_line = std::abs(t.x() * mid.y() - t.y() * mid.x());
  return overlap > 0.5 * shorter && off_line < 0.5 * shorter;
}

int degree_of(const model::ProblemSpec& spec, const model::BodySpec& body, int element) {
  const auto it = body.element_degrees.find(body.element_ids[element]);
  const auto p = it != body.element_degrees.end() ? it->second
                                                  : body.degree.value_or(spec.discretization.degree);
  return std::max(p[0], p[1]);
}

}  // namespace

void match_facing_degrees(model::ProblemSpec& spec) {
  for (const auto& pair : spec.contact) {
    // Friction's stick ties the traces tangentially at every node; the oscillation was seen there
    // (without friction, unequal degrees cost nothing measurable: examples/roller-block)
    if (pair.obstacle.kind != model::ObstacleKind::body || pair.friction.law == "none" ||
        pair.enforcement != model::Enforcement::augmented_lagrangian)
      continue;
    const int ba = body_index(spec, pair.body), bb = body_index(spec, pair.obstacle.body);
    if (ba < 0 || bb < 0 || ba == bb) continue;
    auto& A = spec.bodies[ba];
    auto& B = spec.bodies[bb];
    const auto ea = contact_edges(A, pair.edge_sets), eb = contact_edges(B, pair.obstacle.edge_sets);
    std::vector<std::pair<int, int>> faces;  // (element of A, element of B)
    for (const auto& e : ea)
      for (const auto& f : eb)
        if (facing(e, f) || facing(f, e)) faces.emplace_back(e.element, f.element);
    // The larger degree of each facing couple on both (the estimate asked for it on one side);
    // an element facing two others takes the largest, and its partners follow in the next sweep.
    for (bool changed = true; changed;) {
      changed = false;
      for (const auto& [a, b] : faces) {
        const int pa = degree_of(spec, A, a), pb = degree_of(spec, B, b);
        if (pa == pb) continue;
        const int p = std::max(pa, pb);
        A.element_degrees[A.element_ids[a]] = {p, p};
        B.element_degrees[B.element_ids[b]] = {p, p};
        changed = true;
      }
    }
  }
}

}  // namespace hpcontact::adapt
