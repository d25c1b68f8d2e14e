// A 3D body from a parsed Gmsh file: the chosen volumes' hexahedra renumbered, their Lagrange
// maps (20-node hexahedra completed to 27 nodes), and face sets from the physical surfaces.
#include "hpcontact/io/gmsh_hex_import.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/io/gmsh_import.hpp"

namespace hpcontact::io {

namespace {

using mesh::Vec3;

/// A face of an element by its corner node tags, sorted; a triangle's first entry is 0 (tags
/// are >= 1).
using FaceKey = std::array<int, 4>;

FaceKey face_key(int a, int b, int c, int d = 0) {
  FaceKey key{a, b, c, d};
  std::sort(key.begin(), key.end());
  return key;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

/// The element families of Gmsh's volume types, with their corner faces (local vertex numbers
/// in Gmsh's order, which lists the vertices first at every order).
enum class Family { tetrahedron, hexahedron, prism, pyramid, unknown };

Family family(int type) {
  switch (type) {
    case 4: case 11: case 29: case 30: case 31: return Family::tetrahedron;
    case 5: case 12: case 17: case 92: case 93: return Family::hexahedron;
    case 6: case 13: case 18: return Family::prism;
    case 7: case 14: case 19: return Family::pyramid;
    default: return Family::unknown;
  }
}

/// Number of corners of a 2D element type: 3 (triangles), 4 (quadrilaterals), 0 if unknown.
int face_corners(int type) {
  switch (type) {
    case 2: case 9: case 20: case 21: case 22: case 23: case 24: case 25: return 3;
    case 3: case 10: case 16: case 36: case 37: case 38: return 4;
    default: return 0;
  }
}

/// The faces of a volume element by its node tags; none for an unknown family.
std::vector<FaceKey> element_faces(Family f, const std::vector<int>& v) {
  switch (f) {
    case Family::tetrahedron:
      return {face_key(v[0], v[1], v[2]), face_key(v[0], v[1], v[3]), face_key(v[0], v[2], v[3]),
              face_key(v[1], v[2], v[3])};
    case Family::hexahedron: {
      std::vector<FaceKey> faces;
      for (const auto& c : basis::kHexFaceVertices)
        faces.push_back(face_key(v[c[0]], v[c[1]], v[c[2]], v[c[3]]));
      return faces;
    }
    case Family::prism:  // vertices 0 1 2 at the bottom, 3 4 5 above them
      return {face_key(v[0], v[1], v[2]), face_key(v[3], v[4], v[5]),
              face_key(v[0], v[1], v[4], v[3]), face_key(v[1], v[2], v[5], v[4]),
              face_key(v[2], v[0], v[3], v[5])};
    case Family::pyramid:  // base 0 1 2 3, apex 4
      return {face_key(v[0], v[1], v[2], v[3]), face_key(v[0], v[1], v[4]),
              face_key(v[1], v[2], v[4]), face_key(v[2], v[3], v[4]), face_key(v[3], v[0], v[4])};
    case Family::unknown: break;
  }
  return {};
}

/// "120 tetrahedra (gmsh type 4)", "1 10-node tetrahedron (gmsh type 11)".
std::string counted(int type, int n_nodes, int count) {
  static const char* const names[][2] = {
      {"tetrahedron", "tetrahedra"}, {"hexahedron", "hexahedra"}, {"prism", "prisms"},
      {"pyramid", "pyramids"}};
  const Family f = family(type);
  const std::string type_text = "(gmsh type " + std::to_string(type) + ")";
  const std::string n = std::to_string(count) + " ";
  if (f == Family::unknown) return n + "volume element" + (count == 1 ? " " : "s ") + type_text;
  const bool first_order = type == 4 || type == 5 || type == 6 || type == 7;
  return n + (first_order ? "" : std::to_string(n_nodes) + "-node ") +
         names[static_cast<int>(f)][count == 1 ? 0 : 1] + " " + type_text;
}

/// "a", "a and b", "a, b and c".
std::string listed(const std::vector<std::string>& items) {
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i)
    text += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
  return text;
}

// The 27 nodes of a 20-node hexahedron (Gmsh's order: the first 20 of mesh::kHex27Nodes): its 20
// nodes, then the face centres and the centre where its serendipity map puts them,
// x(r) = sum_k N_k(r) x_k with, for node k at r_k = (xi_k, eta_k, zeta_k),
//   vertex (r_k in {-1, 1}^3):
//     N_k = (1 + xi xi_k)(1 + eta eta_k)(1 + zeta zeta_k)(xi xi_k + eta eta_k + zeta zeta_k - 2)/8,
//   mid-edge (one coordinate 0, say xi_k):  N_k = (1 - xi^2)(1 + eta eta_k)(1 + zeta zeta_k)/4.
// (At a face centre: half the sum of the face's mid-edge nodes less a quarter of its vertices';
// at the centre: a quarter of the mid-edge nodes' sum less a quarter of the vertices'.) The
// serendipity space lies in the triquadratic one, so the triquadratic map through the 27 nodes
// is the serendipity map.
std::array<Vec3, 27> complete_hex20(const std::array<Vec3, 20>& x) {
  std::array<Vec3, 27> nodes;
  std::copy(x.begin(), x.end(), nodes.begin());
  for (int n = 20; n < 27; ++n) {
    const int* r = mesh::kHex27Nodes[n];
    Vec3 p = Vec3::Zero();
    for (int k = 0; k < 20; ++k) {
      const int* c = mesh::kHex27Nodes[k];
      double N = 1;
      if (k < 8) {
        for (int d = 0; d < 3; ++d) N *= 1 + r[d] * c[d];
        N *= (r[0] * c[0] + r[1] * c[1] + r[2] * c[2] - 2) / 8.0;
      } else {
        for (int d = 0; d < 3; ++d) N *= c[d] == 0 ? 1 - r[d] * r[d] : 1 + r[d] * c[d];
        N /= 4;
      }
      p += N * x[static_cast<std::size_t>(k)];
    }
    nodes[static_cast<std::size_t>(n)] = p;
  }
  return nodes;
}

class HexImporter {
 public:
  HexImporter(const GmshVolumeMesh& mesh, const HexImportOptions& options)
      : mesh_(mesh), options_(options) {}

  mesh::HexMesh run() {
    select_elements();
    find_volume_faces();
    refuse_surface_bodies();
    make_nodes_and_maps();
    out_.topology = mesh::HexTopology(std::move(vertices_), static_cast<int>(out_.nodes.size()),
                                      mesh_.file);
    make_face_sets();
    out_.context = mesh_.file;
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail_at(int line, const std::string& what) const {
    throw InputError(mesh_.file + ":" + std::to_string(line) + ": " + what);
  }

  bool chosen(const std::vector<std::string>& groups) const {
    if (options_.volumes.empty()) return true;
    for (const std::string& v : options_.volumes)
      if (contains(groups, v)) return true;
    return false;
  }

  /// The hexahedra of the chosen volumes; any other volume element among them refused.
  void select_elements() {
    for (const GmshPhysicalGroup& g : mesh_.groups)
      if (g.dim == 3 && !contains(volume_names_, g.name)) volume_names_.push_back(g.name);
    std::string defined;
    for (const std::string& name : volume_names_) defined += (defined.empty() ? "" : ", ") + name;
    if (defined.empty()) defined = "none";
    for (std::size_t i = 0; i < options_.volumes.size(); ++i)
      if (!contains(volume_names_, options_.volumes[i]))
        throw GmshOptionError("volumes[" + std::to_string(i) + "]",
                              "no 3D physical group of that name in " + mesh_.file + " (defined: " +
                                  defined + ") (got '" + options_.volumes[i] + "')");
    std::vector<std::string> quoted;
    for (const std::string& v : options_.volumes) quoted.push_back("'" + v + "'");
    const std::string subject = options_.volumes.empty()      ? "the mesh"
                                : options_.volumes.size() == 1 ? "volume " + quoted[0]
                                                               : "volumes " + listed(quoted);

    // Other volume elements: counted by type, refused at the first.
    std::map<int, std::pair<int, int>> other;  // type -> (count, node count)
    const GmshOtherVolume* first = nullptr;
    for (const GmshOtherVolume& e : mesh_.other_volumes) {
      if (!chosen(e.groups)) continue;
      if (!first) first = &e;
      auto& [count, n_nodes] = other[e.type];
      ++count;
      n_nodes = static_cast<int>(e.nodes.size());
    }
    if (first) {
      std::vector<std::string> counts;
      bool only_hexahedra = true;  // of order 3 or more
      for (const auto& [type, c] : other) {
        counts.push_back(counted(type, c.second, c.first));
        only_hexahedra = only_hexahedra && family(type) == Family::hexahedron;
      }
      const std::string where =
          " (the first, element " + std::to_string(first->tag) + ", on this line)";
      if (only_hexahedra)
        fail_at(first->line, subject + " has " + listed(counts) + where +
                                 "; hpcontact reads hexahedra of order 1 and 2 (gmsh types 5, 12, "
                                 "17; gmsh -order 1 or 2)");
      fail_at(first->line, subject + " has " + listed(counts) + where +
                               "; hpcontact meshes 3D bodies with hexahedra only: use Recombine "
                               "and a transfinite or subdivided mesh (Transfinite Volume and "
                               "Recombine, or Mesh.SubdivisionAlgorithm = 2)");
    }
    for (const GmshHex& h : mesh_.hexes)
      if (chosen(h.groups)) hexes_.push_back(&h);
    if (hexes_.empty()) {
      if (mesh_.hexes.empty() && mesh_.other_volumes.empty())
        throw InputError(mesh_.file + ": no volume elements (" +
                         std::to_string(mesh_.quads.size()) + " quadrilaterals, " +
                         std::to_string(mesh_.other_faces.size()) +
                         " other 2D elements): a 3D body needs a volume meshed with hexahedra "
                         "(gmsh -3)");
      throw InputError(mesh_.file + ": " + subject + " has no hexahedra");
    }
  }

  /// The faces of every volume element of the file (of the chosen volumes or not), by corners.
  void find_volume_faces() {
    for (const GmshHex& h : mesh_.hexes)
      for (const FaceKey& f : element_faces(Family::hexahedron, h.nodes)) volume_faces_.insert(f);
    for (const GmshOtherVolume& e : mesh_.other_volumes) {
      const Family f = family(e.type);
      // An unknown type's vertices are unknown: which 2D elements it bounds cannot be told.
      if (f == Family::unknown) unknown_volume_faces_ = true;
      for (const FaceKey& k : element_faces(f, e.nodes)) volume_faces_.insert(k);
    }
  }

  /// Refuses a 2D entity none of whose elements is a face of a volume element: a 2D body in a
  /// file read for a 3D one.
  void refuse_surface_bodies() {
    if (unknown_volume_faces_) return;
    struct Entity {
      int n_elements = 0, first_line = 0;
      bool on_volume = false;
      std::vector<std::string> groups;
    };
    std::map<int, Entity> entities;
    const auto add = [&](int entity, int type, const std::vector<int>& corners, int line,
                         const std::vector<std::string>& groups) {
      Entity& e = entities[entity];
      if (e.n_elements++ == 0) {
        e.first_line = line;
        e.groups = groups;
      }
      const int n = face_corners(type);
      if (n == 0) e.on_volume = true;  // an unknown 2D type: not judged
      else if (!e.on_volume)
        e.on_volume = volume_faces_.count(n == 3 ? face_key(corners[0], corners[1], corners[2])
                                                 : face_key(corners[0], corners[1], corners[2],
                                                            corners[3])) > 0;
    };
    for (const GmshQuad& q : mesh_.quads)
      add(q.entity, q.type, {q.corners.begin(), q.corners.end()}, q.line, q.groups);
    for (const GmshOtherFace& f : mesh_.other_faces)
      add(f.entity, f.type, f.nodes, f.line, f.groups);
    for (const auto& [tag, e] : entities)
      if (!e.on_volume)
        fail_at(e.first_line,
                "surface entity " + std::to_string(tag) +
                    (e.groups.empty() ? "" : " (physical surface '" + listed(e.groups) + "')") +
                    " is a 2D mesh beside the volumes: none of its " +
                    std::to_string(e.n_elements) +
                    " elements is a face of a volume element; a 3D body's file holds volumes and "
                    "their boundary faces: mesh a 2D body in a file of its own");
  }

  void make_nodes_and_maps() {
    std::set<int> tags;
    for (const GmshHex* h : hexes_) tags.insert(h->nodes.begin(), h->nodes.begin() + 8);
    for (int tag : tags) {
      const auto& x = mesh_.nodes.at(tag);
      index_.emplace(tag, static_cast<int>(out_.nodes.size()));
      out_.nodes.emplace_back(x[0], x[1], x[2]);
    }
    const auto position = [&](int tag) {
      const auto& x = mesh_.nodes.at(tag);
      return Vec3(x[0], x[1], x[2]);
    };
    for (const GmshHex* h : hexes_) {
      std::array<int, 8> v;
      for (std::size_t k = 0; k < 8; ++k) v[k] = index_.at(h->nodes[k]);
      vertices_.push_back(v);
      mesh::HexMap map;
      if (h->type == 5) {
        std::array<Vec3, 8> x;
        for (std::size_t k = 0; k < 8; ++k) x[k] = position(h->nodes[k]);
        map = mesh::HexMap::trilinear(x);
      } else if (h->type == 17) {
        std::array<Vec3, 20> x;
        for (std::size_t k = 0; k < 20; ++k) x[k] = position(h->nodes[k]);
        map = mesh::HexMap::triquadratic(complete_hex20(x));
      } else {
        std::array<Vec3, 27> x;
        for (std::size_t k = 0; k < 27; ++k) x[k] = position(h->nodes[k]);
        map = mesh::HexMap::triquadratic(x);
      }
      // det J is of degree 2 (trilinear) or 5 (triquadratic) along each axis: checked at the
      // corners and 3 or 4 Gauss points per axis.
      mesh::check_hex_jacobian(map, mesh_.file + ":" + std::to_string(h->line), h->tag,
                               map.polynomial_degree() + 2);
      out_.maps.push_back(std::move(map));
    }
  }

  /// Each 2D physical group's quadrilaterals on the body's boundary.
  void make_face_sets() {
    const mesh::HexTopology& topology = out_.topology;
    std::map<std::string, std::set<mesh::ElementFace>> seen;
    for (const GmshQuad& q : mesh_.quads) {
      if (q.groups.empty()) continue;
      std::array<int, 4> corners;
      bool on_body = true;
      for (std::size_t k = 0; k < 4; ++k) {
        const auto it = index_.find(q.corners[k]);
        on_body = on_body && it != index_.end();
        corners[k] = on_body ? it->second : -1;
      }
      const int face = on_body ? topology.find_face(corners) : -1;
      if (face < 0) {
        if (volume_faces_.count(face_key(q.corners[0], q.corners[1], q.corners[2], q.corners[3])) ||
            unknown_volume_faces_)
          continue;  // a face of another volume's element
        fail_at(q.line, "face set '" + q.groups[0] + "' has quad " + std::to_string(q.tag) +
                            ", which is not a face of any volume element");
      }
      const mesh::HexFace& f = topology.face(face);
      if (!f.on_boundary())
        fail_at(q.line,
                "face set '" + q.groups[0] + "' has a face that is not on the boundary: quad " +
                    std::to_string(q.tag) + " lies between hexahedra " +
                    std::to_string(hexes_[static_cast<std::size_t>(f.hexes[0])]->tag) + " and " +
                    std::to_string(hexes_[static_cast<std::size_t>(f.hexes[1])]->tag));
      const mesh::ElementFace element_face{f.hexes[0], f.local_face[0]};
      for (const std::string& name : q.groups)
        if (seen[name].insert(element_face).second) out_.face_sets[name].push_back(element_face);
    }
  }

  const GmshVolumeMesh& mesh_;
  const HexImportOptions& options_;
  std::vector<std::string> volume_names_;
  std::vector<const GmshHex*> hexes_;  // the body's, in the file's order
  std::set<FaceKey> volume_faces_;
  bool unknown_volume_faces_ = false;
  std::map<int, int> index_;  // vertex node tag -> body node index
  std::vector<std::array<int, 8>> vertices_;
  mesh::HexMesh out_;
};

}  // namespace

mesh::HexMesh import_gmsh_hex_body(const GmshVolumeMesh& mesh, const HexImportOptions& options) {
  return HexImporter(mesh, options).run();
}

}  // namespace hpcontact::io
