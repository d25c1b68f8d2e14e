// Problem file -> YAML tree -> overrides -> gmsh meshes expanded -> schema check with defaults ->
// cross-checked ProblemSpec.
#include "hpcontact/io/problem_reader.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <optional>
#include <memory>
#include <set>
#include <sstream>
#include <utility>

#include "hpcontact/core/error.hpp"
#include "hpcontact/geometry/profile.hpp"
#include "hpcontact/io/gmsh_import.hpp"
#include "hpcontact/io/gmsh_profile.hpp"
#include "hpcontact/io/overrides.hpp"
#include "hpcontact/io/schema_check.hpp"
#include "hpcontact/io/solid_reader.hpp"
#include "hpcontact/io/text_file.hpp"
#include "hpcontact/io/yaml_limits.hpp"
#include "hpcontact/io/yaml_source.hpp"

namespace hpcontact::io {

namespace {

using namespace hpcontact::model;

// The tree has passed check_and_fill_defaults(), so these conversions cannot fail.
double number(const YAML::Node& node) { return *to_number(node); }
int integer(const YAML::Node& node) { return *to_integer(node); }
bool boolean(const YAML::Node& node) { return *to_boolean(node); }
std::array<double, 2> point(const YAML::Node& node) { return {number(node[0]), number(node[1])}; }
std::array<int, 2> node_pair(const YAML::Node& node) {
  return {integer(node[0]), integer(node[1])};
}
std::array<int, 2> degree(const YAML::Node& node) {
  if (node.IsScalar()) return {integer(node), integer(node)};
  return node_pair(node);
}

/// An edge regardless of orientation: the two node ids, smaller first.
using Edge = std::pair<int, int>;
Edge undirected(std::array<int, 2> nodes) {
  return {std::min(nodes[0], nodes[1]), std::max(nodes[0], nodes[1])};
}

std::string shown_pair(std::array<int, 2> nodes) {
  std::ostringstream os;
  os << '[' << nodes[0] << ", " << nodes[1] << ']';
  return os.str();
}

/// Builds the ProblemSpec from a checked tree, checking the cross references the schema cannot.
class SpecBuilder {
 public:
  explicit SpecBuilder(const YamlSource& source) : source_(source) {}

  ProblemSpec problem(const YAML::Node& root) {
    ProblemSpec spec;
    spec.file = source_.file();
    spec.case_name = root["case"].Scalar();
    if (root["description"]) spec.description = root["description"].Scalar();
    std::map<std::string, std::string> body_paths;  // name -> path of the body that has it
    for (std::size_t i = 0; i < root["bodies"].size(); ++i) {
      const std::string path = join_index("bodies", i);
      spec.bodies.push_back(body(root["bodies"][i], path));
      const auto [at, inserted] = body_paths.emplace(spec.bodies.back().name, path);
      if (!inserted)
        source_.fail(root["bodies"][i]["name"], path + ".name",
                     "name already used by " + at->second + " (got '" + at->first + "')");
    }
    spec.discretization = discretization(root["discretization"]);
    spec.solver = solver(root["solver"]);
    if (root["contact"]) spec.contact = contact(root["contact"], "contact", spec.bodies);
    require_penetration_pairs(root, spec);
    if (root["exact"]) spec.exact = exact(root["exact"], spec.bodies);
    if (root["adapt"]) spec.adapt = adapt(root["adapt"], spec);
    // Goal-oriented degrees spend fewer dofs for an accuracy in the trunk space than in the
    // tensor product space (examples/hertz/CONVERGENCE.md): its default there, for plane bodies.
    // (An axisymmetric ball on a flat at a/R = 0.2 made the contact Newton cycle in the trunk
    // space on the hp meshes, at any force; the tensor space solves it. With friction the trunk
    // loop on examples/partial-slip/hp-tolerance.yaml needs fewer DOF for its tolerance but takes
    // 5-12 times as long, the friction's active set settling slowly: docs/theory.md.)
    const bool axisymmetric = std::any_of(spec.bodies.begin(), spec.bodies.end(), [](const BodySpec& b) {
      return b.material.plane == PlaneMode::axisymmetric;
    });
    const bool friction = std::any_of(spec.contact.begin(), spec.contact.end(), [](const ContactPairSpec& c) {
      return c.friction.law != "none";
    });
    if (!root["discretization"]["space"] && spec.adapt.method == AdaptMethod::hp &&
        spec.adapt.degree == HpDegree::goal && !axisymmetric && !friction)
      spec.discretization.space = ShapeSpace::trunk;
    spec.output = output(root["output"]);
    require_bounded_work(spec, root);
    return spec;
  }

 private:
  /// Keys whose values multiply into the work of a run are bounded together (each alone has its
  /// schema bound): unknowns ~ elements × 2(p+1)², quadrature points ~ elements ×
  /// (p + quadrature_extra)², contact points ~ contact edges × quadrature, VTU points ~ elements ×
  /// (subdivisions + 1)². Refused before anything is built, naming the keys and the limit.
  void require_bounded_work(const ProblemSpec& spec, const YAML::Node& root) {
    const auto& disc = spec.discretization;
    double unknowns = 0, gauss_points = 0, vtu_points = 0, contact_points = 0;
    for (const auto& b : spec.bodies)
      for (std::size_t q = 0; q < b.elements.size(); ++q) {
        std::array<int, 2> p = b.degree.value_or(disc.degree);
        if (const auto it = b.element_degrees.find(b.element_ids[q]); it != b.element_degrees.end())
          p = it->second;
        if (disc.method == Method::h) p = {2, 2};
        const double pmax = std::max(p[0], p[1]);
        unknowns += 2.0 * (p[0] + 1) * (p[1] + 1);
        gauss_points += (pmax + disc.quadrature_extra) * (pmax + disc.quadrature_extra);
        const double s = spec.output.vtu_subdivisions > 0 ? spec.output.vtu_subdivisions
                                                          : std::clamp(pmax, 2.0, 16.0);
        vtu_points += (s + 1) * (s + 1);
      }
    for (const auto& pair : spec.contact) {
      double edges = 0;
      for (const auto& b : spec.bodies)
        if (b.name == pair.body)
          for (const auto& set : b.edge_sets)
            if (std::find(pair.edge_sets.begin(), pair.edge_sets.end(), set.name) !=
                pair.edge_sets.end())
              edges += static_cast<double>(set.edges.size());
      // Two bodies: the other side's edges get as many points.
      contact_points += edges * pair.quadrature * (pair.obstacle.kind == ObstacleKind::body ? 2 : 1);
    }
    auto require = [&](double value, double limit, const YAML::Node& node, const std::string& path,
                       const std::string& what, const std::string& why) {
      if (value <= limit) return;
      std::ostringstream os;
      os << std::setprecision(3) << what << " come to " << value << ", more than the " << limit
         << " a run may have: " << why;
      source_.fail(node, path, os.str());
    };
    require(unknowns, kMaxUnknowns, root["discretization"], "discretization",
            "the elements' modes (elements × 2(p_xi+1)(p_eta+1), the bound of the unknowns)",
            "the sparse factorisation of that many high-order unknowns needs more memory than a "
            "workstation has; use fewer elements or lower degrees");
    require(gauss_points, kMaxQuadraturePoints, root["discretization"]["quadrature_extra"],
            "discretization.quadrature_extra",
            "the quadrature points (elements × (p + quadrature_extra)²)",
            "every assembly evaluates the shape functions at each; lower quadrature_extra or the "
            "degree");
    if (!spec.contact.empty())
      require(contact_points, kMaxContactPoints, root["contact"], "contact",
              "the contact Gauss points (contact edges × contact[].quadrature)",
              "every Newton iteration intersects each with the other side; lower "
              "contact[].quadrature");
    if (spec.adapt.method == AdaptMethod::hp) {
      // The smallest elements are factor^steps of the first ones; below kMinHpScale their arcs
      // span less than the geometry resolves (arc angles of 1e-12).
      const double scale = std::pow(spec.adapt.factor, spec.adapt.steps);
      if (scale < kMinHpScale) {
        int most = 0;
        while (std::pow(spec.adapt.factor, most + 1) >= kMinHpScale) ++most;
        std::ostringstream os;
        os << std::setprecision(3) << "the smallest elements after " << spec.adapt.steps
           << " steps at adapt.factor " << spec.adapt.factor << " are " << scale
           << " of the first ones, below the " << kMinHpScale
           << " the geometry resolves: at most " << most << " steps at this factor";
        const YAML::Node at = root["adapt"]["steps"] ? root["adapt"]["steps"] : root["adapt"]["factor"];
        source_.fail(at ? at : root["adapt"], "adapt.steps", os.str());
      }
    }
    if (spec.output.vtu)
      require(vtu_points, kMaxVtuPoints, root["output"]["vtu_subdivisions"],
              "output.vtu_subdivisions", "the points of solution.vtu (elements × (subdivisions + 1)²)",
              "each takes ~300 bytes of ASCII; lower output.vtu_subdivisions or set output.vtu: "
              "false");
  }

  BodySpec body(const YAML::Node& node, const std::string& path) {
    BodySpec b;
    b.name = node["name"].Scalar();
    b.where = source_.where(node, path);
    b.material = material(node["material"], path + ".material");
    for (const char* key : {"nodes", "elements"})
      if (!node[key])
        source_.fail(node, path,
                     std::string("missing required key '") + key +
                         "' (a body needs nodes and elements, or gmsh)");
    read_mesh(node, path, b);
    if (node["curves"]) read_curves(node["curves"], path + ".curves", b);
    if (node["degree"]) b.degree = degree(node["degree"]);
    if (node["degrees"]) read_element_degrees(node["degrees"], path + ".degrees", b);
    if (node["regions"]) read_regions(node["regions"], path + ".regions", b);
    if (node["edge_sets"]) read_edge_sets(node["edge_sets"], path + ".edge_sets", b);
    if (node["constraints"]) read_constraints(node["constraints"], path + ".constraints", b);
    if (node["loads"]) read_loads(node["loads"], path + ".loads", b);
    if (node["nodal_forces"]) read_nodal_forces(node["nodal_forces"], path + ".nodal_forces", b);
    b.body_force = point(node["body_force"]);
    return b;
  }

  MaterialSpec material(const YAML::Node& node, const std::string& path) {
    MaterialSpec m;
    m.model = node["model"].Scalar();
    require_constants(node, path, m.model);
    const auto constant = [&](const char* key) { return node[key] ? number(node[key]) : 0.0; };
    m.youngs_modulus = constant("E");
    m.poisson_ratio = constant("nu");
    m.C10 = constant("C10");
    m.C01 = constant("C01");
    m.C20 = constant("C20");
    m.C30 = constant("C30");
    m.K = constant("K");
    read_formulation(node, path, m);
    const std::string plane = node["plane"].Scalar();
    m.plane = plane == "stress"         ? PlaneMode::plane_stress
              : plane == "axisymmetric" ? PlaneMode::axisymmetric
                                        : PlaneMode::plane_strain;
    m.thickness = node["thickness"] ? number(node["thickness"]) : 1.0;
    if (m.plane == PlaneMode::axisymmetric && node["thickness"])
      source_.fail(node["thickness"], path + ".thickness",
                   "does not apply to an axisymmetric body: its integrals are over the whole "
                   "circle, 2 pi r per unit area of the section");
    m.where = source_.where(node, path);
    return m;
  }

  /// A rubber law's incompressible and formulation (the schema checks their values): only a
  /// rubber law takes them, and incompressible needs the mixed element.
  void read_formulation(const YAML::Node& node, const std::string& path, MaterialSpec& m) {
    const bool rubber = m.model == "neo-hooke-split" || m.model == "mooney-rivlin" || m.model == "yeoh";
    m.incompressible = node["incompressible"] && boolean(node["incompressible"]);
    for (const char* key : {"incompressible", "formulation"})
      if (node[key] && !rubber && (m.incompressible || std::string(key) == "formulation"))
        source_.fail(node[key], path + "." + key,
                     "is for the rubber laws (neo-hooke-split, mooney-rivlin, yeoh), not model " + m.model);
    m.formulation = node["formulation"] ? node["formulation"].Scalar()
                    : m.incompressible   ? "mixed"
                                         : "displacement";
    if (m.incompressible && m.formulation != "mixed")
      source_.fail(node["formulation"], path + ".formulation",
                   "displacement cannot hold J = 1 (incompressible: true): use formulation: mixed, or "
                   "a finite K instead of incompressible");
  }

  /// Each constant the model takes is given, and no other (the schema checks their ranges); an
  /// incompressible rubber law takes no K.
  void require_constants(const YAML::Node& node, const std::string& path, const std::string& model) {
    const bool incompressible = node["incompressible"] && to_boolean(node["incompressible"]).value_or(false);
    const char* K = incompressible ? nullptr : "K";
    std::vector<std::string> takes = model == "neo-hooke-split" ? std::vector<std::string>{"C10"}
                                     : model == "mooney-rivlin" ? std::vector<std::string>{"C10", "C01"}
                                     : model == "yeoh" ? std::vector<std::string>{"C10", "C20", "C30"}
                                                       : std::vector<std::string>{"E", "nu"};
    if (K && takes.front() == "C10") takes.push_back(K);
    std::string list;
    for (const auto& key : takes) list += (list.empty() ? "" : ", ") + key;
    for (const char* key : {"E", "nu", "C10", "C01", "C20", "C30", "K"}) {
      const bool taken = std::find(takes.begin(), takes.end(), key) != takes.end();
      if (taken && !node[key])
        source_.fail(node, path, std::string("missing required key '") + key + "' (model " + model +
                                     " takes " + list + ")");
      if (!taken && node[key] && std::string(key) == "K" && incompressible)
        source_.fail(node[key], path + ".K", "is not taken with incompressible: true (1/K = 0): "
                     "give one of the two");
      if (!taken && node[key])
        source_.fail(node[key], path + "." + key,
                     "is not a constant of model " + model + " (it takes " + list + ")");
    }
  }

  /// Nodes and elements in the file's order; element corners must be existing nodes.
  void read_mesh(const YAML::Node& node, const std::string& path, BodySpec& b) {
    node_ids_.clear();
    element_ids_.clear();
    edges_.clear();
    for (auto it = node["nodes"].begin(); it != node["nodes"].end(); ++it) {
      b.node_ids.push_back(integer(it->first));
      b.nodes.push_back(point(it->second));
      node_ids_.insert(b.node_ids.back());
    }
    const std::string elements_path = path + ".elements";
    for (auto it = node["elements"].begin(); it != node["elements"].end(); ++it) {
      const std::string element_path = join_key(elements_path, it->first.Scalar());
      std::array<int, 4> corners{};
      for (std::size_t k = 0; k < 4; ++k) {
        corners[k] = integer(it->second[k]);
        require_node(it->second[k], join_index(element_path, k), corners[k], path);
      }
      for (std::size_t k = 0; k < 4; ++k)
        edges_.insert(undirected({corners[k], corners[(k + 1) % 4]}));
      b.element_ids.push_back(integer(it->first));
      b.elements.push_back(corners);
      element_ids_.insert(b.element_ids.back());
    }
  }

  void read_curves(const YAML::Node& list, const std::string& path, BodySpec& b) {
    std::map<Edge, std::string> curve_paths;  // edge -> path of the curve that replaces it
    for (std::size_t i = 0; i < list.size(); ++i) {
      const YAML::Node node = list[i];
      const std::string curve_path = join_index(path, i);
      CurveSpec c;
      const std::array<int, 2> ends = node_pair(node["nodes"]);
      require_edge(node["nodes"], curve_path + ".nodes", ends);
      const auto [at, inserted] = curve_paths.emplace(undirected(ends), curve_path);
      if (!inserted)
        source_.fail(
            node["nodes"], curve_path + ".nodes",
            "edge already has a curve at " + at->second + " (got " + shown_pair(ends) + ")");
      c.node_a = ends[0];
      c.node_b = ends[1];
      if (bool(node["arc"]) == bool(node["parametric"]))
        source_.fail(node, curve_path,
                     std::string("must have exactly one of 'arc' and 'parametric' (got ") +
                         (node["arc"] ? "both" : "neither") + ")");
      if (const YAML::Node arc = node["arc"]) {
        c.kind = CurveKind::arc;
        c.center = point(arc["center"]);
        c.radius = number(arc["radius"]);
        c.ccw = arc["ccw"] ? (boolean(arc["ccw"]) ? 1 : -1) : 0;
      } else {
        c.kind = CurveKind::parametric;
        c.x_expr = node["parametric"]["x"].Scalar();
        c.y_expr = node["parametric"]["y"].Scalar();
      }
      c.where = source_.where(node, curve_path);
      b.curves.push_back(std::move(c));
    }
  }

  void read_regions(const YAML::Node& list, const std::string& path, BodySpec& b) {
    std::set<int> taken;
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string item = join_index(path, i);
      MaterialRegionSpec r;
      if (b.material.model != "linear-elastic" && b.material.model != "saint-venant-kirchhoff" &&
          b.material.model != "neo-hooke")
        source_.fail(list[i], item, "a body of a rubber law (" + b.material.model +
                                        ") has one set of constants: no regions");
      const YAML::Node els = list[i]["elements"];
      for (std::size_t k = 0; k < els.size(); ++k) {
        const int id = integer(els[k]);
        if (!element_ids_.count(id))
          source_.fail(els[k], item + ".elements",
                       "no such element in the body's elements (got " + std::to_string(id) + ")");
        if (!taken.insert(id).second)
          source_.fail(els[k], item + ".elements",
                       "element " + std::to_string(id) + " is already in another region");
        r.elements.push_back(id);
      }
      r.material = material(list[i]["material"], item + ".material");
      if (r.material.model != b.material.model || r.material.plane != b.material.plane)
        source_.fail(list[i]["material"], item + ".material",
                     "a region changes E and nu only: its model and plane must be the body's (" +
                         b.material.model + ")");
      r.where = source_.where(list[i], item);
      b.regions.push_back(std::move(r));
    }
  }

  void read_element_degrees(const YAML::Node& table, const std::string& path, BodySpec& b) {
    for (auto it = table.begin(); it != table.end(); ++it) {
      const int id = integer(it->first);
      if (!element_ids_.count(id))
        source_.fail(it->first, join_key(path, it->first.Scalar()),
                     "no such element in the body's elements (got " + std::to_string(id) + ")");
      b.element_degrees[id] = degree(it->second);
    }
  }

  void read_edge_sets(const YAML::Node& table, const std::string& path, BodySpec& b) {
    for (auto it = table.begin(); it != table.end(); ++it) {
      EdgeSetSpec set;
      set.name = it->first.Scalar();
      const std::string set_path = join_key(path, set.name);
      set.where = source_.where(it->second, set_path);
      std::set<Edge> seen;
      for (std::size_t k = 0; k < it->second.size(); ++k) {
        const std::array<int, 2> ends = node_pair(it->second[k]);
        const std::string edge_path = join_index(set_path, k);
        require_edge(it->second[k], edge_path, ends);
        if (!seen.insert(undirected(ends)).second)
          source_.fail(it->second[k], edge_path,
                       "edge listed twice (got " + shown_pair(ends) + ")");
        set.edges.push_back(ends);
      }
      b.edge_sets.push_back(std::move(set));
    }
  }

  void read_constraints(const YAML::Node& list, const std::string& path, BodySpec& b) {
    for (std::size_t i = 0; i < list.size(); ++i) {
      const YAML::Node node = list[i];
      const std::string item_path = join_index(path, i);
      ConstraintSpec c;
      if (!node["edges"] && !node["nodes"])
        source_.fail(node, item_path,
                     "needs 'edges', 'nodes' or both (got " + shown_value(node) + ")");
      if (!node["ux"] && !node["uy"])
        source_.fail(node, item_path, "needs 'ux', 'uy' or both (got " + shown_value(node) + ")");
      if (node["edges"]) c.edge_sets = edge_set_names(node["edges"], item_path + ".edges", b);
      if (const YAML::Node nodes = node["nodes"]) {
        for (std::size_t k = 0; k < nodes.size(); ++k) {
          c.nodes.push_back(integer(nodes[k]));
          require_node(nodes[k], join_index(item_path + ".nodes", k), c.nodes.back(),
                       body_path(path));
        }
      }
      if (node["ux"]) c.ux = node["ux"].Scalar();
      if (node["uy"]) c.uy = node["uy"].Scalar();
      c.where = source_.where(node, item_path);
      b.constraints.push_back(std::move(c));
    }
    require_single_prescription(b, list, path);
  }

  void read_loads(const YAML::Node& list, const std::string& path, BodySpec& b) {
    static const std::map<std::string, LoadShape> shapes{
        {"constant", LoadShape::constant}, {"linear", LoadShape::linear},
        {"bspline1", LoadShape::bspline1}, {"bspline2", LoadShape::bspline2},
        {"hermite", LoadShape::hermite},   {"expression", LoadShape::expression}};
    for (std::size_t i = 0; i < list.size(); ++i) {
      const YAML::Node node = list[i];
      const std::string item_path = join_index(path, i);
      EdgeLoadSpec load;
      load.edge_sets = edge_set_names(node["edges"], item_path + ".edges", b, true);
      if (bool(node["pressure"]) == bool(node["traction"]))
        source_.fail(node, item_path,
                     std::string("must have exactly one of 'pressure' and 'traction' (got ") +
                         (node["pressure"] ? "both" : "neither") + ")");
      if (node["pressure"]) {
        load.kind = LoadKind::pressure;
        load.value = {number(node["pressure"]), 0.0};
      } else {
        load.kind = LoadKind::traction;
        load.value = point(node["traction"]);
      }
      if (node["resultant"]) load.resultant = number(node["resultant"]);
      load.shape = shapes.at(node["shape"].Scalar());
      const bool is_expression = load.shape == LoadShape::expression;
      if (is_expression && !node["expression"])
        source_.fail(node, item_path, "missing key 'expression' (required by shape: expression)");
      if (!is_expression && node["expression"])
        source_.fail(
            node["expression"], item_path + ".expression",
            "only allowed with shape: expression (got shape: " + node["shape"].Scalar() + ")");
      if (is_expression) load.expression = node["expression"].Scalar();
      load.along = node["along"].Scalar()[0];
      if (node["interval"]) {
        load.interval = point(node["interval"]);
        if ((*load.interval)[0] == (*load.interval)[1])
          source_.fail(node["interval"], item_path + ".interval",
                       "start and end must differ (got " + shown_value(node["interval"]) + ")");
      }
      load.follower = boolean(node["follower"]);
      if (load.follower && load.kind != LoadKind::pressure)
        source_.fail(node["follower"], item_path + ".follower",
                     "a follower load is a pressure (normal to the deformed boundary); a traction "
                     "keeps its direction (got traction with follower: true)");
      if (const YAML::Node pen = node["penetration"]) {
        if (!load.follower)
          source_.fail(pen, item_path + ".penetration",
                       "pressure penetration moves with the contact zone on the deformed boundary: "
                       "it needs follower: true (got follower: false)");
        load.penetration = EdgeLoadSpec::Penetration{integer(pen["contact"]), pen["from"].Scalar() == "end",
                                                     source_.where(pen, item_path + ".penetration")};
      }
      load.where = source_.where(node, item_path);
      b.edge_loads.push_back(std::move(load));
    }
  }

  /// Each penetrating load names an existing contact pair that has edges of the load's body
  /// among the load's edges (as its own or as its obstacle's).
  void require_penetration_pairs(const YAML::Node& root, const ProblemSpec& spec) {
    for (std::size_t i = 0; i < spec.bodies.size(); ++i) {
      const BodySpec& b = spec.bodies[i];
      for (std::size_t j = 0; j < b.edge_loads.size(); ++j) {
        const auto& pen = b.edge_loads[j].penetration;
        if (!pen) continue;
        const std::string path = join_index(join_index("bodies", i) + ".loads", j) + ".penetration.contact";
        const YAML::Node node = root["bodies"][i]["loads"][j]["penetration"]["contact"];
        if (pen->contact >= static_cast<int>(spec.contact.size()))
          source_.fail(node, path, "no such contact pair (the problem has " +
                                       std::to_string(spec.contact.size()) + ") (got " +
                                       std::to_string(pen->contact) + ")");
        const ContactPairSpec& c = spec.contact[pen->contact];
        std::vector<std::string> pair_sets;
        if (c.body == b.name) pair_sets = c.edge_sets;
        if (c.obstacle.kind == ObstacleKind::body && c.obstacle.body == b.name)
          pair_sets.insert(pair_sets.end(), c.obstacle.edge_sets.begin(), c.obstacle.edge_sets.end());
        if (!shares_an_edge(b, pair_sets, b.edge_loads[j].edge_sets))
          source_.fail(node, path, "contact[" + std::to_string(pen->contact) + "] has none of the "
                       "load's edges on body '" + b.name + "': the pressure stops where that pair's "
                       "contact starts on the loaded edges, so the pair must share some of them");
      }
    }
  }

  /// Whether an edge (either direction) lies in one of the sets `a` and one of the sets `b`.
  static bool shares_an_edge(const BodySpec& body, const std::vector<std::string>& a,
                             const std::vector<std::string>& b) {
    std::set<std::pair<int, int>> in_a;
    for (const auto& set : body.edge_sets)
      if (std::find(a.begin(), a.end(), set.name) != a.end())
        for (const auto& e : set.edges) in_a.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});
    for (const auto& set : body.edge_sets)
      if (std::find(b.begin(), b.end(), set.name) != b.end())
        for (const auto& e : set.edges)
          if (in_a.count({std::min(e[0], e[1]), std::max(e[0], e[1])})) return true;
    return false;
  }

  void read_nodal_forces(const YAML::Node& list, const std::string& path, BodySpec& b) {
    for (std::size_t i = 0; i < list.size(); ++i) {
      const YAML::Node node = list[i];
      const std::string item_path = join_index(path, i);
      NodalForceSpec f;
      f.node = integer(node["node"]);
      require_node(node["node"], item_path + ".node", f.node, body_path(path));
      f.force = point(node["force"]);
      f.where = source_.where(node, item_path);
      b.nodal_forces.push_back(std::move(f));
    }
  }

  /// The edge set names of a constraint or load, each one defined in the body.
  /// The edge set names of a list; each must exist and be named once. With `each_edge_once` (a
  /// load, a contact side: what an edge contributes would count twice) no edge may be in two of
  /// the sets.
  std::vector<std::string> edge_set_names(const YAML::Node& list, const std::string& path,
                                          const BodySpec& b, bool each_edge_once = false) {
    std::vector<std::string> names;
    std::map<Edge, std::string> set_of;  // edge -> the listed set that has it
    for (std::size_t k = 0; k < list.size(); ++k) {
      if (std::find(names.begin(), names.end(), list[k].Scalar()) != names.end())
        source_.fail(list[k], join_index(path, k),
                     "edge set listed twice (got '" + list[k].Scalar() + "')" +
                         (each_edge_once ? ": its edges would count twice" : ""));
      names.push_back(list[k].Scalar());
      const bool defined =
          std::any_of(b.edge_sets.begin(), b.edge_sets.end(),
                      [&](const EdgeSetSpec& set) { return set.name == names.back(); });
      if (!defined) {
        std::string known;
        for (const EdgeSetSpec& set : b.edge_sets) known += (known.empty() ? "" : ", ") + set.name;
        source_.fail(list[k], join_index(path, k),
                     "no such edge set (defined: " + (known.empty() ? "none" : known) + ") (got '" +
                         names.back() + "')");
      }
      if (!each_edge_once) continue;
      for (const EdgeSetSpec& set : b.edge_sets) {
        if (set.name != names.back()) continue;
        for (const auto& e : set.edges) {
          const auto [at, inserted] = set_of.emplace(undirected(e), set.name);
          if (!inserted)
            source_.fail(list[k], join_index(path, k),
                         "the edge " + shown_pair(e) + " of edge set '" + set.name +
                             "' is in edge set '" + at->second +
                             "' too: it would count twice (got '" + set.name + "')");
        }
      }
    }
    return names;
  }

  /// Two constraints of a body may not prescribe the same component on the same edge or node:
  /// one of them would silently win.
  void require_single_prescription(const BodySpec& b, const YAML::Node& list,
                                   const std::string& path) {
    std::map<std::pair<std::string, int>, std::size_t> first;  // (what, component) -> constraint
    for (std::size_t i = 0; i < b.constraints.size(); ++i) {
      const ConstraintSpec& c = b.constraints[i];
      std::vector<std::string> places;
      for (const auto& name : c.edge_sets)
        for (const EdgeSetSpec& set : b.edge_sets)
          if (set.name == name)
            for (const auto& e : set.edges) {
              const Edge u = undirected(e);
              places.push_back("edge " + shown_pair({u.first, u.second}));
            }
      for (int n : c.nodes) places.push_back("node " + std::to_string(n));
      std::sort(places.begin(), places.end());
      places.erase(std::unique(places.begin(), places.end()), places.end());
      for (int comp = 0; comp < 2; ++comp) {
        if (!(comp == 0 ? c.ux : c.uy)) continue;
        for (const auto& place : places) {
          const auto [at, inserted] = first.emplace(std::make_pair(place, comp), i);
          if (!inserted)
            source_.fail(list[i], join_index(path, i),
                         std::string("prescribes ") + (comp == 0 ? "ux" : "uy") + " on " + place +
                             ", which " + join_index(path, at->second) +
                             " prescribes already (one of them would silently win)");
        }
      }
    }
  }

  void require_node(const YAML::Node& node, const std::string& path, int id,
                    const std::string& body) {
    if (!node_ids_.count(id))
      source_.fail(node, path,
                   "no such node in " + body + ".nodes (got " + std::to_string(id) + ")");
  }

  void require_edge(const YAML::Node& node, const std::string& path, std::array<int, 2> ends) {
    if (!edges_.count(undirected(ends)))
      source_.fail(node, path, "not an edge of any element (got " + shown_pair(ends) + ")");
  }

  /// "bodies[0]" from "bodies[0].constraints".
  static std::string body_path(const std::string& list_path) {
    return list_path.substr(0, list_path.rfind('.'));
  }

  DiscretizationSpec discretization(const YAML::Node& node) {
    DiscretizationSpec d;
    d.method = node["method"].Scalar() == "h" ? Method::h : Method::p;
    d.degree = degree(node["degree"]);
    d.space = node["space"] && node["space"].Scalar() == "trunk" ? ShapeSpace::trunk
                                                                 : ShapeSpace::tensor_product;
    const std::string element = node["element"].Scalar();
    d.element = element == "Q4"   ? LagrangeElement::q4
                : element == "Q9" ? LagrangeElement::q9
                                  : LagrangeElement::q8;
    d.quadrature_extra = integer(node["quadrature_extra"]);
    d.condense = boolean(node["condense"]);
    d.where = source_.where(node, "discretization");
    return d;
  }

  AdaptSpec adapt(const YAML::Node& node, const ProblemSpec& spec) {
    AdaptSpec a;
    a.where = source_.where(node, "adapt");
    const std::string method = node["method"].Scalar();
    a.method = method == "rp" ? AdaptMethod::rp : method == "hp" ? AdaptMethod::hp : AdaptMethod::none;
    // With a tolerance the loop is asked for accuracy, not for the seed's mesh: the factor that
    // measured fewest DOF per accuracy (examples/hertz/CONVERGENCE.md), steps as the most.
    const bool to_tolerance = a.method == AdaptMethod::hp && node["tolerance"];
    a.factor = node["factor"] ? number(node["factor"]) : to_tolerance ? 0.15 : 0.5;
    a.steps = node["steps"] ? integer(node["steps"]) : to_tolerance ? 12 : 8;
    // As many as the geometry resolves at this factor, when the loop chose the number.
    if (to_tolerance && !node["steps"])
      while (a.steps > 1 && std::pow(a.factor, a.steps) < kMinHpScale) --a.steps;
    // With a tolerance the estimate's solve is there to weigh each element's share of the
    // error: the degrees follow it (examples/hertz/CONVERGENCE.md).
    const std::string rule = node["degree"] ? node["degree"].Scalar() : to_tolerance ? "goal" : "rising";
    a.degree = rule == "goal" ? HpDegree::goal : rule == "constant" ? HpDegree::constant : HpDegree::rising;
    if (a.degree == HpDegree::goal && a.method == AdaptMethod::hp && !node["tolerance"])
      source_.fail(node["degree"], "adapt.degree",
                   "goal corrects the degrees with the error estimate of each step, which only a loop "
                   "to adapt.tolerance computes: give a tolerance, or degree rising");
    a.min_degree = integer(node["min_degree"]);
    if (a.method == AdaptMethod::hp && a.degree != HpDegree::constant && a.min_degree < 2)
      for (size_t b = 0; b < spec.bodies.size(); ++b)
        if (spec.bodies[b].material.formulation == "mixed")
          source_.fail(node["min_degree"], "adapt.min_degree",
                       "bodies[" + std::to_string(b) + "] has the mixed element, whose pressure of "
                       "degree p - 1 needs p >= 2: give adapt.min_degree: 2");
    if (const YAML::Node t = node["tolerance"]) {
      a.tolerance = number(t);
      a.tolerance_given = true;
      if (a.method == AdaptMethod::hp && a.tolerance >= 1)
        source_.fail(t, "adapt.tolerance",
                     "hp reads the tolerance as the relative accuracy of the contact pressure, "
                     "which lies in (0, 1): 1e-3 asks for 0.1 %");
    }
    a.max_dofs = integer(node["max_dofs"]);
    a.max_iterations = integer(node["max_iterations"]);
    a.secant = node["update"].Scalar() == "secant";
    a.stick_slip = boolean(node["stick_slip"]);
    if (a.method != AdaptMethod::none && spec.contact.empty())
      source_.fail(node["method"], "adapt.method",
                   method + " adapts the mesh to the ends of contact zones, but the problem has no contact");
    if (a.method != AdaptMethod::none && spec.discretization.method != Method::p)
      source_.fail(node["method"], "adapt.method",
                   method + " needs the p-version (discretization.method: p)");
    return a;
  }

  SolverSpec solver(const YAML::Node& node) {
    SolverSpec s;
    s.linear = node["linear"].Scalar();
    s.tangent = node["tangent"].Scalar();
    s.load_steps = integer(node["load_steps"]);
    s.max_iterations = integer(node["max_iterations"]);
    s.tolerance = number(node["tolerance"]);
    s.max_cuts = integer(node["max_cuts"]);
    s.line_search = node["line_search"].Scalar();
    s.control = node["control"].Scalar();
    if (const YAML::Node m = node["monitor"]) {
      s.monitor_body = m["body"].Scalar();
      s.monitor_node = integer(m["node"]);
    }
    if (s.control == "arc-length" && node["stages"])
      source_.fail(node["stages"], "solver.stages",
                   "control: arc-length finds its own load path (loads only); stages are for load control");
    if (s.control == "arc-length" && node["target_resultant"])
      source_.fail(node["target_resultant"], "solver.target_resultant",
                   "control: arc-length scales the loads, target_resultant the prescribed displacements");
    if (const YAML::Node target = node["target_resultant"]) {
      TargetResultantSpec t;
      t.value = number(target["value"]);
      t.component = target["component"].Scalar() == "x" ? 0 : 1;
      t.tolerance = number(target["tolerance"]);
      s.target_resultant = t;
    }
    if (const YAML::Node stages = node["stages"]) {
      for (std::size_t i = 0; i < stages.size(); ++i) {
        LoadStageSpec st;
        const YAML::Node stage = stages[i];
        const std::string at = "solver.stages[" + std::to_string(i) + "]";
        if (stage["displacements"]) st.displacements = number(stage["displacements"]);
        if (stage["displacements_x"]) st.x_displacements = number(stage["displacements_x"]);
        if (stage["displacements_y"]) st.y_displacements = number(stage["displacements_y"]);
        if (stage["displacements"] && st.x_displacements && st.y_displacements)
          source_.fail(stage["displacements"], at + ".displacements",
                       "displacements_x and displacements_y are both given, so displacements "
                       "applies to no direction; remove it (or one of them)");
        st.loads = number(stages[i]["loads"]);
        if (stages[i]["steps"]) st.steps = integer(stages[i]["steps"]);
        s.stages.push_back(st);
      }
      // Under force control a stage's displacements is the share of the target resultant
      // reached at its end (the factor on the displacements is the unknown): one share for all
      // directions, not negative, the last one the target itself.
      if (s.target_resultant)
        for (std::size_t i = 0; i < stages.size(); ++i) {
          const std::string at = "solver.stages[" + std::to_string(i) + "]";
          const LoadStageSpec& st = s.stages[i];
          if (st.x_displacements || st.y_displacements)
            source_.fail(stages[i][st.x_displacements ? "displacements_x" : "displacements_y"],
                         at + (st.x_displacements ? ".displacements_x" : ".displacements_y"),
                         "under solver.target_resultant a stage's displacements is the share of the "
                         "target force it reaches, one for all directions (the factor on the "
                         "prescribed displacements is found): use displacements");
          if (st.displacements < 0)
            source_.fail(stages[i]["displacements"], at + ".displacements",
                         "under solver.target_resultant this is the share of the target force the "
                         "stage reaches, not negative");
          if (i + 1 == stages.size() && st.displacements != 1.0)
            source_.fail(stages[i]["displacements"] ? stages[i]["displacements"] : stages[i],
                         at + ".displacements",
                         "under solver.target_resultant the last stage reaches the target force: "
                         "its displacements (the share of the target) must be 1");
        }
    }
    s.where = source_.where(node, "solver");
    return s;
  }

  /// The contact pairs; each names an existing body and edge sets of that body.
  /// The body a scalar node names; an error listing the defined bodies otherwise.
  const BodySpec& body_named(const YAML::Node& node, const std::string& path,
                             const std::vector<BodySpec>& bodies) {
    const std::string name = node.Scalar();
    const auto it = std::find_if(bodies.begin(), bodies.end(),
                                 [&](const BodySpec& b) { return b.name == name; });
    if (it == bodies.end()) {
      std::string known;
      for (const BodySpec& b : bodies) known += (known.empty() ? "" : ", ") + b.name;
      source_.fail(node, path, "no such body (defined: " + known + ") (got '" + name + "')");
    }
    return *it;
  }

  std::vector<ContactPairSpec> contact(const YAML::Node& list, const std::string& path,
                                       const std::vector<BodySpec>& bodies) {
    std::vector<ContactPairSpec> pairs;
    for (std::size_t i = 0; i < list.size(); ++i) {
      const YAML::Node node = list[i];
      const std::string item_path = join_index(path, i);
      ContactPairSpec c;
      c.body = node["body"].Scalar();
      const BodySpec& body = body_named(node["body"], item_path + ".body", bodies);
      c.edge_sets = edge_set_names(node["edges"], item_path + ".edges", body, true);
      c.obstacle = obstacle(node["obstacle"], item_path + ".obstacle", bodies, c.body);
      c.enforcement = node["enforcement"].Scalar() == "augmented-lagrangian"
                          ? Enforcement::augmented_lagrangian
                          : Enforcement::penalty;
      const std::string rule = node["constraint"].Scalar();
      c.constraint = rule == "collocation" ? ConstraintRule::collocation
                     : rule == "mortar"    ? ConstraintRule::mortar
                                           : ConstraintRule::automatic;
      const std::string normal = node["normal"] ? node["normal"].Scalar() : "auto";
      c.mean_normal = normal == "mean";
      if (c.mean_normal && c.obstacle.kind != ObstacleKind::body)
        source_.fail(node["normal"], item_path + ".normal",
                     "mean is the mean of two bodies' normals; against a rigid obstacle the "
                     "obstacle's normal is the only one (normal: other)");
      if (c.mean_normal && c.enforcement == Enforcement::penalty)
        source_.fail(node["normal"], item_path + ".normal",
                     "mean applies to augmented-lagrangian (exact) enforcement; the penalty "
                     "measures its gaps along the other body's normal");
      c.ramp_interference = node["interference"].Scalar() == "ramp";
      if (c.ramp_interference && c.enforcement == Enforcement::penalty)
        source_.fail(node["interference"], item_path + ".interference",
                     "ramp applies to augmented-lagrangian (exact) enforcement; the penalty "
                     "takes an overlap of the input as a penetration from the start");
      c.auto_carrier = node["carrier"].Scalar() == "auto";
      if (c.auto_carrier && (c.obstacle.kind != ObstacleKind::body || c.enforcement == Enforcement::penalty))
        source_.fail(node["carrier"], item_path + ".carrier",
                     "auto chooses which of two bodies carries the multipliers of exact "
                     "(augmented-lagrangian) enforcement; " +
                         std::string(c.obstacle.kind != ObstacleKind::body
                                         ? "against a rigid obstacle the body carries them"
                                         : "the penalty has none and treats both bodies alike"));
      if (node["penalty"]) c.penalty = number(node["penalty"]);
      else if (c.enforcement == Enforcement::penalty)
        source_.fail(node, item_path, "missing key 'penalty' (required by enforcement: penalty)");
      c.quadrature = integer(node["quadrature"]);
      if (const YAML::Node cmp = node["compare"]) {
        PressureCompareSpec pc;
        if (cmp["radius"]) pc.radius = number(cmp["radius"]);
        if (cmp["other_radius"]) pc.other_radius = number(cmp["other_radius"]);
        if (cmp["force"]) pc.force = number(cmp["force"]);
        if (cmp["reference"]) pc.reference = cmp["reference"].Scalar();
        pc.where = source_.where(cmp, item_path + ".compare");
        if (c.auto_carrier)
          source_.fail(node["carrier"], item_path + ".carrier",
                       "auto may swap body and obstacle, and compare's closed forms and reference "
                       "are measured along the obstacle as written: name the carrier as `body` "
                       "(as-written)");
        c.compare = pc;
      }
      if (const YAML::Node fr = node["friction"]) {
        c.friction.law = fr["law"].Scalar();
        if (fr["mu"]) c.friction.mu = number(fr["mu"]);
        c.friction.where = source_.where(fr, item_path + ".friction");
        if (c.friction.law == "coulomb" && !fr["mu"])
          source_.fail(fr, item_path + ".friction", "missing key 'mu' (required by law: coulomb)");
        if (c.friction.law != "none" && !fr["penalty"] && c.enforcement == Enforcement::penalty)
          source_.fail(fr, item_path + ".friction",
                       "missing key 'penalty' (the tangential penalty eps_T, required by law: " +
                           c.friction.law + " with enforcement: penalty)");
        if (fr["penalty"]) c.friction.penalty = number(fr["penalty"]);
        // auto: friction between two bodies, exactly enforced, presses along the mean normal,
        // under which mirror-image bodies hold each other without a tangential traction
        // (mortar: the two-body default; collocated nodes facing the other body's vertices
        // would take their foot at a corner, where the mean normal turns by the kink)
        if (normal == "auto" && c.friction.law != "none" && c.obstacle.kind == ObstacleKind::body &&
            c.enforcement == Enforcement::augmented_lagrangian && c.constraint != ConstraintRule::collocation)
          c.mean_normal = true;
      }
      if (const YAML::Node nd = node["normal_direction"]) {
        const auto v = point(nd);
        const double largest = std::max(std::abs(v[0]), std::abs(v[1]));
        if (largest == 0)
          source_.fail(nd, item_path + ".normal_direction",
                       "must be non-zero (got " + shown_value(nd) + ")");
        const double length = std::hypot(v[0] / largest, v[1] / largest);
        c.normal_direction = {v[0] / largest / length, v[1] / largest / length};
      }
      c.where = source_.where(node, item_path);
      pairs.push_back(std::move(c));
    }
    return pairs;
  }

  /// Keys with a default that mean nothing for an obstacle of this type, refused when given a
  /// value other than the default (the effective input lists every default): obstacle.point but
  /// for a plane, a curve or a profile, normal but for a plane, center and inside but for a
  /// circle, fillet and closed but for a profile.
  void refuse_inapplicable(const YAML::Node& node, const std::string& path, ObstacleKind kind,
                           const std::string& type) {
    struct Key {
      const char* name;
      std::array<double, 2> standard;
      bool applies;
    };
    const Key keys[] = {
        {"point", {0, 0}, kind == ObstacleKind::plane || kind == ObstacleKind::curve || kind == ObstacleKind::profile},
        {"normal", {0, 1}, kind == ObstacleKind::plane},
        {"center", {0, 0}, kind == ObstacleKind::circle},
    };
    for (const Key& k : keys)
      if (!k.applies && point(node[k.name]) != k.standard)
        source_.fail(node[k.name], path + "." + k.name,
                     "does nothing for type: " + type + " (it applies to " +
                         (std::string(k.name) == "point" ? "plane, curve and profile" : std::string(k.name) == "normal" ? "plane" : "circle") +
                         " obstacles); leave it out (got " + shown_value(node[k.name]) + ")");
    if (kind != ObstacleKind::circle && boolean(node["inside"]))
      source_.fail(node["inside"], path + ".inside",
                   "does nothing for type: " + type + " (it applies to circle obstacles); leave it out");
    if (kind != ObstacleKind::profile && boolean(node["closed"]))
      source_.fail(node["closed"], path + ".closed",
                   "does nothing for type: " + type + " (it applies to profile obstacles); leave it out");
    const YAML::Node& fillet = node["fillet"];
    if (kind != ObstacleKind::profile && (fillet.IsSequence() || number(fillet) != 0))
      source_.fail(fillet, path + ".fillet",
                   "does nothing for type: " + type + " (it applies to profile obstacles); leave it out (got " +
                       shown_value(fillet) + ")");
  }

  /// A profile's fillets (one number for every corner, or one per corner) and closure, checked
  /// with its points by geometry::profile_fault: a fault names the point or fillet at fault.
  void read_profile(const YAML::Node& node, const std::string& path, ObstacleSpec& o) {
    o.closed = boolean(node["closed"]);
    const YAML::Node& fillet = node["fillet"];
    const int n = static_cast<int>(o.points.size());
    const int corners = o.closed ? n : std::max(n - 2, 0);
    if (fillet.IsSequence()) {
      for (std::size_t j = 0; j < fillet.size(); ++j) o.fillets.push_back(number(fillet[j]));
    } else if (const double r = number(fillet); r > 0) {
      o.fillets.assign(corners, r);
    }
    geometry::ProfileSpec spec;
    for (const auto& p : o.points) spec.points.emplace_back(p[0], p[1]);
    spec.fillets = o.fillets;
    spec.closed = o.closed;
    const auto fault = geometry::profile_fault(spec);
    if (!fault) return;
    const YAML::Node& list = node[fault->key];
    const bool entry = fault->index >= 0 && list.IsSequence();
    source_.fail(entry ? list[fault->index] : list,
                 path + "." + fault->key + (entry ? "[" + std::to_string(fault->index) + "]" : ""),
                 fault->cause);
  }

  ObstacleSpec obstacle(const YAML::Node& node, const std::string& path,
                        const std::vector<BodySpec>& bodies, const std::string& self) {
    ObstacleSpec o;
    const std::string type = node["type"].Scalar();
    o.kind = type == "circle" ? ObstacleKind::circle
             : type == "curve" ? ObstacleKind::curve
             : type == "profile" ? ObstacleKind::profile
             : type == "body"  ? ObstacleKind::body
                               : ObstacleKind::plane;
    for (const char* key : {"body", "edges"}) {
      if (o.kind == ObstacleKind::body && !node[key])
        source_.fail(node, path, std::string("missing key '") + key + "' (required by type: body)");
      if (o.kind != ObstacleKind::body && node[key])
        source_.fail(node[key], path + "." + key,
                     "only allowed with type: body (got type: " + type + ")");
    }
    if (o.kind == ObstacleKind::body) {
      o.body = node["body"].Scalar();
      const BodySpec& other = body_named(node["body"], path + ".body", bodies);
      if (o.body == self)
        source_.fail(node["body"], path + ".body",
                     "must be another body than the contact's own (got '" + o.body + "')");
      o.edge_sets = edge_set_names(node["edges"], path + ".edges", other, true);
    }
    o.point = point(node["point"]);
    o.normal = point(node["normal"]);
    refuse_inapplicable(node, path, o.kind, type);
    // Normalised; scaled by its largest component first so that huge components cannot overflow.
    const double largest = std::max(std::abs(o.normal[0]), std::abs(o.normal[1]));
    if (largest == 0)
      source_.fail(node["normal"], path + ".normal",
                   "must be non-zero (got " + shown_value(node["normal"]) + ")");
    o.normal = {o.normal[0] / largest, o.normal[1] / largest};
    const double length = std::hypot(o.normal[0], o.normal[1]);
    o.normal = {o.normal[0] / length, o.normal[1] / length};
    o.center = point(node["center"]);
    o.displacement = point(node["displacement"]);
    if (o.kind == ObstacleKind::body && (o.displacement[0] != 0 || o.displacement[1] != 0))
      source_.fail(node["displacement"], path + ".displacement",
                   "a body obstacle moves with its own constraints; displacement is for rigid "
                   "obstacles (type: plane, circle, curve or profile)");
    const bool is_circle = o.kind == ObstacleKind::circle;
    if (is_circle && !node["radius"])
      source_.fail(node, path, "missing key 'radius' (required by type: circle)");
    if (!is_circle && node["radius"])
      source_.fail(node["radius"], path + ".radius",
                   "only allowed with type: circle (got type: " + node["type"].Scalar() + ")");
    if (is_circle) o.radius = number(node["radius"]);
    o.inside = boolean(node["inside"]);
    const bool has_points = o.kind == ObstacleKind::curve || o.kind == ObstacleKind::profile;
    if (has_points && !node["points"])
      source_.fail(node, path, "missing key 'points' (required by type: " + type + ")");
    if (!has_points && node["points"])
      source_.fail(node["points"], path + ".points",
                   "only allowed with type: curve or profile (got type: " + type + ")");
    if (o.kind == ObstacleKind::profile) {
      for (const YAML::Node& p : node["points"]) o.points.push_back(point(p));
      read_profile(node, path, o);
    }
    if (o.kind == ObstacleKind::curve) {
      const YAML::Node& points = node["points"];
      for (std::size_t i = 0; i < points.size(); ++i) o.points.push_back(point(points[i]));
      for (std::size_t i = 1; i < o.points.size(); ++i)
        if (o.points[i] == o.points[i - 1])
          source_.fail(points[i], path + ".points[" + std::to_string(i) + "]",
                       "repeats the point before it (" + shown_value(points[i]) +
                           "): consecutive points of a curve must differ");
    }
    return o;
  }

  /// lame is the thick cylinder of plane bodies, lame_sphere the thick sphere of axisymmetric
  /// ones (its meridian section): the other pairing is refused, naming the body.
  ExactSpec exact(const YAML::Node& node, const std::vector<BodySpec>& bodies) {
    ExactSpec e;
    e.where = source_.where(node, "exact");
    if (node["type"].Scalar() == "none") return e;
    e.type = node["type"].Scalar();
    const bool sphere = e.type == "lame_sphere";
    for (std::size_t i = 0; i < bodies.size(); ++i)
      if ((bodies[i].material.plane == PlaneMode::axisymmetric) != sphere)
        source_.fail(node["type"], "exact.type",
                     sphere ? "lame_sphere is the thick sphere of an axisymmetric body, and " +
                                  join_index("bodies", i) + " is plane (use lame)"
                            : "lame is the thick cylinder of a plane body, and " +
                                  join_index("bodies", i) +
                                  " is axisymmetric (use lame_sphere for the thick sphere)");
    for (const char* key : {"inner_radius", "outer_radius"})
      if (!node[key])
        source_.fail(node, "exact",
                     std::string("missing key '") + key + "' (required by type: " + e.type + ")");
    e.inner_radius = number(node["inner_radius"]);
    e.outer_radius = number(node["outer_radius"]);
    if (e.outer_radius <= e.inner_radius)
      source_.fail(node["outer_radius"], "exact.outer_radius",
                   "must be > exact.inner_radius = " + node["inner_radius"].Scalar() + " (got " +
                       node["outer_radius"].Scalar() + ")");
    e.inner_pressure = number(node["inner_pressure"]);
    e.outer_pressure = number(node["outer_pressure"]);
    e.center = point(node["center"]);
    if (sphere && e.center[0] != 0)
      source_.fail(node["center"], "exact.center",
                   "the centre of a sphere of revolution lies on the axis r = 0 (got " +
                       shown_value(node["center"]) + ")");
    return e;
  }

  OutputSpec output(const YAML::Node& node) {
    OutputSpec o;
    o.vtu = boolean(node["vtu"]);
    o.steps = boolean(node["steps"]);
    o.vtu_subdivisions = integer(node["vtu_subdivisions"]);
    o.effective_input = boolean(node["effective_input"]);
    o.where = source_.where(node, "output");
    return o;
  }

  const YamlSource& source_;
  // The body being read: its node ids, element ids and element edges.
  std::set<int> node_ids_, element_ids_;
  std::set<Edge> edges_;
};

std::string effective_yaml(const YAML::Node& root, const std::string& file_label,
                           const std::vector<std::string>& overrides,
                           const std::vector<std::string>& gmsh_notes) {
  std::string text = "# Effective input of " + file_label + ", defaults filled in";
  text += overrides.empty() ? ".\n" : ", with:\n";
  for (const std::string& o : overrides) text += "#   --set " + o + "\n";
  for (const std::string& note : gmsh_notes) text += "#   " + one_line(note, 400) + "\n";
  YAML::Emitter out;
  out << root;
  return text + out.c_str() + "\n";
}

}  // namespace

ReadResult parse_problem_full(const std::string& yaml_text, const std::string& file_label,
                              const std::vector<std::string>& overrides) {
  YamlSource source(file_label);
  YAML::Node root = load_yaml_map(yaml_text, file_label, "problem file",
                                  "a YAML map of sections (case:, bodies:, ...)");
  try {
    // Each value is bounded by what the tree leaves it; an alias repeats a replaced node
    // wherever it stands, so the tree is counted again after each.
    std::size_t values = overrides.empty() ? 0 : count_yaml_values(root);
    for (const std::string& o : overrides) {
      apply_override(root, o, source, values);
      values = count_yaml_values(root);
      if (values > kMaxYamlValues)
        throw CommandLineError(file_label + ": --set " + one_line(o, 40) + ": the problem has " +
                               std::to_string(values) + " YAML values with it, more than the " +
                               std::to_string(kMaxYamlValues) +
                               " an input may have: give fewer or smaller --set values");
    }
    const bool solid = is_solid_problem(root);
    std::vector<std::string> gmsh_notes =
        solid ? std::vector<std::string>{} : expand_gmsh_meshes(root, source);
    if (!solid)
      for (std::string& note : expand_gmsh_obstacles(root, source)) gmsh_notes.push_back(std::move(note));
    std::optional<model::ProblemSpec> solid_spec;
    if (solid)
      solid_spec = solid_problem(root, source);
    else
      check_and_fill_defaults(root, source);
    // The effective input is read back as a problem file (a run reproduced from its own
    // output), so it is held to the same bounds, with its defaults.
    const std::string effective =
        ": the effective input (input.yaml, the problem with its defaults filled in) ";
    if (const std::size_t effective_values = count_yaml_values(root); effective_values > kMaxYamlValues)
      throw InputError(file_label + effective + "has " + std::to_string(effective_values) +
                       " YAML values, more than the " + std::to_string(kMaxYamlValues) +
                       " a problem file may have, so it could not be read back: give fewer "
                       "elements");
    ReadResult read{solid_spec ? std::move(*solid_spec) : SpecBuilder(source).problem(root),
                    effective_yaml(root, file_label, overrides, gmsh_notes)};
    if (read.effective_yaml.size() > kMaxYamlBytes)
      throw InputError(file_label + effective + "is larger than the " +
                       in_megabytes(kMaxYamlBytes) + " a problem file may have (" +
                       in_megabytes(read.effective_yaml.size()) +
                       "), so it could not be read back: give fewer elements or shorter texts");
    return read;
  } catch (const YAML::Exception& e) {
    // The checks above should leave yaml-cpp nothing to object to; if it does, keep the promise
    // that bad input surfaces as a one-line InputError.
    throw InputError(file_label + ": " + one_line(e.what(), 200));
  }
}

std::string read_input_file(const std::string& path) {
  return read_bounded_file(path, "problem file", kMaxYamlBytes);
}

ReadResult read_problem_full(const std::string& path, const std::vector<std::string>& overrides) {
  return parse_problem_full(read_input_file(path), path, overrides);
}

model::ProblemSpec parse_problem(const std::string& yaml_text, const std::string& file_label,
                                 const std::vector<std::string>& overrides) {
  return parse_problem_full(yaml_text, file_label, overrides).spec;
}

model::ProblemSpec read_problem(const std::string& path,
                                const std::vector<std::string>& overrides) {
  return read_problem_full(path, overrides).spec;
}

}  // namespace hpcontact::io
