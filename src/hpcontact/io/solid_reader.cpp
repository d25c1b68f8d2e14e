// A 3D problem file's tree into a ProblemSpec: conversions and the cross references.
#include "hpcontact/io/solid_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "hpcontact/core/error.hpp"
#include "hpcontact/io/gmsh_hex_import.hpp"
#include "hpcontact/io/gmsh_import.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/io/schema_check.hpp"
#include "hpcontact/io/solid_schema.hpp"

namespace hpcontact::io {

namespace {

using namespace hpcontact::model;

// The tree has passed check_and_fill_defaults(), so these conversions cannot fail.
double number(const YAML::Node& node) { return *to_number(node); }
int integer(const YAML::Node& node) { return *to_integer(node); }
Point3 point3(const YAML::Node& node) {
  return {number(node[0]), number(node[1]), number(node[2])};
}
/// n or [n_x, n_y, n_z].
std::array<int, 3> integers3(const YAML::Node& node) {
  if (node.IsScalar()) return {integer(node), integer(node), integer(node)};
  return {integer(node[0]), integer(node[1]), integer(node[2])};
}
std::vector<std::string> names(const YAML::Node& node) {
  std::vector<std::string> out;
  for (const auto& n : node) out.push_back(n.Scalar());
  return out;
}

class SolidSpecBuilder {
 public:
  explicit SolidSpecBuilder(const YamlSource& source) : source_(source) {}

  ProblemSpec problem(const YAML::Node& root) {
    ProblemSpec spec;
    spec.file = source_.file();
    spec.case_name = root["case"].Scalar();
    if (root["description"]) spec.description = root["description"].Scalar();
    const YAML::Node bodies = root["bodies"];
    if (bodies.size() > 1)
      source_.fail(bodies[1], "bodies[1]",
                   "a 3D problem has one body (3D contact between bodies is not yet available; "
                   "got " + std::to_string(bodies.size()) + " bodies)");
    auto solid = std::make_shared<SolidSpec>();
    solid->body = body(bodies[0], "bodies[0]");
    const YAML::Node disc = root["discretization"];
    solid->degree = integers3(disc["degree"]);
    solid->tensor_space = disc["space"].Scalar() == "tensor";
    solid->where = source_.where(disc, "discretization");
    if (root["exact"]) solid->exact_strain_energy = number(root["exact"]["strain_energy"]);
    const YAML::Node out = root["output"];
    spec.output.vtu = *to_boolean(out["vtu"]);
    spec.output.vtu_subdivisions = integer(out["vtu_subdivisions"]);
    spec.output.effective_input = *to_boolean(out["effective_input"]);
    spec.output.where = source_.where(out, "output");
    require_bounded_work(*solid, root);
    spec.solid = std::move(solid);
    return spec;
  }

 private:
  SolidBodySpec body(const YAML::Node& node, const std::string& path) {
    SolidBodySpec b;
    b.name = node["name"].Scalar();
    b.youngs_modulus = number(node["material"]["E"]);
    b.poisson_ratio = number(node["material"]["nu"]);
    b.mesh = mesh(node, path);
    std::vector<std::string> sets = solid_face_set_names(b.mesh.kind);
    if (b.mesh.imported)
      for (const auto& [name, faces] : b.mesh.imported->face_sets) sets.push_back(name);
    if (const YAML::Node list = node["surfaces"])
      for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string p = join_index(path + ".surfaces", i);
        SurfaceSpec s;
        s.faces = face_sets(list[i]["faces"], p + ".faces", sets);
        const YAML::Node cylinder = list[i]["cylinder"], sphere = list[i]["sphere"];
        if (cylinder.IsDefined() == sphere.IsDefined())
          source_.fail(list[i], p, "give one of cylinder and sphere");
        s.sphere = sphere.IsDefined();
        s.point = point3(s.sphere ? sphere["centre"] : cylinder["point"]);
        if (!s.sphere) {
          s.axis = point3(cylinder["axis"]);
          if (s.axis == Point3{0, 0, 0})
            source_.fail(cylinder["axis"], p + ".cylinder.axis", "must not be zero");
        }
        s.radius = number(s.sphere ? sphere["radius"] : cylinder["radius"]);
        s.where = source_.where(list[i], p);
        b.surfaces.push_back(std::move(s));
      }
    if (const YAML::Node list = node["constraints"])
      for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string p = join_index(path + ".constraints", i);
        FaceConstraintSpec c;
        c.faces = face_sets(list[i]["faces"], p + ".faces", sets);
        const char* keys[3] = {"ux", "uy", "uz"};
        for (int k = 0; k < 3; ++k)
          if (list[i][keys[k]]) c.u[k] = number(list[i][keys[k]]);
        if (!c.u[0] && !c.u[1] && !c.u[2])
          source_.fail(list[i], p, "prescribes nothing: give ux, uy or uz");
        c.where = source_.where(list[i], p);
        b.constraints.push_back(std::move(c));
      }
    if (const YAML::Node list = node["loads"])
      for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string p = join_index(path + ".loads", i);
        FaceLoadSpec l;
        l.faces = face_sets(list[i]["faces"], p + ".faces", sets);
        if (list[i]["traction"]) l.traction = point3(list[i]["traction"]);
        if (list[i]["pressure"]) l.pressure = number(list[i]["pressure"]);
        if (list[i]["resultant"]) l.resultant = number(list[i]["resultant"]);
        if (l.traction.has_value() == l.pressure.has_value())
          source_.fail(list[i], p, "give one of traction and pressure");
        l.where = source_.where(list[i], p);
        b.loads.push_back(std::move(l));
      }
    b.body_force = point3(node["body_force"]);
    b.where = source_.where(node, path);
    return b;
  }

  SolidMeshSpec mesh(const YAML::Node& node, const std::string& path) {
    SolidMeshSpec m;
    const int given = (node["box"] ? 1 : 0) + (node["shell_octant"] ? 1 : 0) + (node["gmsh"] ? 1 : 0);
    if (given != 1)
      source_.fail(node, path,
                   given == 0 ? "has no mesh: give box, shell_octant or gmsh"
                              : "has more than one mesh: give one of box, shell_octant and gmsh");
    if (const YAML::Node box = node["box"]) {
      m.kind = SolidMeshKind::box;
      m.from = point3(box["from"]);
      m.to = point3(box["to"]);
      m.elements = integers3(box["elements"]);
      for (int k = 0; k < 3; ++k)
        if (!(m.to[k] > m.from[k]))
          source_.fail(box["to"], path + ".box.to",
                       "must be larger than from in every coordinate (coordinate " +
                           std::to_string(k) + ": " + shown_value(box["to"][k]) + " <= " +
                           shown_value(box["from"][k]) + ")");
      m.where = source_.where(box, path + ".box");
    } else if (YAML::Node g = node["gmsh"]) {
      m.kind = SolidMeshKind::gmsh;
      m.where = source_.where(g, path + ".gmsh");
      m.imported = std::make_shared<const mesh::HexMesh>(gmsh_body(g, path + ".gmsh"));
    } else {
      const YAML::Node shell = node["shell_octant"];
      m.kind = SolidMeshKind::shell_octant;
      m.inner_radius = number(shell["inner_radius"]);
      m.outer_radius = number(shell["outer_radius"]);
      m.layers = integer(shell["layers"]);
      if (!(m.outer_radius > m.inner_radius))
        source_.fail(shell["outer_radius"], path + ".shell_octant.outer_radius",
                     "must be larger than inner_radius (got " +
                         shown_value(shell["outer_radius"]) + ")");
      m.where = source_.where(shell, path + ".shell_octant");
    }
    return m;
  }

  /// The body of a gmsh section; its file is written back as an absolute path (the effective
  /// input then runs from any folder).
  mesh::HexMesh gmsh_body(YAML::Node g, const std::string& path) {
    std::filesystem::path file(g["file"].Scalar());
    if (file.is_relative()) file = std::filesystem::path(source_.file()).parent_path() / file;
    GmshVolumeMesh parsed;
    try {
      parsed = read_gmsh_volume(file.string());
    } catch (const IoError& e) {
      throw IoError(source_.where(g["file"], path + ".file").str() + ": " + e.what());
    }
    HexImportOptions options;
    if (g["volumes"]) options.volumes = names(g["volumes"]);
    mesh::HexMesh body;
    try {
      body = import_gmsh_hex_body(parsed, options);
    } catch (const GmshOptionError& e) {
      // its key is "volumes[i]"
      const std::size_t i = std::stoul(e.key.substr(e.key.find('[') + 1));
      source_.fail(g["volumes"][i], path + "." + e.key, e.what_text);
    }
    g["file"] = std::filesystem::absolute(file).lexically_normal().string();
    return body;
  }

  std::vector<std::string> face_sets(const YAML::Node& node, const std::string& path,
                                     const std::vector<std::string>& known) {
    std::vector<std::string> out = names(node);
    for (std::size_t i = 0; i < out.size(); ++i)
      if (std::find(known.begin(), known.end(), out[i]) == known.end()) {
        std::string list;
        for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
        source_.fail(node[i], join_index(path, i),
                     "no face set of that name in the body's mesh (it has: " + list + "; got '" +
                         out[i] + "')");
      }
    return out;
  }

  /// Unknowns ~ elements × 3 (p_xi + 1)(p_eta + 1)(p_zeta + 1), bounded as a 2D problem's are.
  void require_bounded_work(const SolidSpec& s, const YAML::Node& root) {
    const auto& m = s.body.mesh;
    const double elements = m.kind == SolidMeshKind::box ? double(m.elements[0]) * m.elements[1] * m.elements[2]
                            : m.kind == SolidMeshKind::gmsh ? m.imported->topology.n_hexes()
                                                            : 3.0 * m.layers;
    const double unknowns =
        elements * 3 * (s.degree[0] + 1.0) * (s.degree[1] + 1.0) * (s.degree[2] + 1.0);
    if (unknowns > kMaxUnknowns) {
      std::ostringstream os;
      os << "asks for about " << unknowns << " unknowns (" << elements
         << " elements × 3(p_xi + 1)(p_eta + 1)(p_zeta + 1)), more than the " << kMaxUnknowns
         << " a run may have: fewer elements or a lower degree";
      source_.fail(root["discretization"]["degree"], "discretization.degree", os.str());
    }
  }

  const YamlSource& source_;
};

}  // namespace

bool is_solid_problem(const YAML::Node& root) {
  const YAML::Node& tree = root;  // const: looking a key up adds nothing to the tree
  return tree.IsMap() && tree["dimension"];
}

std::vector<std::string> solid_face_set_names(SolidMeshKind kind) {
  switch (kind) {
    case SolidMeshKind::box: return {"x0", "x1", "y0", "y1", "z0", "z1"};
    case SolidMeshKind::shell_octant: return {"inner", "outer", "x0", "y0", "z0"};
    case SolidMeshKind::gmsh: break;
  }
  return {};  // the file's physical surfaces
}

ProblemSpec solid_problem(YAML::Node& root, YamlSource& source) {
  check_and_fill_defaults(root, source, solid_schema());
  return SolidSpecBuilder(source).problem(root);
}

}  // namespace hpcontact::io
