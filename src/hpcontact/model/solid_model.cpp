// One hexahedral body: its mesh from a generator, its modes, constraints, loads and solve.
#include "hpcontact/model/solid_model.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>

#include "hpcontact/core/error.hpp"
#include "hpcontact/fem/hex_assembly.hpp"
#include "hpcontact/fem/hex_face_load.hpp"
#include "hpcontact/geometry/blending_hex.hpp"
#include "hpcontact/mesh/hex_box.hpp"
#include "hpcontact/mesh/shell_octant.hpp"
#include "hpcontact/solve/fixed_dofs.hpp"

namespace hpcontact::model {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// A box of nx × ny × nz equal trilinear hexahedra, face sets x0 … z1 (mesh/hex_box.hpp).
mesh::HexMesh box_mesh(const Point3& from, const Point3& to, std::array<int, 3> n,
                       const std::string& context) {
  mesh::HexMesh m = mesh::hex_box_mesh(mesh::Vec3(from[0], from[1], from[2]),
                                       mesh::Vec3(to[0], to[1], to[2]), n);
  m.context = context;
  return m;
}

mesh::HexMesh shell_mesh(const SolidMeshSpec& s, const std::string& context) {
  mesh::HexMesh m = mesh::shell_octant_mesh(s.inner_radius, s.outer_radius, s.layers);
  m.context = context;
  return m;
}

/// The faces of a constraint's or load's sets, each once.
std::vector<mesh::ElementFace> faces_of(const mesh::HexMesh& m,
                                        const std::vector<std::string>& sets) {
  std::vector<mesh::ElementFace> faces;
  for (const auto& name : sets) {
    const auto it = m.face_sets.find(name);
    HPC_REQUIRE(it != m.face_sets.end(), InputError, m.context, ": no face set '", name, "'");
    for (const auto& f : it->second)
      if (std::find(faces.begin(), faces.end(), f) == faces.end()) faces.push_back(f);
  }
  return faces;
}

/// Whether local edge le of a hexahedron lies on local face lf.
bool edge_on_face(int le, int lf) {
  const auto& f = basis::kHexFaceVertices[lf];
  const auto on = [&](int v) { return std::find(std::begin(f), std::end(f), v) != std::end(f); };
  return on(basis::kHexEdgeVertices[le][0]) && on(basis::kHexEdgeVertices[le][1]);
}

geometry::SurfacePtr make_surface(const SurfaceSpec& s) {
  const mesh::Vec3 p(s.point[0], s.point[1], s.point[2]);
  if (s.sphere) return std::make_shared<geometry::Sphere>(p, s.radius);
  return std::make_shared<geometry::Cylinder>(p, mesh::Vec3(s.axis[0], s.axis[1], s.axis[2]),
                                              s.radius);
}

/// Gives every element with a face in a surface's sets the blending map that puts the face on
/// the surface. Refused (InputError naming the element and the surface's key): a face in two
/// surfaces' sets, vertices off the surface (blending_hex), an element that shares an edge with
/// a face on a surface without a face of its own there (its edge would stay straight while its
/// neighbour's is curved: a gap in the body).
void put_faces_on_surfaces(mesh::HexMesh& m, const std::vector<SurfaceSpec>& surfaces) {
  const int n = m.topology.n_hexes();
  std::vector<std::array<geometry::SurfacePtr, 6>> on(n);
  std::map<const geometry::Surface*, const SurfaceSpec*> spec_of;
  for (const SurfaceSpec& s : surfaces) {
    const geometry::SurfacePtr surface = make_surface(s);
    spec_of[surface.get()] = &s;
    for (const auto& [h, lf] : faces_of(m, s.faces)) {
      HPC_REQUIRE(!on[h][lf] || on[h][lf] == surface, InputError, s.where.str(), ": face ", lf,
                  " of element ", h, " of ", m.context, " is also in the sets of ",
                  spec_of[on[h][lf].get()]->where.key, ": a face lies on one surface");
      on[h][lf] = surface;
    }
  }
  std::map<int, const geometry::Surface*> curved_edge;  // global edge -> its surface
  for (int h = 0; h < n; ++h)
    for (int lf = 0; lf < 6; ++lf)
      if (on[h][lf])
        for (int le = 0; le < 12; ++le)
          if (edge_on_face(le, lf)) curved_edge[m.topology.hex_edge(h, le)] = on[h][lf].get();
  for (int h = 0; h < n; ++h) {
    bool curved = false;
    for (int le = 0; le < 12; ++le) {
      const auto it = curved_edge.find(m.topology.hex_edge(h, le));
      if (it == curved_edge.end()) continue;
      bool own = false;
      for (int lf = 0; lf < 6; ++lf) own = own || (on[h][lf].get() == it->second && edge_on_face(le, lf));
      HPC_REQUIRE(own, InputError, spec_of[it->second]->where.str(), ": element ", h, " of ",
                  m.context, " shares an edge with a face on this surface but has no face in its "
                  "sets: its edge would stay straight beside its neighbour's curved one (add its "
                  "face to the set, or mesh so that the surface is met by faces only)");
      curved = true;
    }
    if (!curved) continue;
    std::array<mesh::Vec3, 8> vertices;
    for (int c = 0; c < 8; ++c) vertices[c] = m.nodes[m.topology.hex(h)[c]];
    // messages name the input key of (the first of) the element's surfaces
    const geometry::Surface* first = nullptr;
    for (int lf = 0; lf < 6 && !first; ++lf) first = on[h][lf].get();
    const std::string context = spec_of[first]->where.str() + ": element " + std::to_string(h) +
                                " of the mesh" + (m.nodes.empty() ? "" : "");
    m.maps[h] = mesh::HexMap::blending(geometry::blending_hex(vertices, on[h], context.c_str()));
  }
}

mesh::Vec3 traction_of(const FaceLoadSpec& load) {
  return mesh::Vec3((*load.traction)[0], (*load.traction)[1], (*load.traction)[2]);
}

/// A surface load as given (before any scaling): each face's element load vector.
struct FaceLoads {
  std::vector<std::pair<int, Eigen::VectorXd>> faces;  ///< element, its load (component-blocked)
  /// ∫ t dA: the vertex modes sum to one (basis/hex_modes.hpp: local modes 0..7), so their
  /// entries of the load vectors sum to the load's integral.
  mesh::Vec3 resultant() const {
    mesh::Vec3 total = mesh::Vec3::Zero();
    for (const auto& [h, f] : faces)
      for (int c = 0; c < 3; ++c) total(c) += f.segment(c * (f.size() / 3), 8).sum();
    return total;
  }
  /// Σ |vertex entries|: the scale against which a resultant is zero.
  double magnitude() const {
    double sum = 0;
    for (const auto& [h, f] : faces)
      for (int c = 0; c < 3; ++c) sum += f.segment(c * (f.size() / 3), 8).cwiseAbs().sum();
    return sum;
  }
};

FaceLoads face_loads(const SolidDiscretization& d, const FaceLoadSpec& load) {
  FaceLoads out;
  for (const auto& [h, lf] : faces_of(d.mesh, load.faces)) {
    const fem::HexElementSpace& space = d.dofs.element(h);
    const int n_points = fem::hex_face_gauss_points(space.hierarchic, d.mesh.maps[h], lf);
    out.faces.emplace_back(
        h, load.pressure ? fem::hex_face_pressure_load(space.hierarchic, d.mesh.maps[h], lf,
                                                       *load.pressure, n_points)
                         : fem::hex_face_traction_load(space.hierarchic, d.mesh.maps[h], lf,
                                                       traction_of(load), n_points));
  }
  return out;
}

/// 1, or the factor that gives the load the resultant asked for; refused where it vanishes.
double load_scale(const FaceLoads& loads, const FaceLoadSpec& load) {
  if (!load.resultant) return 1.0;
  const double total = loads.resultant().norm(), magnitude = loads.magnitude();
  HPC_REQUIRE(total > 1e-9 * magnitude, InputError, load.where.str(),
              ": the load's integral over its faces vanishes (", total, " of ", magnitude,
              "), so no scale gives it the resultant asked for");
  return *load.resultant / total;
}

}  // namespace

mesh::HexMesh solid_mesh(const SolidMeshSpec& spec, const std::string& context) {
  switch (spec.kind) {
    case SolidMeshKind::box: return box_mesh(spec.from, spec.to, spec.elements, context);
    case SolidMeshKind::shell_octant: return shell_mesh(spec, context);
    case SolidMeshKind::gmsh: break;
  }
  mesh::HexMesh m = *spec.imported;
  m.context = context + " (" + m.context + ")";
  return m;
}

SolidDiscretization discretize_solid(const SolidSpec& spec, const std::string& file) {
  const std::string context = file + ": body '" + spec.body.name + "'";
  mesh::HexMesh m = solid_mesh(spec.body.mesh, context);
  put_faces_on_surfaces(m, spec.body.surfaces);
  fem::HexSpaceOptions options;
  options.space = spec.tensor_space ? basis::Space::tensor_product : basis::Space::trunk;
  options.degrees.assign(m.topology.n_hexes(), spec.degree);
  fem::HexDofMap dofs(m.topology, options);
  material::LinearElastic law;
  law.youngs_modulus = spec.body.youngs_modulus;
  law.poisson_ratio = spec.body.poisson_ratio;

  // dof -> (value, the constraint that set it)
  std::map<int, std::pair<double, const FaceConstraintSpec*>> prescribed;
  for (const FaceConstraintSpec& c : spec.body.constraints)
    for (const auto& [h, lf] : faces_of(m, c.faces)) {
      const int face = m.topology.hex_face(h, lf);
      const auto& corners = m.topology.face(face).vertices;
      for (int mode : dofs.modes_on_face(m.topology, face)) {
        const bool vertex = std::any_of(corners.begin(), corners.end(),
                                        [&](int v) { return dofs.vertex_mode(v) == mode; });
        for (int k = 0; k < 3; ++k) {
          if (!c.u[k]) continue;
          const double value = vertex ? *c.u[k] : 0.0;
          const auto [at, inserted] = prescribed.emplace(3 * mode + k, std::make_pair(value, &c));
          const SourceRef& other = at->second.second->where;
          HPC_REQUIRE(inserted || at->second.first == value, InputError, c.where.str(), ": gives u",
                      "xyz"[k], " = ", value, " on faces where ", other.key, " (line ",
                      other.line, ") gives ", at->second.first, ": a node cannot move by both");
        }
      }
    }
  SolidDiscretization d{std::move(m), std::move(dofs), law, {}, {}};
  for (const auto& [dof, value] : prescribed) {
    d.fixed.push_back(dof);
    d.fixed_values.push_back(value.first);
  }
  return d;
}

Eigen::VectorXd element_coefficients(const SolidDiscretization& d, int element,
                                     const Eigen::VectorXd& u) {
  const fem::HexElementSpace& space = d.dofs.element(element);
  const int n = space.n_modes();
  Eigen::VectorXd u_e(3 * n);
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < n; ++a) u_e(c * n + a) = u(3 * space.modes[a] + c);
  return u_e;
}

SolidSolution solve_solid(const SolidSpec& spec, const SolidDiscretization& d,
                          const std::string& file) {
  SolidSolution sol;
  const auto t0 = Clock::now();
  fem::HexBody body;
  body.dofs = &d.dofs;
  body.maps = d.mesh.maps;
  body.material = d.material;
  body.body_force = mesh::Vec3(spec.body.body_force[0], spec.body.body_force[1],
                               spec.body.body_force[2]);
  body.context = d.mesh.context;
  fem::HexSystem system = fem::assemble_hex_elasticity(body, {.condense_internal = true});
  // Surface loads: face modes are external, so they keep their numbers in the condensed system.
  for (const FaceLoadSpec& load : spec.body.loads) {
    const FaceLoads loads = face_loads(d, load);
    const double scale = load_scale(loads, load);
    for (const auto& [h, f] : loads.faces) {
      const fem::HexElementSpace& space = d.dofs.element(h);
      const int n = space.n_modes();
      for (int local = 0; local < 3 * n; ++local)
        if (f(local) != 0) system.f(3 * space.modes[local % n] + local / n) += scale * f(local);
    }
  }
  sol.assembly_seconds = seconds_since(t0);
  sol.n_system = static_cast<int>(system.K.rows()) - static_cast<int>(d.fixed.size());
  const auto t1 = Clock::now();
  const Eigen::VectorXd values =
      Eigen::Map<const Eigen::VectorXd>(d.fixed_values.data(), d.fixed_values.size());
  Eigen::VectorXd u_external;
  try {
    u_external = solve::solve_with_fixed_dofs(system.K, system.f, d.fixed, values).col(0);
  } catch (const NumericalError& e) {
    throw NumericalError(file + ": body '" + spec.body.name +
                         "': the stiffness cannot be factorised — is the body held against every "
                         "rigid motion (three translations, three rotations)? (" + e.what() + ")");
  }
  sol.u = system.recover(d.dofs, u_external);
  sol.solve_seconds = seconds_since(t1);
  return sol;
}

}  // namespace hpcontact::model
