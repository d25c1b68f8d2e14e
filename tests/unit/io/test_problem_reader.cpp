// Unit tests of the problem-file reader: the Lamé example, defaults, --set overrides, the schema
// docs, and one-line input errors that name the file, line, key path and value.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "edit_text.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/discretization.hpp"

#ifndef HPC_SOURCE_DIR
#define HPC_SOURCE_DIR "/work/main"
#endif

namespace hio = hpcontact::io;
namespace hm = hpcontact::model;
using hpcontact::InputError;

namespace {

const std::string label = "case.yaml";

// A small valid problem; tests change one piece of it. Line numbers matter to some tests.
const std::string square = R"(case: square
bodies:
  - name: block
    material: {E: 1000, nu: 0.25}
    nodes:
      1: [0, 0]
      2: [1, 0]
      3: [1, 1]
      4: [0, 1]
    elements:
      1: [1, 2, 3, 4]
    edge_sets:
      bottom: [[1, 2]]
      top: [[3, 4]]
    constraints:
      - {edges: [bottom], ux: 0, uy: 0}
    loads:
      - {edges: [top], pressure: 10}
)";

using hpcontact::test::with;

/// The InputError message of parsing `text`, checked to be one line holding every fragment.
std::string input_error(const std::string& text, const std::vector<std::string>& fragments,
                        const std::vector<std::string>& overrides = {}) {
  try {
    hio::parse_problem(text, label, overrides);
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    for (const std::string& fragment : fragments)
      EXPECT_NE(message.find(fragment), std::string::npos)
          << "message lacks '" << fragment << "': " << message;
    return message;
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return "";
}

/// The YAML of an effective input without its leading comment lines.
std::string without_comments(const std::string& yaml) {
  std::string out;
  std::size_t start = 0;
  while (start < yaml.size()) {
    const std::size_t end = yaml.find('\n', start);
    const std::string line = yaml.substr(start, end - start);
    if (!line.starts_with("#")) out += line + "\n";
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out;
}

}  // namespace

// The reader shall turn the Lamé example file into the values it states, in the file's order.
TEST(ProblemReader, ReadsLameExample) {
  const hm::ProblemSpec spec =
      hio::read_problem(HPC_SOURCE_DIR "/examples/lame/thick-cylinder.yaml");
  EXPECT_EQ(spec.case_name, "lame-thick-cylinder");
  EXPECT_NE(spec.description.find("Thick-walled cylinder"), std::string::npos);
  ASSERT_EQ(spec.bodies.size(), 1u);
  const hm::BodySpec& body = spec.bodies[0];
  EXPECT_EQ(body.name, "cylinder");
  EXPECT_EQ(body.material.youngs_modulus, 200000.0);
  EXPECT_EQ(body.material.poisson_ratio, 0.3);
  EXPECT_EQ(body.material.plane, hm::PlaneMode::plane_strain);
  EXPECT_EQ(body.material.thickness, 1.0);
  EXPECT_EQ(body.material.where.line, 10);
  EXPECT_EQ(body.node_ids, (std::vector<int>{1, 2, 3, 4, 5, 6}));
  ASSERT_EQ(body.nodes.size(), 6u);
  EXPECT_EQ(body.nodes[2][0], 7.0710678118654755);
  EXPECT_EQ(body.nodes[5][1], 20.0);
  EXPECT_EQ(body.element_ids, (std::vector<int>{1, 2}));
  EXPECT_EQ(body.elements[0], (std::array<int, 4>{1, 2, 4, 3}));
  EXPECT_EQ(body.elements[1], (std::array<int, 4>{3, 4, 6, 5}));
  ASSERT_EQ(body.curves.size(), 4u);
  EXPECT_EQ(body.curves[0].node_a, 1);
  EXPECT_EQ(body.curves[0].node_b, 3);
  EXPECT_EQ(body.curves[0].kind, hm::CurveKind::arc);
  EXPECT_EQ(body.curves[0].radius, 10.0);
  EXPECT_EQ(body.curves[0].ccw, 0);
  EXPECT_EQ(body.curves[3].radius, 20.0);
  EXPECT_EQ(body.curves[3].where.line, 25);
  ASSERT_EQ(body.edge_sets.size(), 3u);
  EXPECT_EQ(body.edge_sets[0].name, "inner");
  EXPECT_EQ(body.edge_sets[0].edges, (std::vector<std::array<int, 2>>{{1, 3}, {3, 5}}));
  EXPECT_EQ(body.edge_sets[1].name, "bottom");
  EXPECT_EQ(body.edge_sets[2].name, "left");
  ASSERT_EQ(body.constraints.size(), 2u);
  EXPECT_EQ(body.constraints[0].edge_sets, (std::vector<std::string>{"bottom"}));
  EXPECT_FALSE(body.constraints[0].ux.has_value());
  EXPECT_EQ(body.constraints[0].uy, "0");
  EXPECT_EQ(body.constraints[1].ux, "0");
  ASSERT_EQ(body.edge_loads.size(), 1u);
  EXPECT_EQ(body.edge_loads[0].kind, hm::LoadKind::pressure);
  EXPECT_EQ(body.edge_loads[0].value[0], 100.0);
  EXPECT_EQ(body.edge_loads[0].shape, hm::LoadShape::constant);
  EXPECT_FALSE(body.degree.has_value());
  EXPECT_EQ(spec.discretization.method, hm::Method::p);
  EXPECT_EQ(spec.discretization.degree, (std::array<int, 2>{8, 8}));
  EXPECT_EQ(spec.exact.type, "lame");
  EXPECT_EQ(spec.exact.inner_radius, 10.0);
  EXPECT_EQ(spec.exact.outer_radius, 20.0);
  EXPECT_EQ(spec.exact.inner_pressure, 100.0);
  EXPECT_EQ(spec.exact.outer_pressure, 0.0);
}

// Absent keys shall take the schema's defaults, and these shall equal the ProblemSpec's own.
TEST(ProblemReader, FillsDefaultsEqualToSpecDefaults) {
  const hio::ReadResult read = hio::parse_problem_full(square, label);
  const hm::ProblemSpec& spec = read.spec;
  const hm::DiscretizationSpec d;
  EXPECT_EQ(spec.discretization.method, d.method);
  EXPECT_EQ(spec.discretization.degree, d.degree);
  EXPECT_EQ(spec.discretization.space, d.space);
  EXPECT_EQ(spec.discretization.element, d.element);
  EXPECT_EQ(spec.discretization.quadrature_extra, d.quadrature_extra);
  EXPECT_EQ(spec.discretization.condense, d.condense);
  const hm::SolverSpec solver;
  EXPECT_EQ(spec.solver.linear, solver.linear);
  EXPECT_EQ(spec.solver.tangent, solver.tangent);
  EXPECT_EQ(spec.solver.load_steps, solver.load_steps);
  EXPECT_EQ(spec.solver.max_iterations, solver.max_iterations);
  EXPECT_EQ(spec.solver.tolerance, solver.tolerance);
  EXPECT_EQ(spec.solver.max_cuts, solver.max_cuts);
  EXPECT_FALSE(spec.solver.target_resultant.has_value());
  EXPECT_TRUE(spec.contact.empty());
  EXPECT_EQ(spec.output.vtu, hm::OutputSpec{}.vtu);
  EXPECT_EQ(spec.output.vtu_subdivisions, hm::OutputSpec{}.vtu_subdivisions);
  EXPECT_EQ(spec.output.effective_input, hm::OutputSpec{}.effective_input);
  EXPECT_EQ(spec.exact.type, "");
  const hm::MaterialSpec& m = spec.bodies[0].material;
  EXPECT_EQ(m.model, hm::MaterialSpec{}.model);
  EXPECT_EQ(m.plane, hm::MaterialSpec{}.plane);
  EXPECT_EQ(m.thickness, hm::MaterialSpec{}.thickness);
  EXPECT_EQ(spec.bodies[0].body_force, (std::array<double, 2>{0, 0}));
  const hm::EdgeLoadSpec& load = spec.bodies[0].edge_loads[0];
  EXPECT_EQ(load.shape, hm::EdgeLoadSpec{}.shape);
  EXPECT_EQ(load.along, hm::EdgeLoadSpec{}.along);
  EXPECT_EQ(spec.discretization.where.str(), "case.yaml: discretization (default)");
  for (const char* filled : {"quadrature_extra: 2", "linear: cholmod", "plane: strain",
                             "vtu_subdivisions: 0", "body_force: [0, 0]", "shape: constant"})
    EXPECT_NE(read.effective_yaml.find(filled), std::string::npos) << filled;
}

// The effective input, read back, shall give the same problem and the same effective input.
TEST(ProblemReader, EffectiveInputReproducesTheRun) {
  const std::vector<std::string> sets{"discretization.degree=[6, 4]", "bodies[0].material.E=1e5"};
  const hio::ReadResult first =
      hio::read_problem_full(HPC_SOURCE_DIR "/examples/lame/thick-cylinder.yaml", sets);
  EXPECT_NE(first.effective_yaml.find("#   --set bodies[0].material.E=1e5"), std::string::npos);
  const hio::ReadResult second = hio::parse_problem_full(first.effective_yaml, "effective.yaml");
  EXPECT_EQ(without_comments(second.effective_yaml), without_comments(first.effective_yaml));
  EXPECT_EQ(second.spec.discretization.degree, (std::array<int, 2>{6, 4}));
  EXPECT_EQ(second.spec.bodies[0].material.youngs_modulus, 1e5);
  EXPECT_EQ(second.spec.description, first.spec.description);
  EXPECT_EQ(second.spec.bodies[0].nodes, first.spec.bodies[0].nodes);
}

// --set shall change the value of a valid key, create missing map keys, and apply in order.
TEST(ProblemReader, SetOverridesChangeValues) {
  hm::ProblemSpec spec = hio::parse_problem(square, label, {"discretization.degree=10"});
  EXPECT_EQ(spec.discretization.degree, (std::array<int, 2>{10, 10}));
  spec = hio::parse_problem(
      square, label,
      {"discretization.degree=[6,4]", "bodies[0].material.E=1e5", "solver.linear=ldlt",
       "bodies[0].material.E=2e5", "bodies[0].nodes.3=[1.5, 1]", "bodies[0].degree=3"});
  EXPECT_EQ(spec.discretization.degree, (std::array<int, 2>{6, 4}));
  EXPECT_EQ(spec.bodies[0].material.youngs_modulus, 2e5);
  EXPECT_EQ(spec.solver.linear, "ldlt");
  EXPECT_EQ(spec.bodies[0].nodes[2], (std::array<double, 2>{1.5, 1}));
  EXPECT_EQ(spec.bodies[0].degree, (std::array<int, 2>{3, 3}));
}

// A bad value given by --set shall be reported as coming from --set, not from a file line.
TEST(ProblemReader, RejectsBadSetValueNamingTheOverride) {
  const std::string message = input_error(square, {}, {"discretization.degree=0"});
  EXPECT_EQ(message, "case.yaml: discretization.degree (from --set): must be >= 1 (got 0)");
}

// A malformed --set, or one through a missing list index or a scalar, shall be an InputError
// naming the file and the override.
TEST(ProblemReader, RejectsBadSetPath) {
  input_error(square, {label, "bodies[3].material.E=1", "bodies[3]", "no such list element"},
              {"bodies[3].material.E=1"});
  input_error(square, {label, "discretization..degree=3", "malformed key path"},
              {"discretization..degree=3"});
  input_error(square, {label, "degree", "key.path=value"}, {"degree"});
  input_error(square, {label, "case.name=x", "case is not a map"}, {"case.name=x"});
  input_error(square, {label, "bodies.name=x", "bodies is not a map"}, {"bodies.name=x"});
  input_error(square, {label, "discretization.degree=[1,", "not valid YAML"},
              {"discretization.degree=[1,"});
  // A new key that the schema does not know is caught by validation.
  input_error(square, {label, "discretization.degre", "unknown key", "(from --set)"},
              {"discretization.degre=3"});
}

// An empty or comment-only file shall be rejected as such.
TEST(ProblemReader, RejectsEmptyFile) {
  EXPECT_EQ(input_error("", {}), "case.yaml: empty problem file");
  EXPECT_EQ(input_error("  \n# only a comment\n", {}), "case.yaml: empty problem file");
}

// A YAML syntax error shall be an InputError with the file, line and column.
TEST(ProblemReader, RejectsTruncatedYaml) {
  input_error(square.substr(0, square.find("nu: 0.25")), {label, "YAML syntax error"});
  input_error("case: a\nbodies: [\n  {name: x\n", {label + ":", "YAML syntax error"});
  input_error("case: a\n  bodies: b\n", {label + ":2:", "YAML syntax error"});
}

// Binary data shall be rejected with an InputError naming the file, not a crash or other error.
TEST(ProblemReader, RejectsBinaryGarbage) {
  const std::string png("\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\x01\0", 20);
  input_error(png, {label});
  std::string noise;
  for (int i = 0; i < 256; ++i) noise += static_cast<char>((i * 73 + 11) % 256);
  input_error(noise, {label});
  input_error("just a sentence", {label, "must be a YAML map"});
}

// A key the schema does not declare shall be an error naming its path, line and the allowed keys.
TEST(ProblemReader, RejectsUnknownKey) {
  input_error(with(square, "nu: 0.25", "nu: 0.25, youngs: 3"),
              {"case.yaml:4:", "bodies[0].material.youngs: unknown key", "allowed here: model, E"});
  input_error(square + "solvr: {linear: ldlt}\n", {"case.yaml:19:1: solvr: unknown key"});
}

// A value of the wrong type shall be an error naming the key, line, the type and the value.
TEST(ProblemReader, RejectsWrongType) {
  input_error(with(square, "E: 1000", "E: abc"),
              {"case.yaml:4:", "bodies[0].material.E: must be a number (got 'abc')"});
  input_error(with(square, "pressure: 10", "pressure: [1, 2]"),
              {"bodies[0].loads[0].pressure: must be a number (got [1, 2])"});
  input_error(square + "discretization: {degree: 4.5}\n",
              {"case.yaml:19:", "discretization.degree: must be an integer (got '4.5')"});
  input_error(square + "output: {vtu: maybe}\n",
              {"output.vtu: must be true or false (got 'maybe')"});
  input_error(square + "solver: {linear: qr}\n",
              {"solver.linear: must be one of cholmod, ldlt, lu (got 'qr')"});
  input_error(with(square, "2: [1, 0]", "2: [1]"),
              {"case.yaml:7:", "bodies[0].nodes.2: must be [x, y] (got [1])"});
}

// A missing required key shall be an error naming the parent path and the missing key.
TEST(ProblemReader, RejectsMissingRequiredKey) {
  input_error(with(square, "{E: 1000, nu: 0.25}", "{E: 1000}"),
              {"case.yaml:4:15: bodies[0].material: missing required key 'nu'"});
  input_error(with(square, "case: square\n", ""), {"case.yaml:1:1: missing required key 'case'"});
  input_error(with(square, "  - name: block\n", "  - \n"),
              {"case.yaml:", "bodies[0]: missing required key 'name'"});
}

// Young's modulus shall be positive.
TEST(ProblemReader, RejectsNonPositiveYoungsModulus) {
  input_error(with(square, "E: 1000", "E: 0"),
              {"case.yaml:4:", "bodies[0].material.E: must be > 0 (got 0)"});
  input_error(with(square, "E: 1000", "E: -2e5"), {"bodies[0].material.E: must be > 0 (got -2e5)"});
}

// Poisson's ratio shall lie strictly between -1 and 0.5.
TEST(ProblemReader, RejectsIncompressiblePoissonRatio) {
  EXPECT_EQ(input_error(with(square, "nu: 0.25", "nu: 0.5"), {}),
            "case.yaml:4:29: bodies[0].material.nu: must be < 0.5 (got 0.5)");
  input_error(with(square, "nu: 0.25", "nu: -1"), {"bodies[0].material.nu: must be > -1 (got -1)"});
}

// A rubber law shall take exactly its own constants (C10, C01, C20, C30, K), each named when
// missing, misplaced or out of range (C's >= 0, C10 and K > 0), and E, nu no longer; its body
// shall be plane strain or axisymmetric and have no regions.
TEST(ProblemReader, ReadsRubberLawsAndRefusesConstantsTheyDoNotTake) {
  const auto mr = with(square, "{E: 1000, nu: 0.25}", "{model: mooney-rivlin, C10: 0.4, C01: 0.1, K: 50}");
  const auto spec = hio::parse_problem(mr, label, {});
  const auto& m = spec.bodies[0].material;
  EXPECT_EQ(m.model, "mooney-rivlin");
  EXPECT_EQ(m.C10, 0.4);
  EXPECT_EQ(m.C01, 0.1);
  EXPECT_EQ(m.K, 50);
  EXPECT_EQ(m.C20, 0.0);
  const auto d = hm::discretize(spec);
  EXPECT_NEAR(d.bodies[0].material.mu(), 1.0, 1e-14);  // 2 (C10 + C01)
  EXPECT_EQ(d.bodies[0].rubber.C01, 0.1);
  const auto yeoh = with(square, "{E: 1000, nu: 0.25}", "{model: yeoh, C10: 0.4, C20: 0.01, C30: 0.002, K: 50}");
  EXPECT_EQ(hio::parse_problem(yeoh, label, {}).bodies[0].material.C30, 0.002);

  input_error(with(mr, "C01: 0.1, ", ""),
              {"case.yaml:4:", "bodies[0].material: missing required key 'C01' (model mooney-rivlin "
                               "takes C10, C01, K)"});
  input_error(with(mr, "K: 50", "K: 50, C20: 1"),
              {"case.yaml:4:", "bodies[0].material.C20: is not a constant of model mooney-rivlin"});
  input_error(with(yeoh, "K: 50", "K: 50, E: 3"),
              {"bodies[0].material.E: is not a constant of model yeoh (it takes C10, C20, C30, K)"});
  input_error(with(yeoh, "C30: 0.002, ", ""), {"bodies[0].material: missing required key 'C30'"});
  input_error(with(square, "nu: 0.25", "nu: 0.25, K: 3"),
              {"bodies[0].material.K: is not a constant of model linear-elastic (it takes E, nu)"});
  input_error(with(mr, "C01: 0.1", "C01: -0.1"), {"bodies[0].material.C01: must be >= 0 (got -0.1)"});
  input_error(with(yeoh, "C20: 0.01", "C20: -0.01"), {"bodies[0].material.C20: must be >= 0 (got -0.01)"});
  input_error(with(mr, "C10: 0.4", "C10: 0"), {"bodies[0].material.C10: must be > 0 (got 0)"});
  input_error(with(mr, "K: 50", "K: 0"), {"bodies[0].material.K: must be > 0 (got 0)"});
  input_error(with(mr, "K: 50", "K: -5"), {"bodies[0].material.K: must be > 0 (got -5)"});
  input_error(mr + "    regions:\n      - {elements: [1], material: {E: 1, nu: 0.3}}\n",
              {"bodies[0].regions[0]: a body of a rubber law (mooney-rivlin) has one set of "
               "constants: no regions"});
  try {
    hm::discretize(hio::parse_problem(with(mr, "K: 50", "K: 50, plane: stress"), label, {}));
    ADD_FAILURE() << "a rubber law in plane stress accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "bodies[0].material.plane: mooney-rivlin is implemented in plane strain and axisymmetry only"),
              std::string::npos)
        << e.what();
  }
}

// An element shall reference existing nodes only, four distinct ones.
TEST(ProblemReader, RejectsElementWithUnknownNode) {
  input_error(
      with(square, "1: [1, 2, 3, 4]", "1: [1, 2, 3, 7]"),
      {"case.yaml:11:", "bodies[0].elements.1[3]: no such node in bodies[0].nodes (got 7)"});
  input_error(with(square, "1: [1, 2, 3, 4]", "1: [1, 2, 3, 3]"),
              {"case.yaml:11:", "bodies[0].elements.1: must have four distinct node ids"});
}

// Node and element ids shall be unique within a body.
TEST(ProblemReader, RejectsDuplicateIds) {
  input_error(with(square, "      4: [0, 1]\n", "      4: [0, 1]\n      2: [5, 5]\n"),
              {"case.yaml:10:", "bodies[0].nodes.2: duplicate id"});
  input_error(with(square, "case: square\n", "case: square\ncase: other\n"),
              {"case.yaml:2:1: case: duplicate key"});
}

// Every edge of an edge set shall be an edge of some element.
TEST(ProblemReader, RejectsEdgeSetWithNonEdge) {
  input_error(
      with(square, "bottom: [[1, 2]]", "bottom: [[1, 2], [1, 3]]"),
      {"case.yaml:13:", "bodies[0].edge_sets.bottom[1]: not an edge of any element (got [1, 3])"});
  input_error(with(square, "bottom: [[1, 2]]", "bottom: [[1, 2], [2, 1]]"),
              {"bodies[0].edge_sets.bottom[1]: edge listed twice"});
}

// A constraint or load shall name edge sets that the body defines.
TEST(ProblemReader, RejectsUnknownEdgeSet) {
  input_error(with(square, "edges: [bottom]", "edges: [botom]"),
              {"case.yaml:16:", "bodies[0].constraints[0].edges[0]: no such edge set",
               "defined: bottom, top", "(got 'botom')"});
  input_error(with(square, "edges: [top]", "edges: [top, side]"),
              {"case.yaml:18:", "bodies[0].loads[0].edges[1]: no such edge set"});
}

// A constraint shall say where (edges or nodes) and what (ux or uy); its nodes shall exist.
TEST(ProblemReader, RejectsIncompleteConstraint) {
  input_error(with(square, "{edges: [bottom], ux: 0, uy: 0}", "{edges: [bottom]}"),
              {"case.yaml:16:", "bodies[0].constraints[0]: needs 'ux', 'uy' or both"});
  input_error(with(square, "{edges: [bottom], ux: 0, uy: 0}", "{ux: 0}"),
              {"bodies[0].constraints[0]: needs 'edges', 'nodes' or both"});
  input_error(with(square, "{edges: [bottom], ux: 0, uy: 0}", "{nodes: [1, 9], ux: 0}"),
              {"bodies[0].constraints[0].nodes[1]: no such node in bodies[0].nodes (got 9)"});
}

// Constraint values shall be kept verbatim, numbers and formulas alike.
TEST(ProblemReader, KeepsConstraintValuesAsText) {
  const hm::ProblemSpec spec =
      hio::parse_problem(with(square, "ux: 0, uy: 0", "ux: -0.01, uy: \"0.001*x\""), label);
  EXPECT_EQ(spec.bodies[0].constraints[0].ux, "-0.01");
  EXPECT_EQ(spec.bodies[0].constraints[0].uy, "0.001*x");
}

// A curve shall replace an element edge, at most one curve per edge, given as arc or parametric.
TEST(ProblemReader, ChecksCurves) {
  const std::string arc =
      "    curves:\n      - {nodes: [2, 3], arc: {center: [0, 0.5], radius: 1.2}}\n";
  const std::string text = with(square, "    edge_sets:\n", arc + "    edge_sets:\n");
  const hm::ProblemSpec spec =
      hio::parse_problem(with(text, "radius: 1.2}", "radius: 1.2, ccw: false}"), label);
  EXPECT_EQ(spec.bodies[0].curves[0].ccw, -1);
  input_error(
      with(text, "- {nodes: [2, 3]", "- {nodes: [1, 3]"),
      {"case.yaml:13:", "bodies[0].curves[0].nodes: not an edge of any element (got [1, 3])"});
  input_error(with(text, "    edge_sets:\n",
                   "      - {nodes: [3, 2], parametric: {x: 1, y: s}}\n    edge_sets:\n"),
              {"case.yaml:14:",
               "bodies[0].curves[1].nodes: edge already has a curve at bodies[0].curves[0]"});
  input_error(with(text, "arc: {center: [0, 0.5], radius: 1.2}", "parametric: {x: s}"),
              {"bodies[0].curves[0].parametric: missing required key 'y'"});
  input_error(
      with(text, ", arc: {center: [0, 0.5], radius: 1.2}", ""),
      {"bodies[0].curves[0]: must have exactly one of 'arc' and 'parametric' (got neither)"});
}

// A load shall be either a pressure or a traction, with a formula exactly when its shape says so.
TEST(ProblemReader, ChecksLoads) {
  const hm::ProblemSpec spec = hio::parse_problem(
      with(square, "pressure: 10}",
           "traction: [0, -1], shape: expression, expression: \"x*x\", along: y, "
           "interval: [1, 0], resultant: 5}"),
      label);
  const hm::EdgeLoadSpec& load = spec.bodies[0].edge_loads[0];
  EXPECT_EQ(load.kind, hm::LoadKind::traction);
  EXPECT_EQ(load.value, (std::array<double, 2>{0, -1}));
  EXPECT_EQ(load.shape, hm::LoadShape::expression);
  EXPECT_EQ(load.expression, "x*x");
  EXPECT_EQ(load.along, 'y');
  EXPECT_EQ(load.interval, (std::array<double, 2>{1, 0}));
  EXPECT_EQ(load.resultant, 5.0);
  input_error(
      with(square, "pressure: 10}", "pressure: 10, traction: [1, 0]}"),
      {"case.yaml:18:",
       "bodies[0].loads[0]: must have exactly one of 'pressure' and 'traction' (got both)"});
  input_error(with(square, "pressure: 10}", "pressure: 10, shape: expression}"),
              {"bodies[0].loads[0]: missing key 'expression'"});
  input_error(with(square, "pressure: 10}", "pressure: 10, expression: x}"),
              {"bodies[0].loads[0].expression: only allowed with shape: expression"});
}

// Per-element degrees shall name existing elements; degrees shall lie in [1, 30].
TEST(ProblemReader, ChecksDegrees) {
  const hm::ProblemSpec spec = hio::parse_problem(
      with(square, "    edge_sets:\n", "    degrees: {1: [3, 5]}\n    edge_sets:\n"), label);
  EXPECT_EQ(spec.bodies[0].element_degrees.at(1), (std::array<int, 2>{3, 5}));
  input_error(with(square, "    edge_sets:\n", "    degrees: {2: 3}\n    edge_sets:\n"),
              {"case.yaml:12:", "bodies[0].degrees.2: no such element"});
  input_error(square + "discretization: {degree: [4, 31]}\n",
              {"discretization.degree[1]: must be <= 30 (got 31)"});
}

// The Lamé solution shall need both radii, the outer larger than the inner.
TEST(ProblemReader, ChecksExactSolution) {
  input_error(square + "exact: {type: lame, inner_radius: 2}\n",
              {"case.yaml:19:", "exact: missing key 'outer_radius'"});
  input_error(square + "exact: {type: lame, inner_radius: 2, outer_radius: 1}\n",
              {"exact.outer_radius: must be > exact.inner_radius = 2 (got 1)"});
  input_error(square + "exact: {inner_radius: 2}\n", {"exact: missing required key 'type'"});
  EXPECT_EQ(hio::parse_problem(square + "exact: {type: none}\n", label).exact.type, "");
}

// A contact section shall give a ContactPairSpec with the stated values and the spec's defaults.
TEST(ProblemReader, ReadsContactPair) {
  const hm::ProblemSpec spec = hio::parse_problem(
      square + "contact:\n  - body: block\n    edges: [bottom]\n"
               "    obstacle: {type: plane, point: [0, -0.5], normal: [0, 2]}\n"
               "    penalty: 1e6\n",
      label);
  ASSERT_EQ(spec.contact.size(), 1u);
  const hm::ContactPairSpec& c = spec.contact[0];
  EXPECT_EQ(c.body, "block");
  EXPECT_EQ(c.edge_sets, (std::vector<std::string>{"bottom"}));
  EXPECT_EQ(c.penalty, 1e6);
  EXPECT_EQ(c.quadrature, hm::ContactPairSpec{}.quadrature);
  EXPECT_EQ(c.where.line, 20);
  EXPECT_EQ(c.obstacle.kind, hm::ObstacleKind::plane);
  EXPECT_EQ(c.obstacle.point, (std::array<double, 2>{0, -0.5}));
  EXPECT_EQ(c.obstacle.normal, (std::array<double, 2>{0, 1}));  // normalised
  const hm::ObstacleSpec o;
  EXPECT_EQ(c.obstacle.center, o.center);
  EXPECT_EQ(c.obstacle.radius, o.radius);
  EXPECT_EQ(c.obstacle.inside, o.inside);
  const hm::ProblemSpec circle = hio::parse_problem(
      square + "contact:\n  - {body: block, edges: [top, bottom], penalty: 5, quadrature: 8,\n"
               "     obstacle: {type: circle, center: [0.5, 3], radius: 2, inside: true}}\n",
      label);
  const hm::ContactPairSpec& d = circle.contact[0];
  EXPECT_EQ(d.edge_sets, (std::vector<std::string>{"top", "bottom"}));
  EXPECT_EQ(d.quadrature, 8);
  EXPECT_EQ(d.obstacle.kind, hm::ObstacleKind::circle);
  EXPECT_EQ(d.obstacle.center, (std::array<double, 2>{0.5, 3}));
  EXPECT_EQ(d.obstacle.radius, 2.0);
  EXPECT_TRUE(d.obstacle.inside);
  EXPECT_EQ(d.obstacle.normal, o.normal);
}

// The body of a contact pair shall be named in bodies; the error shall list the bodies.
TEST(ProblemReader, RejectsContactWithUnknownBody) {
  input_error(square + "contact:\n  - {body: blok, edges: [bottom], penalty: 1, "
                       "obstacle: {type: plane}}\n",
              {"case.yaml:20:", "contact[0].body: no such body (defined: block) (got 'blok')"});
}

// The edges of a contact pair shall be edge sets of its body.
TEST(ProblemReader, RejectsContactWithUnknownEdgeSet) {
  input_error(square + "contact:\n  - {body: block, edges: [bottom, side], penalty: 1, "
                       "obstacle: {type: plane}}\n",
              {"case.yaml:20:", "contact[0].edges[1]: no such edge set", "defined: bottom, top",
               "(got 'side')"});
  input_error(square + "contact:\n  - {body: block, edges: [], penalty: 1, "
                       "obstacle: {type: plane}}\n",
              {"contact[0].edges: must have at least 1 entry"});
}

// The contact penalty shall be positive.
TEST(ProblemReader, RejectsNonPositivePenalty) {
  const std::string text = square + "contact:\n  - {body: block, edges: [bottom], penalty: 1, "
                                    "obstacle: {type: plane}}\n";
  input_error(with(text, "penalty: 1,", "penalty: 0,"),
              {"case.yaml:20:", "contact[0].penalty: must be > 0 (got 0)"});
  input_error(with(text, "penalty: 1,", "penalty: -3,"), {"contact[0].penalty: must be > 0"});
  input_error(with(text, "penalty: 1, ", "enforcement: penalty, "),
              {"contact[0]: missing key 'penalty' (required by enforcement: penalty)"});
  // exact enforcement needs none (the augmentation defaults to E p²/h)
  EXPECT_EQ(hio::parse_problem(with(text, "penalty: 1, ", ""), label).contact.at(0).penalty, 0.0);
}

// An obstacle shall be complete: a circle needs its radius (a plane has none), a plane a
// non-zero normal.
TEST(ProblemReader, ChecksObstacle) {
  const std::string text = square + "contact:\n  - {body: block, edges: [bottom], penalty: 1, "
                                    "obstacle: {type: plane}}\n";
  input_error(with(text, "type: plane", "type: circle"),
              {"case.yaml:20:", "contact[0].obstacle: missing key 'radius' (required by type: "
                                "circle)"});
  input_error(with(text, "type: plane", "type: plane, radius: 1"),
              {"contact[0].obstacle.radius: only allowed with type: circle"});
  input_error(with(text, "type: plane", "type: plane, normal: [0, 0]"),
              {"contact[0].obstacle.normal: must be non-zero (got [0, 0])"});
  input_error(with(text, "type: plane", "type: circle, radius: 0"),
              {"contact[0].obstacle.radius: must be > 0 (got 0)"});
  input_error(with(text, "penalty: 1,", "penalty: 1, quadrature: 201,"),
              {"contact[0].quadrature: must be <= 200 (got 201)"});
}

// A rigid curve is read with its points in order; it needs at least two, each [x, y], no two
// consecutive ones equal, and points belong to no other type.
TEST(ProblemReader, ReadsAndChecksCurveObstacle) {
  const std::string text = square + "contact:\n  - {body: block, edges: [bottom], penalty: 1, "
                                    "obstacle: {type: plane}}\n";
  const hm::ProblemSpec spec =
      hio::parse_problem(with(text, "type: plane", "type: curve, points: [[-1, -0.5], [0.5, -0.6], [2, -0.5]]"), label);
  EXPECT_EQ(spec.contact[0].obstacle.kind, hm::ObstacleKind::curve);
  EXPECT_EQ(spec.contact[0].obstacle.points,
            (std::vector<std::array<double, 2>>{{-1, -0.5}, {0.5, -0.6}, {2, -0.5}}));
  input_error(with(text, "type: plane", "type: curve"),
              {"case.yaml:20:", "contact[0].obstacle: missing key 'points' (required by type: curve)"});
  input_error(with(text, "type: plane", "type: curve, points: [[0, -1]]"),
              {"contact[0].obstacle.points: must have at least 2 entries"});
  input_error(with(text, "type: plane", "type: curve, points: [[0, -1], [1]]"),
              {"contact[0].obstacle.points[1]: must be [x, y]"});
  input_error(with(text, "type: plane", "type: curve, points: [[0, -1], [1, -1], [1, -1]]"),
              {"contact[0].obstacle.points[2]: repeats the point before it ([1, -1])"});
  input_error(with(text, "type: plane", "type: plane, points: [[0, -1], [1, -1]]"),
              {"contact[0].obstacle.points: only allowed with type: curve or profile (got type: plane)"});
}

// The solver's Newton settings and load control by force shall be read, component y as 1.
TEST(ProblemReader, ReadsSolverSettingsAndTargetResultant) {
  const hm::ProblemSpec spec = hio::parse_problem(
      square + "solver:\n  tangent: finite-difference\n  load_steps: 4\n  max_iterations: 12\n"
               "  tolerance: 1e-8\n  max_cuts: 0\n  target_resultant: {value: 250}\n",
      label);
  EXPECT_EQ(spec.solver.tangent, "finite-difference");
  EXPECT_EQ(spec.solver.load_steps, 4);
  EXPECT_EQ(spec.solver.max_iterations, 12);
  EXPECT_EQ(spec.solver.tolerance, 1e-8);
  EXPECT_EQ(spec.solver.max_cuts, 0);
  ASSERT_TRUE(spec.solver.target_resultant.has_value());
  EXPECT_EQ(spec.solver.target_resultant->value, 250.0);
  EXPECT_EQ(spec.solver.target_resultant->component, 1);
  EXPECT_EQ(spec.solver.target_resultant->tolerance, hm::TargetResultantSpec{}.tolerance);
  const hm::ProblemSpec x = hio::parse_problem(
      square + "solver: {target_resultant: {value: 1, component: x, tolerance: 1e-6}}\n", label);
  EXPECT_EQ(x.solver.target_resultant->component, 0);
  EXPECT_EQ(x.solver.target_resultant->tolerance, 1e-6);
  input_error(square + "solver: {target_resultant: {component: y}}\n",
              {"solver.target_resultant: missing required key 'value'"});
  input_error(square + "solver: {target_resultant: {value: 0}}\n",
              {"solver.target_resultant.value: must be > 0 (got 0)"});
  input_error(square + "solver: {load_steps: 0}\n", {"solver.load_steps: must be >= 1 (got 0)"});
  input_error(square + "solver: {tangent: secant}\n",
              {"solver.tangent: must be one of analytic, finite-difference (got 'secant')"});
}

// Body names shall be unique.
TEST(ProblemReader, RejectsDuplicateBodyName) {
  const std::string body = square.substr(square.find("  - name: block"));
  input_error(square + body, {"bodies[1].name: name already used by bodies[0] (got 'block')"});
}

// A file that cannot be read shall be an IoError naming the path and the reason.
TEST(ProblemReader, ReportsUnreadableFile) {
  try {
    hio::read_problem("/nonexistent/problem.yaml");
    ADD_FAILURE() << "no IoError";
  } catch (const hpcontact::IoError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/problem.yaml"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos);
  }
  EXPECT_THROW(hio::read_problem("/tmp"), hpcontact::IoError);
}

// Source references shall print as "file:line:col: key (origin)", leaving out unknown parts.
TEST(SourceRef, FormatsKnownParts) {
  EXPECT_EQ((hm::SourceRef{"a.yaml", 12, 9, "bodies[0].material.nu", ""}).str(),
            "a.yaml:12:9: bodies[0].material.nu");
  EXPECT_EQ((hm::SourceRef{"case.yaml", 0, 0, "discretization.degree", "from --set"}).str(),
            "case.yaml: discretization.degree (from --set)");
  EXPECT_EQ((hm::SourceRef{"a.yaml", 0, 0, "", ""}).str(), "a.yaml");
}

// The schema shall declare each key once, under a declared section, and the docs shall list
// every key in a table of its section.
TEST(InputSchema, IsConsistentAndDocumented) {
  std::set<std::string_view> paths;
  for (const hio::KeySpec& key : hio::input_schema()) {
    EXPECT_TRUE(paths.insert(key.path).second) << "declared twice: " << key.path;
    EXPECT_FALSE(key.doc.empty()) << key.path;
    EXPECT_FALSE(key.required && !key.default_yaml.empty()) << key.path;
    EXPECT_EQ(key.choices.empty(), key.type != hio::ValueType::choice) << key.path;
    const std::string_view path = key.path;
    const std::size_t dot = path.rfind('.');
    if (dot == std::string_view::npos) continue;
    std::string_view parent = path.substr(0, dot);
    const bool is_list_item = parent.ends_with("[]");
    if (is_list_item) parent.remove_suffix(2);
    const hio::KeySpec* parent_key = hio::find_key_spec(parent);
    ASSERT_NE(parent_key, nullptr) << key.path;
    EXPECT_EQ(parent_key->type,
              is_list_item ? hio::ValueType::section_list : hio::ValueType::section)
        << key.path;
  }
  const std::string markdown = hio::input_schema_markdown();
  for (const hio::KeySpec& key : hio::input_schema())
    EXPECT_NE(markdown.find("| `" + std::string(key.path) + "` |"), std::string::npos) << key.path;
  EXPECT_NE(markdown.find("## `bodies[].material`"), std::string::npos);
  EXPECT_NE(markdown.find("| `bodies[].material.nu` | number in (-1, 0.5) | required |"),
            std::string::npos);
}

// Contact with another body: the body must exist, differ from the pair's own, and name its
// edge sets; body and edges belong to type body only.
TEST(ProblemReader, RejectsBadBodyObstacle) {
  const std::string pair = square + "contact:\n  - {body: block, edges: [bottom], penalty: 1, ";
  input_error(pair + "obstacle: {type: body, edges: [top]}}\n",
              {"contact[0].obstacle: missing key 'body' (required by type: body)"});
  input_error(pair + "obstacle: {type: body, body: block, edges: [top]}}\n",
              {"contact[0].obstacle.body: must be another body than the contact's own (got 'block')"});
  input_error(pair + "obstacle: {type: body, body: other, edges: [top]}}\n",
              {"contact[0].obstacle.body: no such body (defined: block) (got 'other')"});
  input_error(pair + "obstacle: {type: plane, body: block}}\n",
              {"contact[0].obstacle.body: only allowed with type: body (got type: plane)"});
}
