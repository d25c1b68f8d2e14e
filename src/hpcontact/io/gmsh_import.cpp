// A body's mesh from a parsed Gmsh file: quadrilaterals of a physical surface, counter-clockwise;
// exact circular arcs named in the problem file or recovered from second-order midside nodes;
// edge sets from 1D physical groups; and the expansion of bodies[].gmsh into the YAML tree.
#include "hpcontact/io/gmsh_import.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>

#include "hpcontact/io/schema_check.hpp"
#include "hpcontact/io/yaml_limits.hpp"

namespace hpcontact::io {

namespace {

using Point = std::array<double, 2>;
/// An edge regardless of orientation: the two node tags, smaller first.
using Edge = std::pair<int, int>;

Edge undirected(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

double cross(const Point& u, const Point& v) { return u[0] * v[1] - u[1] * v[0]; }
Point minus(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1]}; }
double norm(const Point& u) { return std::hypot(u[0], u[1]); }

std::string shown_number(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

std::string shown_point(const Point& p) {
  return "(" + shown_number(p[0]) + ", " + shown_number(p[1]) + ")";
}

bool in_group(const std::vector<std::string>& groups, const std::string& name) {
  return std::find(groups.begin(), groups.end(), name) != groups.end();
}

bool has_group(const GmshMesh& mesh, int dim, const std::string& name) {
  return std::any_of(mesh.groups.begin(), mesh.groups.end(),
                     [&](const GmshPhysicalGroup& g) { return g.dim == dim && g.name == name; });
}

bool is_triangle(int type) { return type == 2 || type == 9 || (type >= 20 && type <= 25); }

/// The circle through three points that are not on one line: centre and radius.
struct Circle {
  Point center{};
  double radius = 0;
};

// With u = b - a and v = m - a, the centre c = a + w solves 2 w·u = |u|², 2 w·v = |v|²:
//   w = (|u|² (v_y, -v_x) - |v|² (u_y, -u_x)) / (2 u × v).
Circle circle_through(const Point& a, const Point& m, const Point& b) {
  const Point u = minus(b, a), v = minus(m, a);
  const double d = 2 * cross(u, v), uu = u[0] * u[0] + u[1] * u[1], vv = v[0] * v[0] + v[1] * v[1];
  const Point w{(uu * v[1] - vv * u[1]) / d, (vv * u[0] - uu * v[0]) / d};
  const Point c{a[0] + w[0], a[1] + w[1]};
  return {c, (norm(minus(a, c)) + norm(minus(b, c)) + norm(minus(m, c))) / 3};
}

/// Least-squares circle through `points` (Gauss-Newton on sum (|p - c| - r)², from `start`);
/// nothing if the normal equations are singular.
std::optional<Circle> fit_circle(const std::vector<Point>& points, Circle c) {
  for (int iteration = 0; iteration < 20; ++iteration) {
    // Residual r_i = |p_i - c| - r; its gradient J_i = (-(p_i - c)/|p_i - c|, -1).
    double jj[3][3] = {}, jr[3] = {};
    for (const Point& p : points) {
      const Point d = minus(p, c.center);
      const double l = norm(d);
      if (l == 0) return std::nullopt;
      const double j[3] = {-d[0] / l, -d[1] / l, -1.0}, r = l - c.radius;
      for (int i = 0; i < 3; ++i) {
        jr[i] += j[i] * r;
        for (int k = 0; k < 3; ++k) jj[i][k] += j[i] * j[k];
      }
    }
    // Solve jj delta = -jr by Cramer's rule (3 x 3, symmetric positive semi-definite).
    const auto det = [](const double m[3][3]) {
      return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
             m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const double d0 = det(jj);
    const double scale = jj[0][0] * jj[1][1] * jj[2][2];
    if (!(std::abs(d0) > 1e-12 * scale)) return std::nullopt;
    double delta[3];
    for (int col = 0; col < 3; ++col) {
      double m[3][3];
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) m[i][k] = k == col ? -jr[i] : jj[i][k];
      delta[col] = det(m) / d0;
    }
    c.center = {c.center[0] + delta[0], c.center[1] + delta[1]};
    c.radius += delta[2];
    if (std::abs(delta[0]) + std::abs(delta[1]) + std::abs(delta[2]) <= 1e-15 * c.radius) break;
  }
  if (!(c.radius > 0) || !std::isfinite(c.center[0]) || !std::isfinite(c.center[1]))
    return std::nullopt;
  return c;
}

/// Union-find over candidate arcs.
int find_root(std::vector<int>& parent, int i) {
  while (parent[static_cast<std::size_t>(i)] != i) {
    parent[static_cast<std::size_t>(i)] =
        parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
    i = parent[static_cast<std::size_t>(i)];
  }
  return i;
}

/// An edge of a second-order quad whose midside node is off its chord.
struct CurvedEdge {
  std::array<int, 2> nodes;  // oriented as in the first element that has it
  int midside;
  Circle circle;
};

class Importer {
 public:
  Importer(const GmshMesh& mesh, const ImportOptions& options) : mesh_(mesh), options_(options) {}

  ImportedMesh run() {
    select_quads();
    make_nodes();
    make_elements();
    for (const auto& e : options_.edges_with_curves)
      curve_owner_.emplace(undirected(e[0], e[1]), -1);
    for (std::size_t j = 0; j < options_.arcs.size(); ++j) make_named_arc(j);
    recover_arcs();
    make_edge_sets();
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail_at(int line, const std::string& what) const {
    throw InputError(mesh_.file + ":" + std::to_string(line) + ": " + what);
  }

  const Point& xy(int tag) const { return mesh_.nodes.at(tag); }

  void select_quads() {
    const std::string& surface = options_.surface;
    if (!surface.empty() && !has_group(mesh_, 2, surface))
      throw GmshOptionError("surface", "no 2D physical group of that name in " + mesh_.file +
                                           " (defined: " + gmsh_group_list(mesh_, 2) + ") (got '" +
                                           surface + "')");
    const std::string in_surface = surface.empty() ? "" : " of surface '" + surface + "'";
    for (const GmshOtherFace& f : mesh_.other_faces) {
      if (!surface.empty() && !in_group(f.groups, surface)) continue;
      if (is_triangle(f.type))
        fail_at(f.line, "element " + std::to_string(f.tag) + in_surface + " is a " +
                            gmsh_type_name(f.type) +
                            ": hpcontact needs quadrilaterals; recombine the mesh "
                            "(Mesh.RecombineAll = 1)");
      fail_at(f.line, "element " + std::to_string(f.tag) + in_surface + " is a " +
                          gmsh_type_name(f.type) +
                          ": hpcontact reads quadrilaterals of order 1 and 2 (gmsh types 3, 16, "
                          "10; gmsh -order 1 or 2)");
    }
    for (const GmshQuad& q : mesh_.quads)
      if (surface.empty() || in_group(q.groups, surface)) quads_.push_back(&q);
    if (quads_.empty())
      throw InputError(mesh_.file + ": no quadrilaterals" + in_surface +
                       " (gmsh element types 3, 16, 10; recombine the mesh with "
                       "Mesh.RecombineAll = 1)");
  }

  void make_nodes() {
    std::set<int> tags;
    for (const GmshQuad* q : quads_) tags.insert(q->corners.begin(), q->corners.end());
    Point lo{xy(*tags.begin())}, hi = lo;
    for (int tag : tags) {
      const Point& p = xy(tag);
      out_.nodes.emplace_back(tag, p);
      for (std::size_t k = 0; k < 2; ++k) {
        lo[k] = std::min(lo[k], p[k]);
        hi[k] = std::max(hi[k], p[k]);
      }
    }
    out_.size = norm(minus(hi, lo));
  }

  /// Corners counter-clockwise (reversed where the file has them clockwise); the element edges,
  /// oriented as the first element that has them runs along them, with their midside nodes.
  void make_elements() {
    for (const GmshQuad* q : quads_) {
      std::array<int, 4> v = q->corners, mid = q->midside;
      double area2 = 0;  // twice the signed area of the corner polygon (shoelace)
      for (std::size_t k = 0; k < 4; ++k) area2 += cross(xy(v[k]), xy(v[(k + 1) % 4]));
      if (!(std::abs(area2) > 1e-14 * out_.size * out_.size))
        fail_at(q->line, "element " + std::to_string(q->tag) + " has zero area (corners " +
                             corner_list(v) + ")");
      // Reversed, edge k (from corner k to k + 1, with midside node k) becomes edge 3 - k.
      if (area2 < 0) {
        v = {v[0], v[3], v[2], v[1]};
        mid = {mid[3], mid[2], mid[1], mid[0]};
      }
      for (std::size_t k = 0; k < 4; ++k) {
        const int a = v[k], b = v[(k + 1) % 4];
        const auto [at, inserted] = edge_index_.emplace(undirected(a, b), edges_.size());
        if (inserted) {
          edges_.push_back({{a, b}, mid[k], q->line});
        } else if (edges_[at->second].midside != mid[k]) {
          fail_at(q->line,
                  "element " + std::to_string(q->tag) + " has node " + std::to_string(mid[k]) +
                      " in the middle of edge [" + std::to_string(a) + ", " + std::to_string(b) +
                      "], another element node " + std::to_string(edges_[at->second].midside) +
                      " (the mesh is not conforming)");
        }
      }
      out_.elements.emplace_back(q->tag, v);
    }
  }

  static std::string corner_list(const std::array<int, 4>& v) {
    std::ostringstream os;
    os << '[' << v[0] << ", " << v[1] << ", " << v[2] << ", " << v[3] << ']';
    return os.str();
  }

  /// The lines of 1D physical group `name` that are edges of the body, each edge once.
  std::vector<const GmshLine*> body_lines(const std::string& name) const {
    std::vector<const GmshLine*> lines;
    std::set<Edge> seen;
    for (const GmshLine& l : mesh_.lines) {
      if (!in_group(l.groups, name)) continue;
      const Edge e = undirected(l.ends[0], l.ends[1]);
      if (edge_index_.count(e) && seen.insert(e).second) lines.push_back(&l);
    }
    return lines;
  }

  void make_named_arc(std::size_t j) {
    const ImportOptions::NamedArc& arc = options_.arcs[j];
    const std::string key = "arcs[" + std::to_string(j) + "]";
    if (!has_group(mesh_, 1, arc.group))
      throw GmshOptionError(key + ".edges", "no 1D physical group of that name in " + mesh_.file +
                                                " (defined: " + gmsh_group_list(mesh_, 1) + ") (got '" +
                                                arc.group + "')");
    const std::vector<const GmshLine*> lines = body_lines(arc.group);
    if (lines.empty())
      throw GmshOptionError(key + ".edges", "no line of physical group '" + arc.group + "' in " +
                                                mesh_.file + " is an edge of the body");
    for (const GmshLine* l : lines) {
      const Edge e = undirected(l->ends[0], l->ends[1]);
      const std::string edge = "edge [" + std::to_string(l->ends[0]) + ", " +
                               std::to_string(l->ends[1]) + "] (" + mesh_.file + ":" +
                               std::to_string(l->line) + ")";
      if (const auto it = curve_owner_.find(e); it != curve_owner_.end())
        throw GmshOptionError(
            key + ".edges", edge + " already has a curve " +
                                (it->second < 0 ? std::string("given in curves")
                                                : "from arcs[" + std::to_string(it->second) + "]"));
      for (int node : l->ends) {
        const double distance = norm(minus(xy(node), arc.center));
        if (std::abs(distance - arc.radius) > 1e-6 * arc.radius)
          throw GmshOptionError(
              key, "node " + std::to_string(node) + " " + shown_point(xy(node)) + " of " + edge +
                       " is at distance " + shown_number(distance) +
                       " from the centre, not on the circle of radius " + shown_number(arc.radius));
      }
      curve_owner_.emplace(e, static_cast<int>(j));
      out_.arcs.push_back({l->ends, arc.center, arc.radius, 0});
    }
  }

  /// Second-order edges whose midside node is off the chord become arcs through their three
  /// nodes. A circle through three close points is ill-conditioned (its radius errs by about
  /// R/sagitta times the coordinates' round-off), so neighbouring arcs of one circle are joined
  /// and fitted to one circle through all their nodes.
  void recover_arcs() {
    const double tolerance = options_.arc_tolerance * out_.size;
    std::vector<CurvedEdge> curved;
    for (const EdgeInfo& e : edges_) {
      if (e.midside == 0 || curve_owner_.count(undirected(e.nodes[0], e.nodes[1]))) continue;
      const Point &a = xy(e.nodes[0]), &b = xy(e.nodes[1]), &m = xy(e.midside);
      const double chord = norm(minus(b, a));
      const double off = std::abs(cross(minus(b, a), minus(m, a))) / chord;
      if (!(off > tolerance)) continue;
      curved.push_back({e.nodes, e.midside, circle_through(a, m, b)});
    }
    // Join arcs that share a node and agree on their circle to 1e-7 of the radius.
    std::vector<int> parent(curved.size());
    std::iota(parent.begin(), parent.end(), 0);
    std::map<int, std::vector<int>> at_node;
    for (std::size_t i = 0; i < curved.size(); ++i)
      for (int node : curved[i].nodes) at_node[node].push_back(static_cast<int>(i));
    for (const auto& [node, list] : at_node)
      for (std::size_t x = 0; x < list.size(); ++x)
        for (std::size_t y = x + 1; y < list.size(); ++y) {
          const Circle &c1 = curved[static_cast<std::size_t>(list[x])].circle,
                       &c2 = curved[static_cast<std::size_t>(list[y])].circle;
          const double r = std::max(c1.radius, c2.radius);
          if (norm(minus(c1.center, c2.center)) <= 1e-7 * r &&
              std::abs(c1.radius - c2.radius) <= 1e-7 * r)
            parent[static_cast<std::size_t>(find_root(parent, list[x]))] =
                find_root(parent, list[y]);
        }
    std::map<int, std::vector<std::size_t>> chains;
    for (std::size_t i = 0; i < curved.size(); ++i)
      chains[find_root(parent, static_cast<int>(i))].push_back(i);
    for (const auto& [root, members] : chains) {
      if (members.size() < 2) continue;
      std::set<int> tags;
      Circle start;
      for (std::size_t i : members) {
        tags.insert({curved[i].nodes[0], curved[i].nodes[1], curved[i].midside});
        start.center[0] += curved[i].circle.center[0] / static_cast<double>(members.size());
        start.center[1] += curved[i].circle.center[1] / static_cast<double>(members.size());
        start.radius += curved[i].circle.radius / static_cast<double>(members.size());
      }
      std::vector<Point> points;
      for (int tag : tags) points.push_back(xy(tag));
      const std::optional<Circle> fit = fit_circle(points, start);
      if (!fit) continue;
      double worst = 0;
      for (const Point& p : points)
        worst = std::max(worst, std::abs(norm(minus(p, fit->center)) - fit->radius));
      if (worst > 1e-9 * fit->radius) continue;  // not one circle after all: keep each edge's own
      for (std::size_t i : members) curved[i].circle = *fit;
    }
    for (const CurvedEdge& c : curved) {
      // Three points in counter-clockwise order along a circle turn left: a -> m -> b.
      const Point &a = xy(c.nodes[0]), &b = xy(c.nodes[1]), &m = xy(c.midside);
      const int ccw = cross(minus(m, a), minus(b, m)) > 0 ? 1 : -1;
      out_.arcs.push_back({c.nodes, c.circle.center, c.circle.radius, ccw});
      ++out_.n_recovered_arcs;
    }
  }

  void make_edge_sets() {
    std::set<std::string> done;
    for (const GmshPhysicalGroup& g : mesh_.groups) {
      if (g.dim != 1 || !done.insert(g.name).second) continue;
      std::vector<std::array<int, 2>> edges;
      for (const GmshLine* l : body_lines(g.name)) edges.push_back(l->ends);
      if (!edges.empty()) out_.edge_sets.emplace_back(g.name, std::move(edges));
    }
  }

  struct EdgeInfo {
    std::array<int, 2> nodes;
    int midside;
    int line;
  };

  const GmshMesh& mesh_;
  const ImportOptions& options_;
  std::vector<const GmshQuad*> quads_;
  std::vector<EdgeInfo> edges_;
  std::map<Edge, std::size_t> edge_index_;
  std::map<Edge, int> curve_owner_;  // edge -> index of its named arc; -1: a hand-given curve
  ImportedMesh out_;
};

// ---- the YAML side ------------------------------------------------------------------------

/// Shortest text that reads back as the same double.
std::string number_text(double v) {
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, end);
}

YAML::Node flow_pair(const std::string& a, const std::string& b) {
  YAML::Node pair(YAML::NodeType::Sequence);
  pair.push_back(a);
  pair.push_back(b);
  pair.SetStyle(YAML::EmitterStyle::Flow);
  return pair;
}

YAML::Node ids_node(const std::array<int, 2>& e) {
  return flow_pair(std::to_string(e[0]), std::to_string(e[1]));
}

/// The node at `key` ("surface", "arcs[1].edges") below `section`.
YAML::Node node_at(const YAML::Node& section, const std::string& key) {
  YAML::Node node = section;
  std::size_t start = 0;
  while (start < key.size()) {
    const std::size_t end = std::min(key.find_first_of(".[", start), key.size());
    if (end > start) {
      const YAML::Node& map = node;
      node = map[key.substr(start, end - start)];
    }
    if (end < key.size() && key[end] == '[') {
      const std::size_t close = key.find(']', end);
      const YAML::Node& list = node;
      node = list[std::stoul(key.substr(end + 1, close - end - 1))];
      start = close + 2;
    } else {
      start = end + 1;
    }
  }
  return node;
}

ImportOptions read_options(const YAML::Node& g, const YAML::Node& body) {
  ImportOptions o;
  if (g["surface"]) o.surface = g["surface"].Scalar();
  if (const YAML::Node arcs = g["arcs"])
    for (std::size_t j = 0; j < arcs.size(); ++j)
      o.arcs.push_back({arcs[j]["edges"].Scalar(),
                        {*to_number(arcs[j]["center"][0]), *to_number(arcs[j]["center"][1])},
                        *to_number(arcs[j]["radius"])});
  o.arc_tolerance = *to_number(g["arc_tolerance"]);
  // Hand-given curves, as far as they are well formed (the schema check reports the others).
  if (const YAML::Node curves = body["curves"]; curves && curves.IsSequence())
    for (std::size_t i = 0; i < curves.size(); ++i) {
      if (!curves[i].IsMap()) continue;
      const YAML::Node nodes = curves[i]["nodes"];
      if (!nodes || !nodes.IsSequence() || nodes.size() != 2) continue;
      const std::optional<int> a = to_integer(nodes[0]), b = to_integer(nodes[1]);
      if (a && b) o.edges_with_curves.push_back({*a, *b});
    }
  return o;
}

/// The YAML values write_mesh() adds for `m` at most (every key, list, map and scalar).
std::size_t yaml_values(const ImportedMesh& m) {
  std::size_t n = 2 + 4 * m.nodes.size();  // nodes: {id: [x, y], ...}
  n += 2 + 6 * m.elements.size();          // elements: {id: [a, b, c, d], ...}
  n += 2 + 15 * m.arcs.size();  // curves: [{nodes: [a, b], arc: {center: [x, y], radius: r, ccw: c}}]
  n += 2;                       // edge_sets: {name: [[a, b], ...], ...}
  for (const auto& set : m.edge_sets) n += 2 + 3 * set.second.size();
  return n;
}

/// Writes the imported mesh into the body's tree: nodes, elements, curves and edge_sets.
void write_mesh(YAML::Node body, const ImportedMesh& m, const std::string& path,
                const std::string& origin, YamlSource& source) {
  YAML::Node nodes(YAML::NodeType::Map), elements(YAML::NodeType::Map);
  for (const auto& [tag, p] : m.nodes) nodes.force_insert(std::to_string(tag), point_node(p));
  for (const auto& [tag, v] : m.elements) {
    YAML::Node corners(YAML::NodeType::Sequence);
    for (int n : v) corners.push_back(std::to_string(n));
    corners.SetStyle(YAML::EmitterStyle::Flow);
    elements.force_insert(std::to_string(tag), corners);
  }
  body["nodes"] = nodes;
  body["elements"] = elements;
  source.mark_generated(path + ".nodes", origin);
  source.mark_generated(path + ".elements", origin);

  const YAML::Node& view = body;
  if (!m.arcs.empty()) {
    YAML::Node curves = view["curves"] ? view["curves"] : YAML::Node(YAML::NodeType::Sequence);
    for (const ImportedMesh::Arc& a : m.arcs) {
      YAML::Node arc(YAML::NodeType::Map), curve(YAML::NodeType::Map);
      arc["center"] = point_node(a.center);
      arc["radius"] = number_text(a.radius);
      if (a.ccw != 0) arc["ccw"] = a.ccw > 0 ? "true" : "false";
      curve["nodes"] = ids_node(a.nodes);
      curve["arc"] = arc;
      curve.SetStyle(YAML::EmitterStyle::Flow);
      source.mark_generated(join_index(path + ".curves", curves.size()), origin);
      curves.push_back(curve);
    }
    if (!view["curves"]) body["curves"] = curves;
  }
  if (!m.edge_sets.empty()) {
    YAML::Node sets = view["edge_sets"] ? view["edge_sets"] : YAML::Node(YAML::NodeType::Map);
    for (const auto& [name, edges] : m.edge_sets) {
      YAML::Node list(YAML::NodeType::Sequence);
      for (const auto& e : edges) list.push_back(ids_node(e));
      list.SetStyle(YAML::EmitterStyle::Flow);
      sets.force_insert(name, list);
      source.mark_generated(join_key(path + ".edge_sets", name), origin);
    }
    if (!view["edge_sets"]) body["edge_sets"] = sets;
  }
}

}  // namespace

YAML::Node point_node(const std::array<double, 2>& p) {
  return flow_pair(number_text(p[0]), number_text(p[1]));
}

std::string gmsh_group_list(const GmshMesh& mesh, int dim) {
  std::string list;
  std::set<std::string> seen;
  for (const GmshPhysicalGroup& g : mesh.groups)
    if (g.dim == dim && seen.insert(g.name).second) list += (list.empty() ? "" : ", ") + g.name;
  return list.empty() ? "none" : list;
}

ImportedMesh import_gmsh_body(const GmshMesh& mesh, const ImportOptions& options) {
  return Importer(mesh, options).run();
}

GmshMesh read_gmsh_section(const YAML::Node& section, const std::string& path, YamlSource& source) {
  std::filesystem::path file(section["file"].Scalar());
  if (file.is_relative()) file = std::filesystem::path(source.file()).parent_path() / file;
  try {
    return read_gmsh(file.string());
  } catch (const IoError& e) {
    throw IoError(source.where(section["file"], path + ".file").str() + ": " + e.what());
  }
}

void refuse_second_gmsh_key(const YAML::Node& parent, const std::string& gmsh_path, YamlSource& source) {
  int n_gmsh = 0;
  for (auto it = parent.begin(); it != parent.end(); ++it)
    if (it->first.IsScalar() && it->first.Scalar() == "gmsh" && ++n_gmsh > 1)
      source.fail(it->first, gmsh_path, "duplicate key");
}

std::vector<std::string> expand_gmsh_meshes(YAML::Node& root, YamlSource& source) {
  std::vector<std::string> notes;
  std::optional<std::size_t> values;  // of the tree, counted at the first gmsh section
  const YAML::Node& view = root;
  const YAML::Node bodies = view["bodies"];
  if (!bodies || !bodies.IsSequence()) return notes;  // the schema check reports it
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    YAML::Node body = bodies[i];
    const YAML::Node& body_view = body;
    if (!body.IsMap() || !body_view["gmsh"]) continue;
    const std::string path = join_index("bodies", i), gmsh_path = path + ".gmsh";
    refuse_second_gmsh_key(body_view, gmsh_path, source);
    const YAML::Node g = body_view["gmsh"];
    check_and_fill_defaults(g, "bodies[].gmsh", gmsh_path, source);
    for (const char* key : {"nodes", "elements"})
      if (body_view[key])
        source.fail(body_view[key], join_key(path, key),
                    "give either gmsh or nodes and elements, not both");

    const GmshMesh mesh = read_gmsh_section(g, gmsh_path, source);
    ImportedMesh imported;
    try {
      imported = import_gmsh_body(mesh, read_options(g, body_view));
    } catch (const GmshOptionError& e) {
      source.fail(node_at(g, e.key), join_key(gmsh_path, e.key), e.what_text);
    }
    if (const YAML::Node sets = body_view["edge_sets"]; sets && sets.IsMap())
      for (auto it = sets.begin(); it != sets.end(); ++it)
        for (const auto& [name, edges] : imported.edge_sets)
          if (it->first.IsScalar() && it->first.Scalar() == name)
            source.fail(it->first, join_key(path + ".edge_sets", name),
                        "the 1D physical group '" + name + "' of " + mesh.file +
                            " makes an edge set of this name already; rename one of them");

    // Its tree is bounded as the file's was, before it is built.
    if (!values) values = count_yaml_values(root);
    const std::size_t added = yaml_values(imported);
    if (*values + added > kMaxYamlValues)
      source.fail(g, gmsh_path,
                  "the mesh of " + mesh.file + " (" + std::to_string(imported.nodes.size()) +
                      " corner nodes, " + std::to_string(imported.elements.size()) +
                      " elements) makes " + std::to_string(added) +
                      " YAML values, which with the problem's " + std::to_string(*values) +
                      " are more than the " + std::to_string(kMaxYamlValues) +
                      " an input may have (some 500 bytes of memory each: about 4 per node and 6 "
                      "per element): give a coarser mesh (a p-FEM mesh needs few elements: raise "
                      "the degree)");
    *values += added;

    // The mesh takes the place of the gmsh key: the keys after it are taken out and put back
    // after the mesh (curves and edge_sets stay where they are and receive the new entries).
    std::vector<std::pair<YAML::Node, YAML::Node>> after;
    bool past_gmsh = false;
    for (auto it = body.begin(); it != body.end(); ++it) {
      if (!it->first.IsScalar()) continue;
      const std::string& key = it->first.Scalar();
      if (past_gmsh && key != "curves" && key != "edge_sets")
        after.emplace_back(it->first, it->second);
      past_gmsh = past_gmsh || key == "gmsh";
    }
    for (const auto& [key, value] : after) body.remove(key.Scalar());
    body.remove("gmsh");
    write_mesh(body, imported, path, "from " + mesh.file, source);
    for (const auto& [key, value] : after) body.force_insert(key, value);
    const YAML::Node name = body_view["name"];
    std::string note = path +
                       (name && name.IsScalar() ? " (" + one_line(name.Scalar()) + ")" : "") +
                       ": mesh of " + mesh.file;
    if (g["surface"]) note += ", surface '" + g["surface"].Scalar() + "'";
    note += ": " + std::to_string(imported.nodes.size()) + " nodes, " +
            std::to_string(imported.elements.size()) + " elements, " +
            std::to_string(imported.n_recovered_arcs) + " arcs recovered from midside nodes";
    if (!imported.edge_sets.empty()) {
      note += ", edge sets";
      for (const auto& set : imported.edge_sets) note += " " + set.first;
    }
    notes.push_back(note);
  }
  return notes;
}

}  // namespace hpcontact::io
