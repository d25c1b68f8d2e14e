// Reading a YAML problem file (with --set overrides) into a validated model::ProblemSpec.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "hpcontact/io/input_schema.hpp"
#include "hpcontact/model/problem_spec.hpp"

namespace hpcontact::io {

/// Bounds on the work of one run, checked when a problem is read (keys that multiply; each key
/// alone has its schema bound). docs/input.md ("Limits") lists them.
constexpr double kMaxUnknowns = 5e7;          ///< elements × 2(p_xi+1)(p_eta+1)
constexpr double kMaxQuadraturePoints = 2e8;  ///< elements × (p + quadrature_extra)²
constexpr double kMaxContactPoints = 1e6;     ///< contact edges × contact[].quadrature
constexpr double kMaxVtuPoints = 1e7;         ///< elements × (vtu_subdivisions + 1)²
constexpr double kMinHpScale = 1e-11;         ///< hp: adapt.factor ^ adapt.steps

/// A validated problem and the effective input it was built from.
struct ReadResult {
  model::ProblemSpec spec;
  /// The problem file with the overrides applied and every default filled in, as YAML text that
  /// starts with comment lines naming the file and the overrides. Reading it back (without
  /// overrides) gives the same spec, so a run can be reproduced from its own output.
  /// Comments of the original file are not kept; keys keep the file's order, with filled-in
  /// defaults after the keys that were given.
  std::string effective_yaml;
};

/// Parses problem-file text, bounded as a file is (yaml_limits.hpp: its bytes and values, then
/// the values with the overrides and the Gmsh meshes, and the effective input's values and bytes,
/// so that it can be read back). `file_label` names the file in messages
/// (and becomes spec.file); a body's gmsh.file is found relative to its folder (to the current
/// directory if it has none).
/// `overrides` are "key.path=value" strings (--set), applied in order to the YAML tree before
/// validation; see apply_override() in overrides.hpp. Then every bodies[].gmsh section is
/// replaced by the mesh it names (expand_gmsh_meshes() in gmsh_import.hpp), every key is checked
/// against input_schema(), and cross references (node ids, edges, edge set names) are checked.
/// Throws InputError, one line: "<file>:<line>:<col>: <key.path>: <what is wrong> (got <value>)"
/// (or "<mesh.msh>:<line>: <what>" for an error in a gmsh file); IoError if a gmsh file cannot
/// be read.
ReadResult parse_problem_full(const std::string& yaml_text, const std::string& file_label,
                              const std::vector<std::string>& overrides = {});

/// Reads and parses the problem file at `path` (the label in messages is `path` as given).
/// Throws IoError naming the path and the OS reason if the file cannot be read; InputError as
/// parse_problem_full().
ReadResult read_problem_full(const std::string& path,
                             const std::vector<std::string>& overrides = {});

/// The whole text of a problem or study file (a regular file of at most kMaxYamlBytes);
/// IoError naming the path and the reason otherwise (a folder, a device, a missing file).
std::string read_input_file(const std::string& path);

/// parse_problem_full() without the effective input.
model::ProblemSpec parse_problem(const std::string& yaml_text, const std::string& file_label,
                                 const std::vector<std::string>& overrides = {});

/// read_problem_full() without the effective input.
model::ProblemSpec read_problem(const std::string& path,
                                const std::vector<std::string>& overrides = {});

}  // namespace hpcontact::io
