// Chaining a Gmsh 1D physical group into an obstacle's points (see gmsh_profile.hpp).
#include "hpcontact/io/gmsh_profile.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "hpcontact/io/gmsh_import.hpp"
#include "hpcontact/io/schema_check.hpp"
#include "hpcontact/io/yaml_limits.hpp"

namespace hpcontact::io {
namespace {

using Point = std::array<double, 2>;

/// One line element of the chain: its ends and, for a second-order line, its midside node.
struct Link {
  int a = 0, b = 0, mid = 0;
};

std::vector<Link> group_lines(const GmshMesh& mesh, const std::string& group) {
  std::vector<Link> links;
  for (const GmshLine& line : mesh.lines)
    if (std::find(line.groups.begin(), line.groups.end(), group) != line.groups.end())
      links.push_back({line.ends[0], line.ends[1], line.midside});
  if (links.empty())
    throw GmshOptionError("curve", "no line elements of a 1D physical group '" + group + "' in " +
                                       mesh.file + " (defined: " + gmsh_group_list(mesh, 1) + ")");
  return links;
}

/// " at (x, y)" of a node of the file, for messages; empty if it has none.
std::string position_text(const GmshMesh& mesh, int tag) {
  const auto it = mesh.nodes.find(tag);
  if (it == mesh.nodes.end()) return "";
  std::ostringstream os;
  os << " at (" << it->second[0] << ", " << it->second[1] << ")";
  return os.str();
}

/// The node tags of the chain in walking order (a midside node's tag negated), in the direction
/// links[0] runs from a to b; a closed chain starts at links[0].a.
std::vector<int> walk(const std::vector<Link>& links, const GmshMesh& mesh, const std::string& group,
                      bool& closed) {
  std::map<int, std::vector<int>> at;  // node tag -> the links that end there
  for (int k = 0; k < static_cast<int>(links.size()); ++k) {
    at[links[k].a].push_back(k);
    at[links[k].b].push_back(k);
  }
  std::vector<int> ends;
  for (const auto& [node, ks] : at) {
    if (ks.size() > 2)
      throw GmshOptionError("curve", "the lines of '" + group + "' in " + mesh.file + " branch: " +
                                         std::to_string(ks.size()) + " of them meet at node " +
                                         std::to_string(node) + position_text(mesh, node) +
                                         " (an obstacle's boundary is one chain)");
    if (ks.size() == 1) ends.push_back(node);
  }
  closed = ends.empty();
  std::vector<char> used(links.size(), 0);
  std::vector<int> order;
  // Along link k from `node`: its midside node and its other end.
  auto follow = [&](int k, int node) {
    used[k] = 1;
    const Link& l = links[k];
    if (l.mid) order.push_back(-l.mid);
    const int next = l.a == node ? l.b : l.a;
    order.push_back(next);
    return next;
  };
  int node = closed ? links[0].a : ends[0];
  order.push_back(node);
  if (closed) node = follow(0, node);
  for (bool more = true; more;) {
    more = false;
    for (int k : at[node])
      if (!used[k]) {
        node = follow(k, node);
        more = true;
        break;
      }
  }
  if (std::find(used.begin(), used.end(), 0) != used.end())
    throw GmshOptionError("curve", "the lines of '" + group + "' in " + mesh.file +
                                       " are not one chain: they fall into pieces");
  if (closed) {
    order.pop_back();  // back at the start
    return order;
  }
  const auto position = [&](int tag) { return std::find(order.begin(), order.end(), tag) - order.begin(); };
  if (position(links[0].b) < position(links[0].a)) std::reverse(order.begin(), order.end());
  return order;
}

/// Leaves out the points where the path goes straight on.
std::vector<Point> corners_only(const std::vector<Point>& p, bool closed, int& left_out) {
  const int n = static_cast<int>(p.size());
  std::vector<Point> kept;
  left_out = 0;
  for (int i = 0; i < n; ++i) {
    if (!closed && (i == 0 || i == n - 1)) {
      kept.push_back(p[i]);
      continue;
    }
    const Point& a = p[(i - 1 + n) % n];
    const Point& c = p[(i + 1) % n];
    const double ux = p[i][0] - a[0], uy = p[i][1] - a[1], vx = c[0] - p[i][0], vy = c[1] - p[i][1];
    const double turn = std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
    if (std::abs(turn) < 1e-9) {
      ++left_out;
      continue;
    }
    kept.push_back(p[i]);
  }
  return kept;
}

}  // namespace

GmshPath gmsh_path(const GmshMesh& mesh, const std::string& group, bool reverse) {
  const std::vector<Link> links = group_lines(mesh, group);
  GmshPath path;
  path.lines = static_cast<int>(links.size());
  std::vector<int> order = walk(links, mesh, group, path.closed);
  if (reverse) std::reverse(path.closed ? order.begin() + 1 : order.begin(), order.end());
  std::vector<Point> points;
  for (int tag : order) {
    const auto it = mesh.nodes.find(std::abs(tag));
    if (it == mesh.nodes.end())
      throw GmshOptionError("curve", "node " + std::to_string(std::abs(tag)) + " of a line of '" +
                                         group + "' is not in " + mesh.file + "'s $Nodes");
    points.push_back(it->second);
  }
  path.points = corners_only(points, path.closed, path.straight_on);
  return path;
}

}  // namespace hpcontact::io

namespace hpcontact::io {
namespace {

YAML::Node points_node(const std::vector<std::array<double, 2>>& points) {
  YAML::Node list(YAML::NodeType::Sequence);
  for (const auto& p : points) list.push_back(point_node(p));
  list.SetStyle(YAML::EmitterStyle::Flow);
  return list;
}

/// Replaces one obstacle's gmsh section by its points (see expand_gmsh_obstacles).
std::string expand_one(YAML::Node obstacle, const std::string& path, YamlSource& source) {
  const YAML::Node& view = obstacle;
  const std::string gmsh_path_key = path + ".gmsh";
  refuse_second_gmsh_key(view, gmsh_path_key, source);
  const YAML::Node g = view["gmsh"];
  check_and_fill_defaults(g, "contact[].obstacle.gmsh", gmsh_path_key, source);
  const YAML::Node type = view["type"];
  const std::string kind = type && type.IsScalar() ? type.Scalar() : "";
  if (kind != "profile" && kind != "curve")
    source.fail(g, gmsh_path_key,
                "gives the points of a profile or curve obstacle (got type: " +
                    (kind.empty() ? std::string("none") : kind) + ")");
  if (view["points"])
    source.fail(view["points"], path + ".points", "give either gmsh or points, not both");
  const GmshMesh mesh = read_gmsh_section(g, gmsh_path_key, source);
  const std::string group = g["curve"].Scalar();
  GmshPath chain;
  try {
    chain = gmsh_path(mesh, group, g["reverse"].as<bool>());
  } catch (const GmshOptionError& e) {
    source.fail(g[e.key], gmsh_path_key + "." + e.key, e.what_text);
  }
  if (chain.closed && kind == "curve")
    source.fail(g["curve"], gmsh_path_key + ".curve",
                "the lines of '" + group + "' in " + mesh.file +
                    " close on themselves, and a curve obstacle is open: use type: profile "
                    "(closed) or a group that does not close");
  if (const YAML::Node closed = view["closed"]; closed && closed.IsScalar()) {
    const bool given = closed.Scalar() == "true";
    if (given != chain.closed)
      source.fail(closed, path + ".closed",
                  std::string("the lines of '") + group + "' in " + mesh.file +
                      (chain.closed ? " close on themselves" : " do not close") + ": leave closed out (it follows the chain)");
  }
  if (count_yaml_values(view) + 3 * chain.points.size() > kMaxYamlValues)
    source.fail(g, gmsh_path_key, "the chain of '" + group + "' has more points than an input may have");
  obstacle.remove("gmsh");
  obstacle["points"] = points_node(chain.points);
  if (chain.closed && kind == "profile") obstacle["closed"] = true;
  return path + ": " + kind + " of " + mesh.file + ", curve '" + group + "': " +
         std::to_string(chain.points.size()) + " points from " + std::to_string(chain.lines) +
         " lines" + (chain.straight_on ? " (" + std::to_string(chain.straight_on) +
                                             " where it goes straight on left out)" : "") +
         (chain.closed ? ", closed" : "");
}

}  // namespace

std::vector<std::string> expand_gmsh_obstacles(YAML::Node& root, YamlSource& source) {
  std::vector<std::string> notes;
  const YAML::Node& view = root;
  const YAML::Node contact = view["contact"];
  if (!contact || !contact.IsSequence()) return notes;  // the schema check reports it
  for (std::size_t i = 0; i < contact.size(); ++i) {
    YAML::Node pair = contact[i];
    const YAML::Node& pair_view = pair;
    if (!pair.IsMap() || !pair_view["obstacle"] || !pair_view["obstacle"].IsMap()) continue;
    YAML::Node obstacle = pair["obstacle"];
    const YAML::Node& obstacle_view = obstacle;
    if (!obstacle_view["gmsh"]) continue;
    notes.push_back(expand_one(obstacle, join_key(join_index("contact", i), "obstacle"), source));
  }
  return notes;
}

}  // namespace hpcontact::io
