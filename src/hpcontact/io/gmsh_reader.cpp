// A line-based parser of Gmsh MSH 4.1 ASCII files that checks every count, tag and value it
// reads, so that a truncated or hostile file ends in a one-line InputError, never in a crash. One
// parser reads 2D and 3D meshes: they differ in the nodes' z (0, or kept) and the elements kept
// (quads and lines, or hexahedra and quads).
//
// The layout read (gmsh reference manual, "MSH file format", version 4.1), one record per line:
//   $MeshFormat      version file-type data-size                    (4.1 0 8)
//   $PhysicalNames   n, then n x: dim tag "name"
//   $Entities        nPoints nCurves nSurfaces nVolumes, then per point
//                      tag x y z nPhys phys...
//                    and per curve / surface / volume
//                      tag minX minY minZ maxX maxY maxZ nPhys phys... nBounding bounding...
//   $Nodes           nBlocks nNodes minTag maxTag, then per block
//                      entityDim entityTag parametric n, n lines of tags, n lines of x y z [u [v]]
//   $Elements        nBlocks nElements minTag maxTag, then per block
//                      entityDim entityTag type n, n lines of: tag node...
// Other sections are skipped up to their $End line.
#include "hpcontact/io/gmsh_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

#include "hpcontact/core/error.hpp"
#include "hpcontact/io/text_file.hpp"
#include "hpcontact/io/yaml_limits.hpp"
#include "hpcontact/io/yaml_source.hpp"

namespace hpcontact::io {

namespace {

/// What the parser knows of a gmsh element type: its node count and dimension.
struct ElementType {
  int type;
  int n_nodes;
  int dim;
  const char* name;
};

// The element types of the gmsh manual (section "MSH file format", elm-type) up to order 5 in 2D,
// and the hexahedra of order 3 and 4.
constexpr ElementType element_types[] = {
    {1, 2, 1, "2-node line"},
    {2, 3, 2, "3-node triangle"},
    {3, 4, 2, "4-node quadrilateral"},
    {4, 4, 3, "4-node tetrahedron"},
    {5, 8, 3, "8-node hexahedron"},
    {6, 6, 3, "6-node prism"},
    {7, 5, 3, "5-node pyramid"},
    {8, 3, 1, "3-node line"},
    {9, 6, 2, "6-node triangle"},
    {10, 9, 2, "9-node quadrilateral"},
    {11, 10, 3, "10-node tetrahedron"},
    {12, 27, 3, "27-node hexahedron"},
    {13, 18, 3, "18-node prism"},
    {14, 14, 3, "14-node pyramid"},
    {15, 1, 0, "point"},
    {16, 8, 2, "8-node quadrilateral"},
    {17, 20, 3, "20-node hexahedron"},
    {18, 15, 3, "15-node prism"},
    {19, 13, 3, "13-node pyramid"},
    {20, 9, 2, "9-node triangle"},
    {21, 10, 2, "10-node triangle"},
    {22, 12, 2, "12-node triangle"},
    {23, 15, 2, "15-node triangle"},
    {24, 15, 2, "15-node triangle"},
    {25, 21, 2, "21-node triangle"},
    {26, 4, 1, "4-node line"},
    {27, 5, 1, "5-node line"},
    {28, 6, 1, "6-node line"},
    {29, 20, 3, "20-node tetrahedron"},
    {30, 35, 3, "35-node tetrahedron"},
    {31, 56, 3, "56-node tetrahedron"},
    {36, 16, 2, "16-node quadrilateral"},
    {37, 25, 2, "25-node quadrilateral"},
    {38, 36, 2, "36-node quadrilateral"},
    {92, 64, 3, "64-node hexahedron"},
    {93, 125, 3, "125-node hexahedron"},
};

const ElementType* find_element_type(std::int64_t type) {
  for (const ElementType& t : element_types)
    if (t.type == type) return &t;
  return nullptr;
}

std::string format_number(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

std::string_view trim(std::string_view s) {
  const auto space = [](char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
  };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split(std::string_view s) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < s.size() && s[i] != ' ' && s[i] != '\t') ++i;
    if (i > start) tokens.push_back(s.substr(start, i - start));
  }
  return tokens;
}

std::optional<std::int64_t> to_int64(std::string_view s) {
  if (s.size() > 1 && s.front() == '+') s.remove_prefix(1);
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return value;
}

std::optional<double> to_double(std::string_view s) {
  if (s.size() > 1 && s.front() == '+') s.remove_prefix(1);
  double value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

/// An element block: the entity its elements belong to, for their physical groups.
struct Block {
  int dim = 0;
  int entity = 0;
  int line = 0;
};

class Parser {
 public:
  /// `volume`: read a 3D mesh (GmshVolumeMesh) instead of a 2D one (GmshMesh).
  Parser(std::string_view text, std::string file, bool volume)
      : text_(text), file_(std::move(file)), volume_(volume) {
    mesh_.file = file_;
    volume_mesh_.file = file_;
  }

  GmshMesh mesh_2d() && { return std::move(mesh_); }
  GmshVolumeMesh mesh_3d() && { return std::move(volume_mesh_); }

  void parse() {
    if (!next_line()) fail(1, "empty file; expected a Gmsh mesh starting with $MeshFormat");
    if (line_text_ != "$MeshFormat")
      fail("not a Gmsh .msh file: expected $MeshFormat on its first line (got '" +
           shown(line_text_) + "')");
    read_format();
    while (next_line()) {
      if (line_text_.empty() || line_text_.front() != '$')
        fail("expected a section such as $Nodes or $Elements (got '" + shown(line_text_) + "')");
      const std::string name(line_text_.substr(1));
      if (name.starts_with("End"))
        fail("$" + name + " without its section (got '" + shown(line_text_) + "')");
      const bool known = name == "PhysicalNames" || name == "Entities" || name == "Nodes" ||
                         name == "Elements" || name == "MeshFormat";
      if (known && !sections_seen_.insert(name).second) fail("section $" + name + " given twice");
      if (name == "MeshFormat") fail("section $MeshFormat given twice");
      if (name == "PhysicalNames")
        read_physical_names();
      else if (name == "Entities")
        read_entities();
      else if (name == "Nodes")
        read_nodes();
      else if (name == "Elements")
        read_elements();
      else
        skip_section(name);
    }
    finish();
  }

 private:
  // ---- lines and values -------------------------------------------------------------------

  /// Moves to the next non-blank line; false at the end of the text.
  bool next_line() {
    while (pos_ < text_.size()) {
      const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
      line_text_ = trim(text_.substr(pos_, end - pos_));
      pos_ = end + 1;
      ++line_;
      if (!line_text_.empty()) return true;
    }
    line_text_ = {};
    return false;
  }

  /// The next line split into values; an error naming `what` at the end of the text.
  std::vector<std::string_view> need_line(const std::string& what) {
    if (!next_line()) fail("unexpected end of file in $" + section_ + ": expected " + what);
    if (line_text_.front() == '$')
      fail("section $" + section_ + " ends early: expected " + what + " (got '" +
           shown(line_text_) + "')");
    return split(line_text_);
  }

  void expect_end() {
    const std::string end = "$End" + section_;
    if (!next_line()) fail("unexpected end of file: expected " + end);
    if (line_text_ != end) fail("expected " + end + " (got '" + shown(line_text_) + "')");
  }

  [[noreturn]] void fail(const std::string& what) const { fail(line_, what); }
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw InputError(file_ + ":" + std::to_string(line) + ": " + what);
  }

  static std::string shown(std::string_view text) { return one_line(text, 60); }

  /// Checks that `tokens` has exactly `n` values, described by `what`.
  void need_count(const std::vector<std::string_view>& tokens, std::size_t n,
                  const std::string& what) const {
    if (tokens.size() != n) fail("expected " + what + " (got '" + shown(line_text_) + "')");
  }

  std::int64_t integer(std::string_view token, const std::string& what) const {
    const std::optional<std::int64_t> v = to_int64(token);
    if (!v) fail("expected " + what + " as an integer (got '" + shown(token) + "')");
    return *v;
  }

  /// A count: a whole number >= 0.
  std::uint64_t count(std::string_view token, const std::string& what) const {
    const std::int64_t v = integer(token, what);
    if (v < 0) fail("expected " + what + " >= 0 (got '" + shown(token) + "')");
    return static_cast<std::uint64_t>(v);
  }

  /// A node or element tag: a whole number in [1, INT_MAX] (problem files use int ids).
  int tag(std::string_view token, const std::string& what) const {
    const std::int64_t v = integer(token, what);
    if (v < 1 || v > std::numeric_limits<int>::max())
      fail("expected " + what + " in [1, " + std::to_string(std::numeric_limits<int>::max()) +
           "] (got '" + shown(token) + "')");
    return static_cast<int>(v);
  }

  /// An int-sized whole number of any sign (entity and physical tags).
  int small_integer(std::string_view token, const std::string& what) const {
    const std::int64_t v = integer(token, what);
    if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
      fail("expected " + what + " that fits an int (got '" + shown(token) + "')");
    return static_cast<int>(v);
  }

  /// A section's header count against its bound, before anything of the section is read.
  void require_at_most(std::uint64_t n, std::uint64_t most, const std::string& what) const {
    if (n > most)
      fail("the header says " + std::to_string(n) + " " + what + ", more than the " +
           std::to_string(most) + " a mesh file may have: a body's mesh becomes part of the "
           "problem's YAML tree, of at most " + std::to_string(kMaxYamlValues) +
           " values (some 4 per node and 6 per element); give a coarser mesh (a p-FEM mesh needs "
           "few elements: raise the degree)");
  }

  int dimension(std::string_view token) const {
    const std::int64_t v = integer(token, "a dimension");
    if (v < 0 || v > 3) fail("expected a dimension 0 to 3 (got '" + shown(token) + "')");
    return static_cast<int>(v);
  }

  double real(std::string_view token, const std::string& what) const {
    const std::optional<double> v = to_double(token);
    if (!v) fail("expected " + what + " as a finite number (got '" + shown(token) + "')");
    return *v;
  }

  // ---- sections ---------------------------------------------------------------------------

  void read_format() {
    section_ = "MeshFormat";
    const auto t = need_line("'version file-type data-size' (4.1 0 8)");
    if (t.size() < 3)
      fail("expected 'version file-type data-size' (4.1 0 8) (got '" + shown(line_text_) + "')");
    const std::optional<double> version = to_double(t[0]);
    if (!version || std::abs(*version - 4.1) > 1e-9)
      fail("MSH version " + shown(t[0]) +
           " is not read; hpcontact reads MSH 4.1 ASCII (gmsh -format msh41, or "
           "Mesh.MshFileVersion = 4.1) (got '" +
           shown(line_text_) + "')");
    if (t[1] != "0")
      fail(std::string(t[1] == "1" ? "binary" : "unknown file-type " + shown(t[1])) +
           " .msh is not read; hpcontact reads ASCII (Mesh.Binary = 0) (got '" + shown(line_text_) +
           "')");
    expect_end();
  }

  void read_physical_names() {
    section_ = "PhysicalNames";
    const auto header = need_line("the number of physical names");
    need_count(header, 1, "the number of physical names");
    const std::uint64_t n = count(header[0], "the number of physical names");
    for (std::uint64_t i = 0; i < n; ++i) {
      const auto t = need_line("'dim tag \"name\"'");
      if (t.size() < 3) fail("expected 'dim tag \"name\"' (got '" + shown(line_text_) + "')");
      const int dim = dimension(t[0]);
      const int phys = small_integer(t[1], "a physical tag");
      // The name is everything between the first and the last double quote (it may hold spaces).
      const std::string_view rest =
          line_text_.substr(static_cast<std::size_t>(t[2].data() - line_text_.data()));
      if (rest.size() < 2 || rest.front() != '"' || rest.back() != '"')
        fail("expected the physical name in double quotes (got '" + shown(line_text_) + "')");
      const std::string_view name = rest.substr(1, rest.size() - 2);
      if (trim(name).empty())
        fail("expected a non-empty physical name (got '" + shown(line_text_) + "')");
      if (!names_.emplace(std::make_pair(dim, phys), std::string(name)).second)
        fail("physical group " + std::to_string(dim) + "D " + std::to_string(phys) +
             " named twice");
    }
    expect_end();
  }

  void read_entities() {
    section_ = "Entities";
    if (sections_seen_.count("Elements")) fail("$Entities must come before $Elements");
    const auto header = need_line("'numPoints numCurves numSurfaces numVolumes'");
    need_count(header, 4, "'numPoints numCurves numSurfaces numVolumes'");
    for (int dim = 0; dim < 4; ++dim) {
      const std::uint64_t n = count(header[static_cast<std::size_t>(dim)], "an entity count");
      for (std::uint64_t i = 0; i < n; ++i) read_entity(dim);
    }
    expect_end();
  }

  /// One entity line; keeps its physical tags.
  void read_entity(int dim) {
    static const char* const kinds[] = {"point", "curve", "surface", "volume"};
    const std::string what = std::string("a ") + kinds[dim] + " entity line";
    const auto t = need_line(what);
    // A point has its coordinates x y z, the others their bounding box (6 numbers).
    const std::size_t n_coords = dim == 0 ? 3 : 6;
    if (t.size() < 2 + n_coords) fail("expected " + what + " (got '" + shown(line_text_) + "')");
    const int entity = small_integer(t[0], "an entity tag");
    for (std::size_t k = 1; k <= n_coords; ++k) real(t[k], "a coordinate");
    std::size_t at = 1 + n_coords;
    const std::uint64_t n_phys = count(t[at++], "the number of physical tags");
    if (n_phys > t.size() - at)
      fail("expected " + std::to_string(n_phys) + " physical tags (got '" + shown(line_text_) +
           "')");
    std::vector<int> phys;
    for (std::uint64_t k = 0; k < n_phys; ++k)
      phys.push_back(small_integer(t[at++], "a physical tag"));
    if (dim > 0) {
      if (at >= t.size())
        fail("expected the number of bounding entities (got '" + shown(line_text_) + "')");
      const std::uint64_t n_bound = count(t[at++], "the number of bounding entities");
      if (n_bound != t.size() - at)
        fail("expected " + std::to_string(n_bound) + " bounding entity tags (got '" +
             shown(line_text_) + "')");
      for (; at < t.size(); ++at) small_integer(t[at], "a bounding entity tag");
    } else if (at != t.size()) {
      fail("expected " + what + " 'tag x y z numPhysicalTags physicalTag...' (got '" +
           shown(line_text_) + "')");
    }
    if (!entities_.emplace(std::make_pair(dim, entity), std::move(phys)).second)
      fail(std::string(kinds[dim]) + " entity " + std::to_string(entity) + " given twice");
  }

  void read_nodes() {
    section_ = "Nodes";
    const auto header = need_line("'numEntityBlocks numNodes minNodeTag maxNodeTag'");
    need_count(header, 4, "'numEntityBlocks numNodes minNodeTag maxNodeTag'");
    const int header_line = line_;
    const std::uint64_t n_blocks = count(header[0], "the number of entity blocks");
    const std::uint64_t n_nodes = count(header[1], "the number of nodes");
    require_at_most(n_nodes, kMaxMeshNodes, "nodes");
    std::uint64_t n_read = 0;
    for (std::uint64_t b = 0; b < n_blocks; ++b) {
      const auto block = need_line("'entityDim entityTag parametric numNodesInBlock'");
      need_count(block, 4, "'entityDim entityTag parametric numNodesInBlock'");
      const int dim = dimension(block[0]);
      small_integer(block[1], "an entity tag");
      const std::int64_t parametric = integer(block[2], "parametric (0 or 1)");
      if (parametric != 0 && parametric != 1)
        fail("expected parametric 0 or 1 (got '" + shown(block[2]) + "')");
      const std::uint64_t n = count(block[3], "the number of nodes in the block");
      // Tags first, then as many coordinate lines; the tags are kept until their coordinates.
      std::vector<std::pair<int, int>> tags;  // tag, line
      for (std::uint64_t i = 0; i < n; ++i) {
        const auto t = need_line("a node tag");
        need_count(t, 1, "one node tag");
        tags.emplace_back(tag(t[0], "a node tag"), line_);
      }
      const std::size_t n_values = 3 + (parametric ? static_cast<std::size_t>(dim) : 0);
      for (const auto& [node, tag_line] : tags) {
        const auto t = need_line("the coordinates of node " + std::to_string(node));
        need_count(t, n_values,
                   std::to_string(n_values) + " numbers (x y z" +
                       (n_values > 3 ? " and parametric coordinates" : "") + ") of node " +
                       std::to_string(node));
        const double x = real(t[0], "x"), y = real(t[1], "y"), z = real(t[2], "z");
        for (std::size_t k = 3; k < n_values; ++k) real(t[k], "a parametric coordinate");
        const bool added = volume_
                               ? volume_mesh_.nodes.emplace(node, std::array{x, y, z}).second
                               : mesh_.nodes.emplace(node, std::array{x, y}).second;
        if (!added) fail(tag_line, "node tag " + std::to_string(node) + " given twice");
        scale_ = std::max({scale_, std::abs(x), std::abs(y)});
        if (std::abs(z) > max_z_) {
          max_z_ = std::abs(z);
          max_z_line_ = line_;
          max_z_node_ = node;
        }
      }
      n_read += n;
    }
    if (n_read != n_nodes)
      fail(header_line, "the header says " + std::to_string(n_nodes) + " nodes, the blocks hold " +
                            std::to_string(n_read));
    expect_end();
  }

  void read_elements() {
    section_ = "Elements";
    const auto header = need_line("'numEntityBlocks numElements minElementTag maxElementTag'");
    need_count(header, 4, "'numEntityBlocks numElements minElementTag maxElementTag'");
    const int header_line = line_;
    const std::uint64_t n_blocks = count(header[0], "the number of entity blocks");
    const std::uint64_t n_elements = count(header[1], "the number of elements");
    require_at_most(n_elements, kMaxMeshElements, "elements");
    std::uint64_t n_read = 0;
    for (std::uint64_t b = 0; b < n_blocks; ++b) {
      const auto block = need_line("'entityDim entityTag elementType numElementsInBlock'");
      need_count(block, 4, "'entityDim entityTag elementType numElementsInBlock'");
      const int dim = dimension(block[0]);
      const int entity = small_integer(block[1], "an entity tag");
      const int type = small_integer(block[2], "an element type");
      const ElementType* info = find_element_type(type);
      if (info && info->dim != dim)
        fail("element type " + std::to_string(type) + " (" + info->name +
             ") in a block of dimension " + std::to_string(dim));
      const std::uint64_t n = count(block[3], "the number of elements in the block");
      const int block_index = static_cast<int>(blocks_.size());
      blocks_.push_back({dim, entity, line_});
      for (std::uint64_t i = 0; i < n; ++i) read_element(dim, type, info, block_index);
      n_read += n;
    }
    if (n_read != n_elements)
      fail(header_line, "the header says " + std::to_string(n_elements) +
                            " elements, the blocks hold " + std::to_string(n_read));
    expect_end();
  }

  void read_element(int dim, int type, const ElementType* info, int block) {
    const auto t = need_line("an element line 'tag node...'");
    if (info)
      need_count(t, 1 + static_cast<std::size_t>(info->n_nodes),
                 "'tag' and " + std::to_string(info->n_nodes) + " node tags of a " + info->name);
    else if (t.size() < 2)
      fail("expected an element line 'tag node...' (got '" + shown(line_text_) + "')");
    const int element = tag(t[0], "an element tag");
    if (!element_tags_.insert(element).second)
      fail("element tag " + std::to_string(element) + " given twice");
    // A 2D mesh keeps quads and lines, a 3D one hexahedra and quads (its boundary faces).
    const bool quad = type == 3 || type == 10 || type == 16;
    const bool line = !volume_ && (type == 1 || type == 8);
    const bool hex = volume_ && (type == 5 || type == 12 || type == 17);
    const int entity = blocks_[static_cast<std::size_t>(block)].entity;
    std::vector<int> nodes;
    // Of other elements a 3D mesh keeps the node tags too (which faces lie on which volumes).
    if (quad || line || hex || volume_)
      for (std::size_t k = 1; k < t.size(); ++k) nodes.push_back(tag(t[k], "a node tag"));
    if (!quad && !line && !hex) {
      if (dim == 2) {
        other_faces().push_back({element, type, {}, entity, std::move(nodes), line_});
        other_blocks_.push_back(block);
      } else if (dim == 3 && volume_) {
        volume_mesh_.other_volumes.push_back({element, type, std::move(nodes), {}, line_});
        other_volume_blocks_.push_back(block);
      }
      return;
    }
    const std::size_t n_corners = hex ? 8 : quad ? 4 : 2;
    for (std::size_t a = 0; a < n_corners; ++a)
      for (std::size_t b = a + 1; b < n_corners; ++b)
        if (nodes[a] == nodes[b])
          fail("element " + std::to_string(element) + " has corner node " +
               std::to_string(nodes[a]) + " twice (got '" + shown(line_text_) + "')");
    if (hex) {
      volume_mesh_.hexes.push_back({element, type, std::move(nodes), {}, line_});
      hex_blocks_.push_back(block);
    } else if (quad) {
      GmshQuad q;
      q.tag = element;
      q.type = type;
      for (std::size_t k = 0; k < 4; ++k) q.corners[k] = nodes[k];
      if (type != 3)
        for (std::size_t k = 0; k < 4; ++k) q.midside[k] = nodes[4 + k];
      q.entity = entity;
      q.line = line_;
      quads().push_back(std::move(q));
      quad_nodes_.push_back(std::move(nodes));
      quad_blocks_.push_back(block);
    } else {
      GmshLine l;
      l.tag = element;
      l.ends = {nodes[0], nodes[1]};
      if (type == 8) l.midside = nodes[2];
      l.line = line_;
      mesh_.lines.push_back(std::move(l));
      line_nodes_.push_back(std::move(nodes));
      line_blocks_.push_back(block);
    }
  }

  void skip_section(const std::string& name) {
    section_ = name;
    const std::string end = "$End" + name;
    const int start = line_;
    while (next_line())
      if (line_text_ == end) return;
    fail(start, "section $" + name + " has no " + end + " line");
  }

  // ---- after the last section -------------------------------------------------------------

  void finish() {
    if (!volume_ && max_z_ > 1e-9 * scale_)
      fail(max_z_line_, "node " + std::to_string(max_z_node_) + " is not in the plane z = 0 (z = " +
                            format_number(max_z_) + "); hpcontact reads 2D meshes in the xy plane");
    check_nodes(quads(), quad_nodes_);
    check_nodes(mesh_.lines, line_nodes_);
    for (const GmshHex& h : volume_mesh_.hexes) check_nodes(h, h.nodes);
    // The physical group names of every block, then of its elements.
    std::vector<std::vector<std::string>> block_groups;
    for (const Block& b : blocks_) block_groups.push_back(group_names(b));
    const auto set_groups = [&](auto& elements, const std::vector<int>& blocks) {
      for (std::size_t i = 0; i < elements.size(); ++i)
        elements[i].groups = block_groups[static_cast<std::size_t>(blocks[i])];
    };
    set_groups(quads(), quad_blocks_);
    set_groups(mesh_.lines, line_blocks_);
    set_groups(other_faces(), other_blocks_);
    set_groups(volume_mesh_.hexes, hex_blocks_);
    set_groups(volume_mesh_.other_volumes, other_volume_blocks_);
    // Every physical group: those named, and those only used by entities (named by their tag).
    std::set<std::pair<int, int>> groups;
    for (const auto& [key, name] : names_) groups.insert(key);
    for (const auto& [entity, phys] : entities_)
      for (int p : phys) groups.insert({entity.first, p});
    for (const auto& [dim, phys] : groups)
      (volume_ ? volume_mesh_.groups : mesh_.groups).push_back({dim, phys, group_name(dim, phys)});
  }

  std::vector<GmshQuad>& quads() { return volume_ ? volume_mesh_.quads : mesh_.quads; }
  std::vector<GmshOtherFace>& other_faces() {
    return volume_ ? volume_mesh_.other_faces : mesh_.other_faces;
  }

  bool node_defined(int node) const {
    return volume_ ? volume_mesh_.nodes.count(node) > 0 : mesh_.nodes.count(node) > 0;
  }

  template <class Element>
  void check_nodes(const Element& element, const std::vector<int>& nodes) const {
    for (int node : nodes)
      if (!node_defined(node))
        fail(element.line, "element " + std::to_string(element.tag) + " refers to node " +
                               std::to_string(node) + ", which $Nodes does not define");
  }

  template <class Element>
  void check_nodes(const std::vector<Element>& elements,
                   const std::vector<std::vector<int>>& nodes) const {
    for (std::size_t i = 0; i < elements.size(); ++i) check_nodes(elements[i], nodes[i]);
  }

  std::string group_name(int dim, int phys) const {
    const auto it = names_.find({dim, phys});
    return it != names_.end() ? it->second : std::to_string(phys);
  }

  std::vector<std::string> group_names(const Block& b) const {
    std::vector<std::string> names;
    if (!sections_seen_.count("Entities")) return names;  // no entities: no physical groups
    const auto it = entities_.find({b.dim, b.entity});
    if (it == entities_.end())
      fail(b.line, "element block of " + std::to_string(b.dim) + "D entity " +
                       std::to_string(b.entity) + ", which $Entities does not define");
    for (int phys : it->second) {
      std::string name = group_name(b.dim, phys);
      if (std::find(names.begin(), names.end(), name) == names.end())
        names.push_back(std::move(name));
    }
    return names;
  }

  std::string_view text_;
  std::string file_;
  bool volume_ = false;
  std::size_t pos_ = 0;
  int line_ = 0;
  std::string_view line_text_;
  std::string section_;
  std::set<std::string> sections_seen_;

  GmshMesh mesh_;               // what a 2D parse gives
  GmshVolumeMesh volume_mesh_;  // what a 3D parse gives
  std::map<std::pair<int, int>, std::string> names_;          // (dim, physical tag) -> name
  std::map<std::pair<int, int>, std::vector<int>> entities_;  // (dim, entity tag) -> physical tags
  std::vector<Block> blocks_;
  std::set<int> element_tags_;
  // Per kept element: all its node tags and its block.
  std::vector<std::vector<int>> quad_nodes_, line_nodes_;
  std::vector<int> quad_blocks_, line_blocks_, other_blocks_, hex_blocks_, other_volume_blocks_;
  double scale_ = 0, max_z_ = 0;
  int max_z_line_ = 0, max_z_node_ = 0;
};

}  // namespace

std::string gmsh_type_name(int type) {
  if (const ElementType* info = find_element_type(type))
    return std::string(info->name) + " (gmsh type " + std::to_string(type) + ")";
  return "element type " + std::to_string(type);
}

GmshMesh parse_gmsh(std::string_view text, const std::string& file_label) {
  Parser parser(text, file_label, false);
  parser.parse();
  return std::move(parser).mesh_2d();
}

GmshVolumeMesh parse_gmsh_volume(std::string_view text, const std::string& file_label) {
  Parser parser(text, file_label, true);
  parser.parse();
  return std::move(parser).mesh_3d();
}

GmshMesh read_gmsh(const std::string& path) {
  return parse_gmsh(read_bounded_file(path, "mesh file", kMaxMeshFileBytes), path);
}

GmshVolumeMesh read_gmsh_volume(const std::string& path) {
  return parse_gmsh_volume(read_bounded_file(path, "mesh file", kMaxMeshFileBytes), path);
}

}  // namespace hpcontact::io
